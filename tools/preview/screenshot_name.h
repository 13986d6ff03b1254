#pragma once
// The P key's screenshots: named after the scene (its file's stem) and numbered, the number the
// first free one in the folder, so that a run never overwrites an earlier run's pictures.
#include <cstdint>
#include <filesystem>
#include <string>

namespace mvpl::preview {

// FOLDER/STEM-NNNN (without extension; FOLDER empty: the working directory) for the smallest NNNN ≥
// *number (from 1) for which neither the .png nor the .exr exists; *number becomes the one after
// it.
std::filesystem::path next_screenshot(const std::filesystem::path& folder, const std::string& stem,
                                      uint32_t* number);

}  // namespace mvpl::preview
