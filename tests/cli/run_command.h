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
// Single-quotes a string for the shell.
std::string shell_quote(const std::string& s);

}  // namespace mvpl::test
