#pragma once
// The `mvpl` subcommands. Each takes the arguments after its name and returns the exit code;
// errors are thrown (UsageError/InputError → exit 2, anything else → exit 1) and reported by main.
#include <string>
#include <vector>

namespace mvpl::cli {

using Args = std::vector<std::string>;

int run_reference(const Args& args);
int run_render(const Args& args);
int run_compare(const Args& args);
int run_info(const Args& args);
int run_preview(const Args& args);
int run_vpls(const Args& args);
int run_bench(const Args& args);
int run_convergence(const Args& args);
int run_completion(const Args& args);

}  // namespace mvpl::cli
