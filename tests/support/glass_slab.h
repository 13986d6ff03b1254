#pragma once
// A glass sheet in front of a textured wall (issue 15's transmission test scene): a checkered
// back wall (z = −1, 8×8 bilinear checker of 0.8 and 0.2 grey, tinted) inside a box open towards
// +Z (white floor and ceiling, dark side walls), an area light of radiance 8 under the ceiling
// near the wall, and a 0.7 × 0.7 glTF glass sheet (transmission 1, IOR 1.5, roughness 0,
// double-sided; thin-walled: no KHR_materials_volume) at z = kGlassSheetZ facing the camera on +Z.
// Light reaches the wall from the emitter without crossing the sheet, so at max depth 3 the wall
// seen through it is lit directly only (no light path passes the glass between two rough
// vertices, which VPLs cannot carry).
#include "engine/scene/scene.h"

namespace mvpl::test {

inline constexpr float kGlassSheetZ = 0.3f;
inline constexpr float kGlassSheetHalf = 0.35f;
inline constexpr int kGlassMaterial = 5;

// `tint`: the glass's base colour (the transmission's tint). `thickness` > 0 makes the sheet a
// solid box from z = kGlassSheetZ − thickness to kGlassSheetZ, faces outwards, whose material has
// KHR_materials_volume's thickness (it refracts).
scene::Scene make_glass_slab(const Rgb& tint = Rgb(1.0f), float thickness = 0.0f);

// Whether the ray through the centre of pixel (x, y) of a size × size image passes through the
// sheet at least `margin` inside its edges; its cosine with the sheet's normal in `cos_theta`.
bool through_glass_sheet(const scene::Camera& camera, int size, int x, int y, float margin,
                         float* cos_theta = nullptr);

}  // namespace mvpl::test
