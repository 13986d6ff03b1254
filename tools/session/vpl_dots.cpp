#include "tools/session/vpl_dots.h"

#include <algorithm>
#include <cmath>

#include "tools/session/heat_colour.h"

namespace mvpl::session {
namespace {

// A disc of `radius` pixels around c; with a ring, its outer pixel is the ring's colour.
void draw_dot(Image& image, const Vec2& c, float radius, const Rgb& colour, const Rgb* ring) {
    const float outer = ring ? radius + 1.0f : radius;
    const int x0 = int(std::floor(c.x - outer)), x1 = int(std::ceil(c.x + outer));
    const int y0 = int(std::floor(c.y - outer)), y1 = int(std::ceil(c.y + outer));
    for (int y = std::max(y0, 0); y <= std::min(y1, image.height() - 1); ++y) {
        for (int x = std::max(x0, 0); x <= std::min(x1, image.width() - 1); ++x) {
            const float dx = float(x) + 0.5f - c.x, dy = float(y) + 0.5f - c.y;
            const float d2 = dx * dx + dy * dy;
            if (d2 <= radius * radius) {
                image.at(x, y) = colour;
            } else if (ring && d2 <= outer * outer) {
                image.at(x, y) = *ring;
            }
        }
    }
}

}  // namespace

Rgb dot_colour(float relative_power) {
    // Three decades below the largest: t = 0 at 10⁻³ (and below), 1 at the largest.
    return relative_power > 0.0f ? heat_colour((std::log10(relative_power) + 3.0f) / 3.0f)
                                 : heat_colour(0.0f);
}

size_t draw_vpls(Image& image, const std::function<bool(const Vec3&, Vec2&)>& project,
                 const std::vector<light::Vpl>& vpls) {
    float max_power = 0.0f;
    for (const light::Vpl& v : vpls)
        max_power = std::max(max_power, luminance(v.power));
    // Powers as the sampler weighted them, relative to the largest: area ∝ power, at least a
    // pixel wide.
    size_t drawn = 0;
    for (const light::Vpl& v : vpls) {
        Vec2 film;
        if (v.type == light::VplType::Directional || !project(v.position, film)) continue;
        const float rel = max_power > 0.0f ? luminance(v.power) / max_power : 0.0f;
        const float radius =
            0.8f + 0.004f * float(std::min(image.width(), image.height())) * std::sqrt(rel);
        draw_dot(image, film, radius, dot_colour(rel),
                 v.path_length == 0 ? &kEmitterRing : nullptr);
        ++drawn;
    }
    return drawn;
}

}  // namespace mvpl::session
