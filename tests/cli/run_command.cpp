#include "tests/cli/run_command.h"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace mvpl::test {

std::string temp_file(const std::string& prefix, const std::string& name) {
    return (std::filesystem::temp_directory_path() /
            (prefix + "_" + std::to_string(::getpid()) + "_" + name))
        .string();
}

std::string shell_quote(const std::string& s) {
    std::string q = "'";
    for (char c : s) {
        if (c == '\'') {
            q += "'\\''";
        } else {
            q += c;
        }
    }
    return q + "'";
}

static std::string slurp(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

void expect_one_line_error(const CommandResult& r, const std::string& must_contain) {
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_EQ(r.err.rfind("mvpl: error: ", 0), 0u) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find(must_contain), std::string::npos) << r.err;
}

CommandResult run_mvpl(const std::string& args) {
    return run_mvpl_env("", args);
}

CommandResult run_mvpl_gpu(const std::string& args, const std::string& prefix) {
    return run_mvpl_env("ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0 " + prefix,
                        args);
}

CommandResult run_mvpl_env(const std::string& env, const std::string& args) {
    static int counter = 0;
    const auto dir = std::filesystem::temp_directory_path();
    const std::string tag = std::to_string(::getpid()) + "_" + std::to_string(counter++);
    const auto out = dir / ("mvpl_out_" + tag);
    const auto err = dir / ("mvpl_err_" + tag);
    const std::string cmd = env + " " + shell_quote(MVPL_EXE) + " " + args + " </dev/null >" +
                            shell_quote(out.string()) + " 2>" + shell_quote(err.string());
    const int status = std::system(cmd.c_str());
    CommandResult r;
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    r.out = slurp(out);
    r.err = slurp(err);
    std::filesystem::remove(out);
    std::filesystem::remove(err);
    return r;
}

}  // namespace mvpl::test
