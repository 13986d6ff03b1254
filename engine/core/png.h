#pragma once
#include <cstdint>
#include <span>
#include <string>

namespace mvpl {

// Writes 8-bit sRGB-encoded RGB pixels (row-major, row 0 at the top, 3 bytes a pixel) as a PNG:
// what write_png writes after tonemapping, and the preview's screenshots of the display image.
// Whole or not at all (atomic_files.h); throws InputError naming the path when it cannot be
// written.
void write_png_rgb8(const std::string& path, std::span<const uint8_t> rgb, int width, int height);

}  // namespace mvpl
