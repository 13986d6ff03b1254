#pragma once
// Image textures as the glTF sampler sees them: float texels (sRGB already decoded where the
// texture is a colour), a wrap mode per axis and a filter.
#include <string>
#include <vector>

#include "engine/core/math.h"

namespace mvpl::scene {

enum class Wrap { Repeat, ClampToEdge, MirroredRepeat };
enum class Filter { Nearest, Linear };

struct Texture {
    std::string name;
    int width = 0;
    int height = 0;
    std::vector<Vec4> texels;  // row-major, row 0 is the top of the image (glTF uv (0,0))
    Wrap wrap_s = Wrap::Repeat;
    Wrap wrap_t = Wrap::Repeat;
    Filter filter = Filter::Linear;

    // Value at texture coordinate uv, with the texture's wrap modes and filter.
    Vec4 sample(const Vec2& uv) const;
};

// A material's reference to a texture: which texture, which TEXCOORD_n set, and
// KHR_texture_transform (applied as offset · rotation · scale, as the extension specifies).
struct TextureRef {
    int texture = -1;
    int texcoord = 0;
    Vec2 offset{0.0f};
    float rotation = 0.0f;
    Vec2 scale{1.0f};

    bool valid() const { return texture >= 0; }
    Vec2 transform(const Vec2& uv) const;
};

}  // namespace mvpl::scene
