#include "engine/scene/mitsuba/bitmap.h"

#include <stb_image.h>

#include <cmath>
#include <memory>

#include "engine/core/error.h"
#include "engine/core/file_extension.h"
#include "engine/core/image.h"
#include "engine/core/regular_file.h"

namespace mvpl::scene::mitsuba {

namespace {

constexpr int64_t kMaxTexels = int64_t(1) << 26;

struct StbiFree {
    void operator()(void* p) const { stbi_image_free(p); }
};

void check_size(const std::string& path, int width, int height) {
    if (width <= 0 || height <= 0 || int64_t(width) * height > kMaxTexels)
        throw InputError(path, "image is " + std::to_string(width) + "x" + std::to_string(height) +
                                   " texels; at most 2^26 are allowed");
}

}  // namespace

Bitmap read_bitmap(const std::string& path, bool raw) {
    require_regular_file(path);
    Bitmap b;
    if (lower_extension(path) == ".exr") {
        const Image image = read_exr(path);
        check_size(path, image.width(), image.height());
        b.width = image.width();
        b.height = image.height();
        b.texels.reserve(size_t(b.width) * size_t(b.height));
        for (int y = 0; y < b.height; ++y)
            for (int x = 0; x < b.width; ++x)
                b.texels.emplace_back(image.at(x, y), 1.0f);
    } else {
        int w = 0, h = 0, channels = 0;
        if (!stbi_info(path.c_str(), &w, &h, &channels)) {
            const char* reason = stbi_failure_reason();
            throw InputError(path, std::string("cannot decode the image (") +
                                       (reason ? reason : "unknown reason") + ")");
        }
        check_size(path, w, h);
        const bool hdr = stbi_is_hdr(path.c_str()) != 0;
        const bool wide = stbi_is_16_bit(path.c_str()) != 0;
        std::unique_ptr<void, StbiFree> pixels(
            hdr    ? static_cast<void*>(stbi_loadf(path.c_str(), &w, &h, &channels, 4))
            : wide ? static_cast<void*>(stbi_load_16(path.c_str(), &w, &h, &channels, 4))
                   : static_cast<void*>(stbi_load(path.c_str(), &w, &h, &channels, 4)));
        if (!pixels) throw InputError(path, "cannot decode the image");
        check_size(path, w, h);
        b.width = w;
        b.height = h;
        b.texels.resize(size_t(w) * size_t(h));
        const float scale = wide ? 1.0f / 65535.0f : 1.0f / 255.0f;
        for (size_t i = 0; i < b.texels.size(); ++i) {
            Vec4 v;
            for (int c = 0; c < 4; ++c) {
                const size_t k = i * 4 + size_t(c);
                v[c] = hdr    ? static_cast<const float*>(pixels.get())[k]
                       : wide ? float(static_cast<const uint16_t*>(pixels.get())[k]) * scale
                              : float(static_cast<const uint8_t*>(pixels.get())[k]) * scale;
            }
            if (!hdr && !raw) {
                for (int c = 0; c < 3; ++c)
                    v[c] = srgb_to_linear(v[c]);
            }
            b.texels[i] = v;
        }
    }
    for (const Vec4& t : b.texels) {
        for (int c = 0; c < 4; ++c) {
            if (!std::isfinite(t[c]) || t[c] < 0.0f)
                throw InputError(path, "the image has a negative or non-finite texel");
        }
    }
    return b;
}

}  // namespace mvpl::scene::mitsuba
