#pragma once
#include <string>

namespace mvpl::test {

struct CommandResult {
    int exit_code = -1;
    std::string out;
    std::string err;
};

// Runs `mvpl ARGS` (the binary under test) through the shell with stdin closed; captures both
// output streams.
CommandResult run_mvpl(const std::string& args);
// The same with environment assignments (e.g. "MVPL_VALIDATION=1") before the command.
CommandResult run_mvpl_env(const std::string& env, const std::string& args);
// `mvpl ARGS` for commands that create a Vulkan instance, after PREFIX (environment assignments
// or a wrapper such as xvfb-run). Sanitizer builds: lavapipe's LLVM JIT leaks blocks that point at
// each other, allocated in libraries that are unloaded at vkDestroyInstance, so LeakSanitizer can
// neither symbolise nor suppress them (tests/gpu/gpu_test.cpp): these runs add detect_leaks=0 to
// the caller's ASAN_OPTIONS; AddressSanitizer's other checks stay on.
CommandResult run_mvpl_gpu(const std::string& args, const std::string& prefix = "");
// A usage or input error: exit code 2 and exactly one line `mvpl: error: …` (containing
// `must_contain`) on stderr; each failed expectation is a GoogleTest failure.
void expect_one_line_error(const CommandResult& r, const std::string& must_contain);
// Single-quotes a string for the shell.
std::string shell_quote(const std::string& s);
// A path in the temporary folder of this test process's own: PREFIX_PID_NAME.
std::string temp_file(const std::string& prefix, const std::string& name);

}  // namespace mvpl::test
