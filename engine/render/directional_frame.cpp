#include "engine/render/directional_frame.h"

#include <limits>

namespace mvpl::render {

DirectionalFrame directional_frame(const Vec3& direction, const scene::Bounds& bounds) {
    DirectionalFrame f;
    const float len = glm::length(direction);
    f.dir = len > 0.0f ? direction / len : Vec3(0, 0, -1);
    const Frame frame(f.dir);
    f.u = frame.s;
    f.v = frame.t;
    if (bounds.empty()) return f;
    Vec3 lo(std::numeric_limits<float>::infinity());
    Vec3 hi(-std::numeric_limits<float>::infinity());
    for (int corner = 0; corner < 8; ++corner) {
        const Vec3 p((corner & 1) ? bounds.hi.x : bounds.lo.x,
                     (corner & 2) ? bounds.hi.y : bounds.lo.y,
                     (corner & 4) ? bounds.hi.z : bounds.lo.z);
        const Vec3 q(glm::dot(p, f.u), glm::dot(p, f.v), glm::dot(p, f.dir));
        lo = glm::min(lo, q);
        hi = glm::max(hi, q);
    }
    // Margins of 1 % so that no surface lands on the window's border or the depth range's ends
    // (where clipping would drop it); all relative, so any scene scale works.
    const float diagonal = std::max(bounds.diagonal(), 1e-30f);
    f.extent = std::max(hi.x - lo.x, hi.y - lo.y) * 1.02f + 1e-6f * diagonal;
    f.depth = (hi.z - lo.z) * 1.02f + 1e-6f * diagonal;
    const Vec3 centre = 0.5f * (lo + hi);
    f.origin =
        Vec3(centre.x - 0.5f * f.extent, centre.y - 0.5f * f.extent, centre.z - 0.5f * f.depth);
    return f;
}

}  // namespace mvpl::render
