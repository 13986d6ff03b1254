#pragma once
// A linear RGB float image and its files: EXR (float, linear) and PNG (sRGB, tonemapped).
#include <span>
#include <string>
#include <vector>

#include "engine/core/color.h"
#include "engine/core/exr_file.h"

namespace mvpl {

class Image {
public:
    Image() = default;
    Image(int width, int height)
        : m_width(width), m_height(height), m_pixels(size_t(width) * height, Rgb(0.0f)) {}

    int width() const { return m_width; }
    int height() const { return m_height; }
    Rgb& at(int x, int y) { return m_pixels[size_t(y) * m_width + x]; }
    const Rgb& at(int x, int y) const { return m_pixels[size_t(y) * m_width + x]; }
    std::vector<Rgb>& pixels() { return m_pixels; }
    const std::vector<Rgb>& pixels() const { return m_pixels; }

    Rgb mean() const;  // accumulated in double
    // The pixels as 3 · width · height floats (R, G, B per pixel), for MPI sums over ranks.
    std::span<float> channels() {
        static_assert(sizeof(Rgb) == 3 * sizeof(float));
        return {reinterpret_cast<float*>(m_pixels.data()), 3 * m_pixels.size()};
    }

private:
    int m_width = 0;
    int m_height = 0;
    std::vector<Rgb> m_pixels;  // row-major, row 0 at the top
};

// Writes by the extension of `path`: .exr (32-bit float linear) or .png (8-bit sRGB after
// multiplying by 2^exposure), whole or not at all (atomic_files.h). Throws UsageError for another
// extension, NonFiniteError (finite_check.h) for an image with a NaN or an infinity, InputError
// naming the path when the file cannot be written (a missing folder, a full disk). Every EXR
// carries the Rec. 709 chromaticities (exr_file.h).
void write_image(const Image& image, const std::string& path, float exposure = 0.0f);
// Every path or none: nothing replaces a target until all are written (`-o` given several times).
// `extras`: channels and attributes an EXR holds besides the image (exr_file.h); a PNG has none.
void write_images(const Image& image, const std::vector<std::string>& paths, float exposure = 0.0f,
                  const ExrExtras& extras = {});
void write_exr(const Image& image, const std::string& path);
void write_png(const Image& image, const std::string& path, float exposure = 0.0f);
// Reads the R, G, B channels of an EXR (half or float). Throws InputError naming the file.
Image read_exr(const std::string& path);

// Linear value to the sRGB transfer curve, clamped to [0, 1].
float linear_to_srgb(float v);
float srgb_to_linear(float v);

}  // namespace mvpl
