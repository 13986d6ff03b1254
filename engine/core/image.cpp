#include "engine/core/image.h"

#include "engine/core/finite_check.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <stb_image_write.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>

#include "engine/core/error.h"
#include "engine/core/file_extension.h"
#include "engine/core/png.h"

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

void write_image(const Image& image, const std::string& path, float exposure) {
    const std::string ext = lower_extension(path);
    // The last guard: a non-finite value is never written silently (finite_check.h).
    require_finite(image, path + " not written");
    if (ext == ".exr") {
        write_exr(image, path);
    } else if (ext == ".png") {
        write_png(image, path, exposure);
    } else {
        throw UsageError(path + ": unknown image extension (use .exr or .png)");
    }
}

void write_exr(const Image& image, const std::string& path) {
    try {
        Imf::Header header(image.width(), image.height());
        header.channels().insert("R", Imf::Channel(Imf::FLOAT));
        header.channels().insert("G", Imf::Channel(Imf::FLOAT));
        header.channels().insert("B", Imf::Channel(Imf::FLOAT));
        Imf::OutputFile file(path.c_str(), header);
        Imf::FrameBuffer fb;
        char* base = reinterpret_cast<char*>(const_cast<Rgb*>(image.pixels().data()));
        const size_t xs = sizeof(Rgb);
        const size_t ys = sizeof(Rgb) * size_t(image.width());
        fb.insert("R", Imf::Slice(Imf::FLOAT, base + 0 * sizeof(float), xs, ys));
        fb.insert("G", Imf::Slice(Imf::FLOAT, base + 1 * sizeof(float), xs, ys));
        fb.insert("B", Imf::Slice(Imf::FLOAT, base + 2 * sizeof(float), xs, ys));
        file.setFrameBuffer(fb);
        file.writePixels(image.height());
    } catch (const std::exception& e) {
        throw std::runtime_error(path + ": cannot write EXR: " + e.what());
    }
}

void write_png(const Image& image, const std::string& path, float exposure) {
    const float scale = std::exp2(exposure);
    std::vector<unsigned char> bytes(size_t(image.width()) * image.height() * 3);
    for (size_t i = 0; i < image.pixels().size(); ++i) {
        const Rgb& p = image.pixels()[i];
        for (int c = 0; c < 3; ++c) {
            bytes[3 * i + c] =
                static_cast<unsigned char>(std::lround(255.0f * linear_to_srgb(p[c] * scale)));
        }
    }
    write_png_rgb8(path, bytes, image.width(), image.height());
}

void write_png_rgb8(const std::string& path, std::span<const uint8_t> rgb, int width, int height) {
    if (rgb.size() != size_t(width) * size_t(height) * 3 ||
        !stbi_write_png(path.c_str(), width, height, 3, rgb.data(), width * 3)) {
        throw std::runtime_error(path + ": cannot write PNG");
    }
}

Image read_exr(const std::string& path) {
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
