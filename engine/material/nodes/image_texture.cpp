// image_texture: factor (Node::value, the glTF factors) times the texel at the transformed
// coordinate — KHR_texture_transform (TextureRef::transform), then the sampler's wrap and filter
// (scene::Texture::sample). A reference to a texture the scene does not hold reads as the factor.
#include "engine/material/node_graph.h"

namespace mvpl::material::nodes {
namespace {

Vec4 evaluate(const NodeContext& c) {
    const Node& n = c.node();
    const scene::Texture* texture = c.texture();
    if (!texture) return n.value;
    const Vec2& uv = n.texture.texcoord == 1 ? c.point().uv1 : c.point().uv0;
    return n.value * texture->sample(n.texture.transform(uv));
}

constexpr std::string_view kGlsl =
    R"(// scene::Texture::sample after TextureRef::transform, with texelFetch so that the wrap modes
// (0 repeat, 1 clamp to edge, 2 mirrored repeat) and the bilinear filter (filter 1) are those of
// the CPU bit for bit rather than the sampler's.
float texture_reduce(float u, int wrap) {
    if (isnan(u) || isinf(u)) return 0.0;
    if (wrap == 0) return u - floor(u);
    if (wrap == 2) return u - 2.0 * floor(0.5 * u);
    return clamp(u, -1.0, 2.0);
}
int texture_wrap_index(int i, int size, int wrap) {
    if (wrap == 0) {
        const int m = i % size;
        return m < 0 ? m + size : m;
    }
    if (wrap == 2) {
        const int period = 2 * size;
        int m = i % period;
        if (m < 0) m += period;
        return m < size ? m : period - 1 - m;
    }
    return clamp(i, 0, size - 1);
}
vec4 texture_texel(sampler2D tex, int i, int j, ivec2 size, int wrap_s, int wrap_t) {
    return texelFetch(tex, ivec2(texture_wrap_index(i, size.x, wrap_s),
                                 texture_wrap_index(j, size.y, wrap_t)), 0);
}
vec4 image_texture(sampler2D tex, vec2 uv, vec2 offset, float rotation, vec2 scale, int wrap_s,
                   int wrap_t, int filter_mode, vec4 factor) {
    vec2 st = uv * scale;
    if (rotation != 0.0) {
        const float c = cos(rotation);
        const float s = sin(rotation);
        st = vec2(c * st.x + s * st.y, -s * st.x + c * st.y);
    }
    st += offset;
    const ivec2 size = textureSize(tex, 0);
    const float x = texture_reduce(st.x, wrap_s) * float(size.x);
    const float y = texture_reduce(st.y, wrap_t) * float(size.y);
    if (filter_mode == 0) {
        return factor * texture_texel(tex, int(floor(x)), int(floor(y)), size, wrap_s, wrap_t);
    }
    const float fx = x - 0.5;
    const float fy = y - 0.5;
    const int x0 = int(floor(fx));
    const int y0 = int(floor(fy));
    const float tx = fx - float(x0);
    const float ty = fy - float(y0);
    const vec4 top = mix(texture_texel(tex, x0, y0, size, wrap_s, wrap_t),
                         texture_texel(tex, x0 + 1, y0, size, wrap_s, wrap_t), tx);
    const vec4 bottom = mix(texture_texel(tex, x0, y0 + 1, size, wrap_s, wrap_t),
                            texture_texel(tex, x0 + 1, y0 + 1, size, wrap_s, wrap_t), tx);
    return factor * mix(top, bottom, ty);
}
)";

int wrap_code(scene::Wrap w) {
    switch (w) {
        case scene::Wrap::Repeat:
            return 0;
        case scene::Wrap::ClampToEdge:
            return 1;
        case scene::Wrap::MirroredRepeat:
            return 2;
    }
    return 0;
}

std::string call(GlslCallContext& c) {
    const Node& n = c.node();
    const scene::Texture* t = c.texture();
    if (!t) return glsl_vec4(n.value);
    const std::string sampler = c.sampler();
    if (sampler.empty()) return "/* texture not bound */ " + glsl_vec4(n.value);
    c.require("image_texture");
    return "image_texture(" + sampler + ", s" + (n.texture.texcoord == 1 ? ".uv1" : ".uv0") + ", " +
           glsl_vec2(n.texture.offset) + ", " + glsl_number(n.texture.rotation) + ", " +
           glsl_vec2(n.texture.scale) + ", " + std::to_string(wrap_code(t->wrap_s)) + ", " +
           std::to_string(wrap_code(t->wrap_t)) + ", " +
           (t->filter == scene::Filter::Nearest ? "0" : "1") + ", " + glsl_vec4(n.value) + ")";
}

}  // namespace

extern const NodeKind kImageTextureNode{.name = "image_texture",
                                        .role = NodeRole::Value,
                                        .value = evaluate,
                                        .glsl = kGlsl,
                                        .glsl_call = call};

}  // namespace mvpl::material::nodes
