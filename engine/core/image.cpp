#include "engine/core/image.h"

#include "engine/core/finite_check.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <stb_image_write.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>

#include "engine/core/atomic_files.h"
#include "engine/core/error.h"
#include "engine/core/exr_file.h"
#include "engine/core/file_extension.h"
#include "engine/core/png.h"
#include "engine/core/regular_file.h"

namespace mvpl {

Rgb Image::mean() const {
    DVec3 sum(0.0);
    for (const Rgb& p : m_pixels)
        sum += DVec3(p);
    return m_pixels.empty() ? Rgb(0.0f) : Rgb(sum / double(m_pixels.size()));
}

float linear_to_srgb(float v) {
    if (!(v > 0.0f)) return 0.0f;
    if (v >= 1.0f) return 1.0f;
    return v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
}

float srgb_to_linear(float v) {
    return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
}

namespace {

// The PNG file's bytes, encoded in memory so that writing them is checked (stb's own file
// writer ignores write errors).
std::vector<uint8_t> png_encode(std::span<const uint8_t> rgb, int width, int height) {
    if (rgb.size() != size_t(width) * size_t(height) * 3)
        throw std::runtime_error("PNG pixel data of the wrong size");
    std::vector<uint8_t> out;
    const auto append = [](void* context, void* data, int size) {
        auto* v = static_cast<std::vector<uint8_t>*>(context);
        const auto* bytes = static_cast<const uint8_t*>(data);
        v->insert(v->end(), bytes, bytes + size);
    };
    if (!stbi_write_png_to_func(append, &out, width, height, 3, rgb.data(), width * 3))
        throw std::runtime_error("cannot encode PNG");
    return out;
}

std::vector<uint8_t> tonemapped_rgb8(const Image& image, float exposure) {
    const float scale = std::exp2(exposure);
    std::vector<uint8_t> bytes(size_t(image.width()) * image.height() * 3);
    for (size_t i = 0; i < image.pixels().size(); ++i) {
        const Rgb& p = image.pixels()[i];
        for (int c = 0; c < 3; ++c)
            bytes[3 * i + c] = uint8_t(std::lround(255.0f * linear_to_srgb(p[c] * scale)));
    }
    return bytes;
}

}  // namespace

void write_images(const Image& image, const std::vector<std::string>& paths, float exposure,
                  const ExrExtras& extras) {
    for (const std::string& path : paths) {
        const std::string ext = lower_extension(path);
        if (ext != ".exr" && ext != ".png")
            throw UsageError(path + ": unknown image extension (use .exr or .png)");
    }
    // The last guard: a non-finite value is never written silently (finite_check.h). One scan
    // serves every path; the error names the first, as writing them in turn did.
    if (!paths.empty()) require_finite(image, paths.front() + " not written");
    for (const ChannelImage& layer : extras.layers) {
        for (const float v : layer.values) {
            if (!std::isfinite(v))
                throw NonFiniteError(paths.front() + " not written: " + layer.name + " holds " +
                                     std::to_string(v));
        }
    }
    std::vector<uint8_t> png;  // encoded once for every .png target
    write_files_atomically(paths, [&](size_t i, const std::string& file) {
        if (lower_extension(paths[i]) == ".exr") {
            write_exr_file(image, extras, file);
            return;
        }
        if (png.empty())
            png = png_encode(tonemapped_rgb8(image, exposure), image.width(), image.height());
        write_bytes(file, png);
    });
}

void write_image(const Image& image, const std::string& path, float exposure) {
    write_images(image, {path}, exposure);
}

void write_exr(const Image& image, const std::string& path) {
    write_files_atomically(
        {path}, [&](size_t, const std::string& file) { write_exr_file(image, ExrExtras{}, file); });
}

void write_png(const Image& image, const std::string& path, float exposure) {
    const std::vector<uint8_t> png =
        png_encode(tonemapped_rgb8(image, exposure), image.width(), image.height());
    write_files_atomically({path},
                           [&](size_t, const std::string& file) { write_bytes(file, png); });
}

void write_png_rgb8(const std::string& path, std::span<const uint8_t> rgb, int width, int height) {
    const std::vector<uint8_t> png = png_encode(rgb, width, height);
    write_files_atomically({path},
                           [&](size_t, const std::string& file) { write_bytes(file, png); });
}

Image read_exr(const std::string& path) {
    require_regular_file(path);
    try {
        Imf::InputFile file(path.c_str());
        const Imath::Box2i dw = file.header().dataWindow();
        const int width = dw.max.x - dw.min.x + 1;
        const int height = dw.max.y - dw.min.y + 1;
        if (width <= 0 || height <= 0 || int64_t(width) * height > (int64_t(1) << 28)) {
            throw InputError(path, "EXR has an unusable size");
        }
        for (const char* name : {"R", "G", "B"}) {
            if (!file.header().channels().findChannel(name)) {
                throw InputError(path, std::string("EXR has no ") + name + " channel");
            }
        }
        Image image(width, height);
        char* base = reinterpret_cast<char*>(image.pixels().data());
        const size_t xs = sizeof(Rgb);
        const size_t ys = sizeof(Rgb) * size_t(width);
        // OpenEXR addresses the slice by absolute data-window coordinates.
        const ptrdiff_t origin =
            -ptrdiff_t(dw.min.x) * ptrdiff_t(xs) - ptrdiff_t(dw.min.y) * ptrdiff_t(ys);
        Imf::FrameBuffer fb;
        fb.insert("R", Imf::Slice(Imf::FLOAT, base + origin + 0 * sizeof(float), xs, ys));
        fb.insert("G", Imf::Slice(Imf::FLOAT, base + origin + 1 * sizeof(float), xs, ys));
        fb.insert("B", Imf::Slice(Imf::FLOAT, base + origin + 2 * sizeof(float), xs, ys));
        file.setFrameBuffer(fb);
        file.readPixels(dw.min.y, dw.max.y);
        return image;
    } catch (const InputError&) {
        throw;
    } catch (const std::exception& e) {
        throw InputError(path, std::string("cannot read EXR: ") + e.what());
    }
}

}  // namespace mvpl
