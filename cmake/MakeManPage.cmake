# cmake -DEXE=mvpl -DHELP2MAN=help2man -DOUT=mvpl.1 -P MakeManPage.cmake: the man page, written by
# help2man from `mvpl --help` and `mvpl --version`, with a COMMANDS section holding each
# command's own `mvpl COMMAND --help` (the commands are read from `mvpl --help`).
execute_process(COMMAND ${EXE} --help OUTPUT_VARIABLE usage RESULT_VARIABLE code)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "${EXE} --help failed (${code})")
endif()
# The commands: the lines "  NAME ARGS   summary" after "commands:".
string(REGEX MATCHALL "\n  [a-z]+" lines "${usage}")
set(sections "[COMMANDS]\n")
foreach(line IN LISTS lines)
  string(STRIP "${line}" command)
  execute_process(COMMAND ${EXE} ${command} --help OUTPUT_VARIABLE help RESULT_VARIABLE code)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "${EXE} ${command} --help failed (${code})")
  endif()
  # roff: a backslash is \e; a line may not begin with a control character.
  string(REPLACE "\\" "\\e" help "${help}")
  string(REGEX REPLACE "\n([.'])" "\n\\\\&\\1" help "\n${help}")
  string(APPEND sections ".SS ${command}\n.nf${help}.fi\n")
endforeach()
get_filename_component(dir ${OUT} DIRECTORY)
file(WRITE ${dir}/mvpl-commands.h2m "${sections}")
execute_process(
  COMMAND ${HELP2MAN} --no-info --no-discard-stderr
    "--name=Metropolis virtual-point-light renderer" --include=${dir}/mvpl-commands.h2m
    --output=${OUT}.tmp ${EXE}
  RESULT_VARIABLE code)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "help2man failed (${code})")
endif()
file(RENAME ${OUT}.tmp ${OUT})
