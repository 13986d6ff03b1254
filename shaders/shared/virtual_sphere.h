// Virtual spherical lights (Hašan, Křivánek, Walter, Bala 2009, "Virtual Spherical Lights for
// Many-Light Rendering of Glossy Scenes") in closed form, one definition for the CPU oracle
// (engine/light/virtual_sphere.h) and the shading pass (shaders/render/shading_template.glsl).
//
// A VSL spreads a surface or area VPL's light over a sphere of radius r around it, so that each
// glossy lobe on either side of the VPL–receiver pair is integrated over the sphere's solid
// angle instead of evaluated along one ray. For the GGX lobes of this renderer that integral is
// approximated by a rougher GGX lobe (cf. Karis 2013, "Real Shading in Unreal Engine 4", sphere
// lights), evaluated along the ray to the sphere's centre:
//
//     α'² = min(1, α² + s²),   s² = r² / (4 · max(d², r²)),
//
// s being half the sphere's angular radius (r/d for d ≥ r, a hemisphere's worth inside it): a
// cone of directions of half-angle θ moves the half vector by θ/2, and a mirror (α → 0)
// averaged over a disk of half vectors of radius θ/2 peaks at 1/(π (θ/2)²) = D_GGX(0) at α' = θ/2.
// α' adds in quadrature as the widths of convolved lobes do. A GGX lobe of any α' is normalised,
// so the energy a lobe reflects never grows (tests/light/test_virtual_sphere.cpp), and its peak
// falls from 1/(π α²) to at most 4 d² / (π r²): the glossy splotches of point VPLs become bounded
// (the d² cancels the geometric term's 1/d²). r → 0 gives the point VPL back.
#ifndef MVPL_SHADERS_SHARED_VIRTUAL_SPHERE_H
#define MVPL_SHADERS_SHARED_VIRTUAL_SPHERE_H

#include "prelude.h"

#ifdef __cplusplus
#include <algorithm>
#include <cmath>
#define MVPL_VSL_FN inline
#else
#define MVPL_VSL_FN
#endif

MVPL_SHARED_BEGIN

#ifdef __cplusplus
using std::max;
using std::min;
using std::sqrt;
#endif

// s², the squared GGX α that a lobe gains from a sphere of squared radius r2 whose centre lies
// at squared distance d2; 0 when r2 is 0 (a point VPL).
MVPL_VSL_FN float vsl_spread2(float r2, float d2) {
    return r2 > 0.0f ? 0.25f * r2 / max(d2, r2) : 0.0f;
}

// The GGX α of a lobe of α `alpha` integrated over a sphere of spread s² = spread2.
MVPL_VSL_FN float vsl_alpha(float alpha, float spread2) {
    return min(1.0f, sqrt(alpha * alpha + spread2));
}

// The perceptual roughness (α = roughness², shading_math.h) of that widened lobe: what a widened
// closure holds (light::widen_closure; widen_closure of shading_template.glsl).
MVPL_VSL_FN float vsl_roughness(float alpha, float spread2) {
    return sqrt(vsl_alpha(alpha, spread2));
}

// The squared distance that divides the glossy products of a VSL pair (issue 15): clamping
// lobe by lobe. Only the diffuse × diffuse product of a pair keeps the clamp max(d², d_min²);
// every product with a widened glossy lobe in it is bounded by the sphere itself. A widened
// lobe's peak D ≤ 1/(π s²) = 4 max(d², r²)/(π r²), so its product over max(d², r²) stays below
// 4/(π r²) however close the pair (tests/light/test_lobe_clamp.cpp); plain 1/d² would be
// singular, because the spread saturates inside the sphere (d < r). min(r², d_min²) keeps
// the glossy part's clamp from exceeding the one it replaces, so d_min = 0 is unclamped (the
// point VPLs' 1/d²) and the default radius (0.03 < 0.05 diagonals) uses r.
MVPL_VSL_FN float vsl_glossy_d2(float d2, float r2, float d_min2) {
    return max(d2, min(r2, d_min2));
}

MVPL_SHARED_END

#undef MVPL_VSL_FN

#endif
