# cmake -DEXE=… -DARGS="a;b" -DOUT=FILE -P RunToFile.cmake: runs EXE ARGS with its standard
# output into FILE (a build step that writes what a command prints: `mvpl completion bash`).
execute_process(COMMAND ${EXE} ${ARGS} OUTPUT_FILE ${OUT}.tmp RESULT_VARIABLE code)
if(NOT code EQUAL 0)
  file(REMOVE ${OUT}.tmp)
  message(FATAL_ERROR "${EXE} ${ARGS} failed (${code})")
endif()
file(RENAME ${OUT}.tmp ${OUT})
