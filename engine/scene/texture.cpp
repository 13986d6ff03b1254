#include "engine/scene/texture.h"

namespace mvpl::scene {
namespace {

// Brings a coordinate into a range where coordinate · size fits an int, without changing what
// the wrap mode samples; non-finite coordinates sample the origin.
float reduce(float u, Wrap wrap) {
    if (!std::isfinite(u)) return 0.0f;
    switch (wrap) {
        case Wrap::Repeat:
            return u - std::floor(u);
        case Wrap::MirroredRepeat:
            return u - 2.0f * std::floor(0.5f * u);
        case Wrap::ClampToEdge:
            return std::clamp(u, -1.0f, 2.0f);
    }
    return 0.0f;
}

int wrap_index(int i, int size, Wrap wrap) {
    switch (wrap) {
        case Wrap::Repeat: {
            const int m = i % size;
            return m < 0 ? m + size : m;
        }
        case Wrap::MirroredRepeat: {
            const int period = 2 * size;
            int m = i % period;
            if (m < 0) m += period;
            return m < size ? m : period - 1 - m;
        }
        case Wrap::ClampToEdge:
            return std::clamp(i, 0, size - 1);
    }
    return 0;
}

}  // namespace

Vec4 Texture::sample(const Vec2& uv) const {
    if (width <= 0 || height <= 0 || texels.size() < size_t(width) * size_t(height)) {
        return Vec4(1.0f);  // neutral when multiplied into a factor
    }
    // uv (0, 0) is the top-left corner of the image: row 0 is the top, so v maps to rows as is.
    const float x = reduce(uv.x, wrap_s) * float(width);
    const float y = reduce(uv.y, wrap_t) * float(height);
    auto texel = [&](int i, int j) -> const Vec4& {
        return texels[size_t(wrap_index(j, height, wrap_t)) * size_t(width) +
                      size_t(wrap_index(i, width, wrap_s))];
    };
    if (filter == Filter::Nearest) return texel(int(std::floor(x)), int(std::floor(y)));
    // Bilinear between the four texel centres around (x, y).
    const float fx = x - 0.5f;
    const float fy = y - 0.5f;
    const int x0 = int(std::floor(fx));
    const int y0 = int(std::floor(fy));
    const float tx = fx - float(x0);
    const float ty = fy - float(y0);
    const Vec4 top = glm::mix(texel(x0, y0), texel(x0 + 1, y0), tx);
    const Vec4 bottom = glm::mix(texel(x0, y0 + 1), texel(x0 + 1, y0 + 1), tx);
    return glm::mix(top, bottom, ty);
}

Vec2 TextureRef::transform(const Vec2& uv) const {
    const Vec2 scaled = uv * scale;
    if (rotation == 0.0f) return scaled + offset;
    // KHR_texture_transform's rotation as the implementations and the sample model apply it:
    // rows [cos, sin; -sin, cos], a counter-clockwise turn in glTF's y-down uv space.
    const float c = std::cos(rotation);
    const float s = std::sin(rotation);
    return Vec2(c * scaled.x + s * scaled.y, -s * scaled.x + c * scaled.y) + offset;
}

}  // namespace mvpl::scene
