#pragma once
#include <cstdint>
#include <span>
#include <string>

namespace mvpl {

// Writes 8-bit sRGB-encoded RGB pixels (row-major, row 0 at the top, 3 bytes a pixel) as a PNG:
// what write_png writes after tonemapping, and the preview's screenshots of the display image.
// Throws std::runtime_error when the file cannot be written.
void write_png_rgb8(const std::string& path, std::span<const uint8_t> rgb, int width, int height);

}  // namespace mvpl
