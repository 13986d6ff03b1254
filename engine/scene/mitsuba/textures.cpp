#include "engine/scene/mitsuba/textures.h"

#include <cmath>

#include "engine/core/error.h"
#include "engine/scene/mitsuba/bitmap.h"
#include "engine/scene/mitsuba/properties.h"
#include "engine/scene/mitsuba/transform.h"

namespace mvpl::scene::mitsuba {

namespace {

constexpr int64_t kMaxTotalTexels = int64_t(1) << 28;

Wrap wrap_mode(Context& ctx, pugi::xml_node texture) {
    const std::string mode = ctx.get_string(texture, "wrap_mode", "repeat");
    if (mode == "repeat") return Wrap::Repeat;
    if (mode == "mirror") return Wrap::MirroredRepeat;
    if (mode == "clamp") return Wrap::ClampToEdge;
    ctx.fail(ctx.property(texture, "wrap_mode"),
             "wrap_mode '" + mode + "' is not supported (repeat, mirror, clamp)");
}

// to_uv as KHR_texture_transform (TextureRef::transform): uv' = t + R(θ) · diag(sx, sy) · uv with
// R's rows [cos θ, sin θ; −sin θ, cos θ]. Mitsuba applies the 4×4's rows and columns 0, 1 and 3 to
// (u, v, 1) (Transform4::extract); its linear part A = [a b; c d] has that form exactly when A's
// columns are orthogonal: (a, c) = sx (cos θ, −sin θ) and (b, d) = sy (sin θ, cos θ), sy < 0 for a
// mirror. A shear (columns not orthogonal, beyond float rounding) or a projective bottom row has no
// such form and is refused.
void apply_to_uv(Context& ctx, pugi::xml_node texture, TextureRef& ref) {
    const pugi::xml_node t = ctx.property(texture, "to_uv");
    if (!t) return;
    const DMat4 m = object_transform(ctx, texture, "to_uv");
    if (m[0][3] != 0.0 || m[1][3] != 0.0 || m[3][3] != 1.0)
        ctx.fail(t,
                 "to_uv with a projective part is not supported (scale, rotate and translate are)");
    const double a = m[0][0], c = m[0][1], b = m[1][0], d = m[1][1];
    const double len0 = std::hypot(a, c), len1 = std::hypot(b, d);
    if (std::abs(a * b + c * d) > 1e-6 * len0 * len1)
        ctx.fail(t, "to_uv with shear is not supported (scale, rotate and translate are)");
    double theta = 0.0, sx = a, sy = d;
    if (b != 0.0 || c != 0.0) {
        theta = len0 > 0.0 ? std::atan2(-c, a) : std::atan2(b, d);
        sx = len0;
        sy = b * std::sin(theta) + d * std::cos(theta);
    }
    ref.scale = Vec2(float(sx), float(sy));
    ref.rotation = float(theta);
    ref.offset = Vec2(float(m[3][0]), float(m[3][1]));
}

int add_texture(Context& ctx, pugi::xml_node at, Texture texture) {
    int64_t total = int64_t(texture.texels.size());
    for (const Texture& t : ctx.scene().textures)
        total += int64_t(t.texels.size());
    if (total > kMaxTotalTexels) ctx.fail(at, "the textures exceed 2^28 texels in all");
    ctx.scene().textures.push_back(std::move(texture));
    return int(ctx.scene().textures.size()) - 1;
}

int bitmap_texture(Context& ctx, pugi::xml_node texture, bool raw_default) {
    const pugi::xml_node name = ctx.property(texture, "filename");
    if (!name) ctx.fail(texture, "bitmap needs a filename");
    const std::string path = ctx.xml().resolve(name, name.attribute("value").as_string());
    const bool raw = ctx.get_bool(texture, "raw", raw_default);
    const std::string filter = ctx.get_string(texture, "filter_type", "bilinear");
    if (filter != "bilinear" && filter != "nearest")
        ctx.fail(ctx.property(texture, "filter_type"),
                 "filter_type '" + filter + "' is not supported (bilinear, nearest)");
    const Wrap wrap = wrap_mode(ctx, texture);
    const std::string key =
        path + (raw ? "|raw|" : "|srgb|") + filter + "|" + std::to_string(int(wrap));
    if (const auto found = ctx.texture_of_file.find(key); found != ctx.texture_of_file.end())
        return found->second;
    Bitmap bitmap;
    try {
        bitmap = read_bitmap(path, raw);
    } catch (const InputError& e) {
        ctx.fail(name, e.what());
    }
    Texture t;
    t.name = path;
    t.width = bitmap.width;
    t.height = bitmap.height;
    t.texels = std::move(bitmap.texels);
    t.wrap_s = t.wrap_t = wrap;
    t.filter = filter == "nearest" ? Filter::Nearest : Filter::Linear;
    const int index = add_texture(ctx, texture, std::move(t));
    ctx.texture_of_file[key] = index;
    return index;
}

int checkerboard_texture(Context& ctx, pugi::xml_node texture) {
    const auto colour = [&](const char* name, float fallback) {
        const pugi::xml_node p = ctx.property(texture, name);
        if (p && std::string(p.name()) == "texture")
            ctx.fail(p, "a textured checkerboard colour is not supported");
        return p ? color_value(ctx, p) : Rgb(fallback);
    };
    const Vec4 c0(colour("color0", 0.4f), 1.0f), c1(colour("color1", 0.2f), 1.0f);
    Texture t;
    t.name = "checkerboard";
    t.width = t.height = 2;
    // Mitsuba: colour 0 where (u mod 1 > ½) equals (v mod 1 > ½).
    t.texels = {c0, c1, c1, c0};
    t.filter = Filter::Nearest;
    return add_texture(ctx, texture, std::move(t));
}

}  // namespace

TextureRef texture_ref(Context& ctx, pugi::xml_node texture, bool raw) {
    const std::string type = texture.attribute("type").as_string();
    TextureRef ref;
    if (type == "bitmap") {
        ref.texture = bitmap_texture(ctx, texture, raw);
        // Mitsuba 0.x's uoffset/voffset/uscale/vscale (upgraded to snake_case names).
        ref.scale =
            Vec2(ctx.get_float(texture, "uscale", 1.0f), ctx.get_float(texture, "vscale", 1.0f));
        ref.offset =
            Vec2(ctx.get_float(texture, "uoffset", 0.0f), ctx.get_float(texture, "voffset", 0.0f));
    } else if (type == "checkerboard") {
        ref.texture = checkerboard_texture(ctx, texture);
    } else {
        ctx.fail(texture, "texture type '" + type + "' is not supported");
    }
    apply_to_uv(ctx, texture, ref);
    return ref;
}

TextureRef derived_texture(Context& ctx, pugi::xml_node at, const TextureRef& ref,
                           const std::function<Vec4(const Vec4&)>& texel) {
    Texture t = ctx.scene().textures[size_t(ref.texture)];
    for (Vec4& v : t.texels)
        v = texel(v);
    TextureRef out = ref;
    out.texture = add_texture(ctx, at, std::move(t));
    return out;
}

ColorInput color_input(Context& ctx, pugi::xml_node bsdf, const std::string& name,
                       const Rgb& fallback, bool raw) {
    ColorInput in;
    const pugi::xml_node p = ctx.property(bsdf, name);
    if (!p) {
        in.value = fallback;
    } else if (std::string(p.name()) == "texture") {
        in.texture = texture_ref(ctx, p, raw);
    } else {
        in.value = color_value(ctx, p);
    }
    return in;
}

float scalar_input(Context& ctx, pugi::xml_node bsdf, const std::string& name, float fallback) {
    const pugi::xml_node p = ctx.property(bsdf, name);
    if (!p) return fallback;
    if (std::string(p.name()) == "texture")
        ctx.fail(p, "a texture for '" + name + "' is not supported (a constant is)");
    const Rgb c = color_value(ctx, p);
    return (c.r + c.g + c.b) / 3.0f;
}

}  // namespace mvpl::scene::mitsuba
