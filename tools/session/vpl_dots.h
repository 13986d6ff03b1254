#pragma once
// VPLs as dots over a picture, for `mvpl vpls` and the preview's `vpls` view: each VPL that
// `project` places on the film (pixel coordinates) becomes a dot whose area grows with its power
// relative to the largest, at least a pixel wide; yellow for emitter VPLs, orange for the others.
#include <cstddef>
#include <functional>
#include <vector>

#include "engine/core/image.h"
#include "engine/core/math.h"
#include "engine/light/vpl.h"

namespace mvpl::session {

inline const Rgb kEmitterDot{1.0f, 0.9f, 0.2f};
inline const Rgb kBounceDot{1.0f, 0.35f, 0.1f};

// How many were drawn. Directional VPLs (no position) are left out.
size_t draw_vpls(Image& image, const std::function<bool(const Vec3&, Vec2&)>& project,
                 const std::vector<light::Vpl>& vpls);

}  // namespace mvpl::session
