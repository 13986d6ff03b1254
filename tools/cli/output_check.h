#pragma once
#include <string>
#include <vector>

namespace mvpl::cli {

// Rejects an output path whose extension is neither .exr nor .png before any rendering starts.
void check_output_extensions(const std::vector<std::string>& outputs);

}  // namespace mvpl::cli
