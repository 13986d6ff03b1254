#pragma once
// Light arriving from infinitely far away in every direction: a constant radiance, or a
// latitude-longitude (equirectangular) map times it (issue 12).
//
// Orientation, as the glTF Sample Viewer's panorama (so that EnvironmentTest looks as its
// screenshot): the map's top row is +Y (up), its bottom row −Y; the centre column faces +X and
// the azimuth φ = atan2(z, x) grows to the right, so that the column three quarters across faces
// +Z and the one a quarter across −Z. `rotation` turns the environment about +Y by that angle
// (a feature the map shows at direction d appears at R_y(rotation) · d, glTF's right-handed
// rotation about +Y).
#include <memory>
#include <string>
#include <vector>

#include "engine/core/color.h"
#include "engine/core/math.h"

namespace mvpl::scene {

// The texels of a latitude-longitude map, linear RGB, row 0 at the top (+Y).
struct EnvironmentMap {
    int width = 0;
    int height = 0;
    std::vector<Rgb> texels;
    std::string path;  // where it was read from (messages)

    const Rgb& at(int x, int y) const { return texels[size_t(y) * size_t(width) + size_t(x)]; }
};

struct Environment {
    Rgb radiance{0.0f};                         // the constant, or the map's multiplier
    std::shared_ptr<const EnvironmentMap> map;  // null: constant
    float rotation = 0.0f;                      // radians about +Y

    bool active() const { return radiance.r > 0.0f || radiance.g > 0.0f || radiance.b > 0.0f; }
    bool has_map() const { return map != nullptr && map->width > 0; }
    // Radiance arriving from direction w (unit, pointing away from the receiver): the map's texel
    // that contains w (nearest, so that the importance sampling's piecewise-constant density is
    // exactly the radiance's shape) times `radiance`.
    Rgb lookup(const Vec3& w) const;
    // Map coordinates in [0, 1)² (u across, v down) of direction w, and back (the rotation
    // applied); uv_to_direction also gives sin θ, the Jacobian's factor (dω = 2π² sin θ du dv).
    Vec2 direction_to_uv(const Vec3& w) const;
    Vec3 uv_to_direction(const Vec2& uv, float* sin_theta = nullptr) const;
};

}  // namespace mvpl::scene
