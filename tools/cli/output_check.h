#pragma once
#include <string>
#include <vector>

namespace mvpl::cli {

// Before any rendering starts, so that a bad -o costs nothing: each output's extension is .exr or
// .png (UsageError), its folder exists and is writable, and it is not itself a folder
// (InputError naming the path).
void check_outputs(const std::vector<std::string>& outputs);

}  // namespace mvpl::cli
