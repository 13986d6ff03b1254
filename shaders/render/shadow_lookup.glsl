// The shadow test against a distance cube, 1 where the cube's centre sees the receiver and 0 where
// it does not (visibility(): the shading pass's point, spot, area and surface VPLs; the reduced
// matrix's rows, matrix_template.glsl). Included after the stage's bindings (shadow_cubes, the push
// constants pc with texel_angle); ortho_lookup.glsl holds the directional VPLs' test.

// Shadow test against the VPL's distance cube, in two lookups.
//
// The receiver-plane test. Nearest sampling reads the texel that contains the direction w to the
// receiver; what that texel stores is the distance rasterised along its CENTRE direction w_c, up
// to half a texel diagonal (0.71 texel angles τ) away. Instead of a slope-scaled bias (which, at
// grazing angles, must grow to d · tan θ · τ and then reaches through walls), the receiver's own
// plane is intersected along w_c: d_c = n·(p − x)/(n·w_c) is the distance the texel would store
// if nothing stood in front of the receiver's plane, so the receiver is lit when stored ≥ d_c, up
// to kConstantBias for the rounding of interpolated distances (~1e-6 relative) and
// kFootprintBias footprints (d · τ) so that a surface meeting the receiver in a concave corner
// does not shadow it. Where w_c runs nearly parallel to the plane, d_c is unreliable and the
// receiver's own distance d with a bounded slope bias is used instead.
//
// The junction test (issue 13, thin walls). The plane test cannot see a zero-thickness wall that
// stands on the receiver's surface: within about a footprint behind the wall's foot the texel's
// centre may pass under the wall and hit the floor in front of it, which lies in the receiver's
// plane, and the footprint allowance lets the wall's foot itself pass; a thick wall hides that
// band, a single plane leaves it in view as a bright line along each junction (measured: 88
// leaking pixels per VPL set in tests/render/test_thin_walls.cpp). The second lookup moves the
// receiver off its surface towards the VPL by kNormalOffset · d · τ · sin θ (a normal offset:
// along w_c the receiver's plane then lies (kNormalOffset − 0.71) · d · τ · tan θ beyond the
// moved point, so the point's own distance can be compared without self-shadowing) and asks
// whether something stands in front of that point within kJunctionReach footprints: a wall at
// the receiver's foot (8: the plane test's leak band, its allowance plus half a texel diagonal,
// 1.71 footprints, plus this lookup's own spread of 0.71 · tan β footprints on a wall met at up
// to β = 83°; 4, for 72°, leaked beside a wall met at 69° at 256² faces in the family of
// test_thin_walls.cpp). Only such near occluders count, so that the offset, which moves the
// lookup by up to kNormalOffset texel angles, does not move the shadows of distant occluders
// (shadowing by every occluder through the offset lookup raised the GPU-vs-oracle error
// 2.6–3.6× on the Cornell box and the two-room scene; a reach of 8 instead of 4 left it
// unchanged). It is generated where a drawn material is double-sided or a mesh is open
// (ShaderFeatures::thin_walls): a plane is a zero-thickness wall whether one or both of its
// sides are shaded, and only a scene of closed solids does not pay for the second lookup.
const float kConstantBias = 2e-4;
const float kFootprintBias = 1.0;
const float kSlopeBias = 1.0;
const float kMaxSlope = 4.0;
const float kNormalOffset = 1.0;
const float kJunctionReach = 8.0;
// Texels drawn from a simplified level of detail hold their distance negated (shadow.frag): such a
// surface lies up to kLodFootprint footprints from the full one (shared/shadow_map.h). The plane
// test's kFootprintBias covers it already; the junction lookups and the orthographic maps' test
// allow it for those texels only, so that thin walls (never simplified) shadow as before.

// The distance a shadow texel holds, and the depth its level of detail may stand in front.
vec2 stored_distance(float texel_value, float footprint) {
    return vec2(abs(texel_value), texel_value < 0.0 ? kLodFootprint * footprint : 0.0);
}

// The cube texel that holds direction w, found as Vulkan's cube sampling finds it (spec, "Cube Map
// Face Selection", the projection shadow.vert renders with), nearest filtering and clamp to edge:
// face = major axis m_a of w, (s, t) = ((s_c, t_c) / |m_a| + 1) / 2, texel = floor((s, t) · res).
// The test needs the texel's centre anyway, so the texel is loaded from the cubes' 2D array
// (shadow_pass.h) rather than sampled through a samplerCubeArray, whose own face selection and
// coordinate handling on lavapipe cost more than all of this: the shading pass ran 1.13–1.4×
// faster without it (Cornell box, 512², batch 32, same-run A/Bs). s_c = S·w and t_c = T·w
// with the face's signed axes S and T; m = M·w = |m_a|.
struct CubeTexel {
    ivec3 texel;  // (column, row, face 0..5 in the order +X −X +Y −Y +Z −Z)
    vec3 centre;  // unit direction through the texel's centre
};

CubeTexel cube_texel(vec3 w, float res) {
    const vec3 a = abs(w);
    const bool x_major = a.x >= a.y && a.x >= a.z;
    const bool y_major = !x_major && a.y >= a.z;
    const bvec3 negative = lessThan(w, vec3(0.0));
    vec3 m_axis, s_axis, t_axis;
    int face;
    if (x_major) {
        m_axis = vec3(negative.x ? -1.0 : 1.0, 0.0, 0.0);
        s_axis = vec3(0.0, 0.0, negative.x ? 1.0 : -1.0);
        t_axis = vec3(0.0, -1.0, 0.0);
        face = negative.x ? 1 : 0;
    } else if (y_major) {
        m_axis = vec3(0.0, negative.y ? -1.0 : 1.0, 0.0);
        s_axis = vec3(1.0, 0.0, 0.0);
        t_axis = vec3(0.0, 0.0, negative.y ? -1.0 : 1.0);
        face = negative.y ? 3 : 2;
    } else {
        m_axis = vec3(0.0, 0.0, negative.z ? -1.0 : 1.0);
        s_axis = vec3(negative.z ? -1.0 : 1.0, 0.0, 0.0);
        t_axis = vec3(0.0, -1.0, 0.0);
        face = negative.z ? 5 : 4;
    }
    const float m = dot(m_axis, w);
    const vec2 st = vec2(dot(s_axis, w), dot(t_axis, w)) / m * 0.5 + 0.5;
    const vec2 texel = clamp(floor(st * res), vec2(0.0), vec2(res - 1.0));
    const vec2 centre = (texel + 0.5) / res * 2.0 - 1.0;
    return CubeTexel(ivec3(ivec2(texel), face),
                     normalize(m_axis + centre.x * s_axis + centre.y * t_axis));
}

// Whether the occluder a texel holds stands beyond a receiver at distance d along w, not in front
// of it (shared/shadow_map.h, the plane channel). The texel's surface is the plane through the
// point `stored` along the texel's centre direction wc with the stored normal; the ray towards the
// receiver meets that plane at t = stored · (n·wc) / (n·w). visibility()'s two lookups (below)
// compare distances along wc, where a surface that meets the receiver's surface in a concave
// corner (a wall on a floor, a box's lit side on the floor before it) may stand in front of the
// receiver's own point by up to (cot α_o + cot α_r) · 0.71 footprints for a ray at angles α_o and α_r to the two
// surfaces: 1.8 footprints for a wall seen at 26° from a ceiling light, beyond kFootprintBias, and
// within the junction lookup's reach. Along w itself such a surface lies beyond the receiver, and
// only a surface that covers the receiver's direction (its plane, within the texel) lies before
// it. Measured on the Cornell box against the oracle (direct light, 256² faces): the floor beside
// the walls 2–3.5 % dark and the floor before the boxes 6–12 % dark without this test.
// `allowance`: how far beyond the receiver the plane must pass (rounding, a simplified mesh's
// offset); within it the lookup's first answer stands, so that a receiver behind a wall's foot
// within rounding of the wall stays dark. (With the allowance the other way, thin lines of light,
// one VPL's each, came out at 15–20× the reference in the two rooms where row-column sampling's
// weights carried them: 2 of 3 renders at 15 s, relMSE 0.06 and 0.12; this way 0.0017–0.0019.)
// The quantised normal moves t by about its error (≤ 1.04·10⁻³ rad) times the angle between w
// and wc (≤ 0.71 texel angles) over |n·w|: within kConstantBias from 128² faces on (2.3·10⁻⁴
// at 64²), and only for receivers that close to the plane. A plane the ray runs along (|n·w|
// below kMinPlaneCos) is not trusted, nor a texel without a plane.
const float kMinPlaneCos = 0.1;

// The normal (not of unit length) of a texel's plane code other than kNoOccluderPlane.
vec3 occluder_plane_normal(float code) {
    const float s = occluder_plane_s(code);
    const float t = occluder_plane_t(code);
    const vec2 p = vec2(s + t, s - t) * 0.5;
    return vec3(p, 1.0 - abs(p.x) - abs(p.y));
}

bool occluder_plane_passes_behind(vec2 texel_value, vec3 wc, vec3 w, float d, float allowance) {
    const float stored = abs(texel_value.x);
    if (texel_value.y == kNoOccluderPlane || stored >= kShadowNoOccluder) return false;
    const vec3 n = occluder_plane_normal(texel_value.y);
    const float along = dot(n, w);
    if (abs(along) < kMinPlaneCos * length(n)) return false;
    return stored * dot(n, wc) / along > d + allowance;
}

// to_receiver = p − VPL, d = |to_receiver|, ng the receiver's geometric normal on the side it is
// shaded from.
float visibility(uint cube, vec3 to_receiver, float d, vec3 ng, float res) {
    const float footprint = d * pc.texel_angle;
    const vec3 w = to_receiver / d;
    const CubeTexel ct = cube_texel(w, res);
    const vec2 texel_value =
        imageLoad(shadow_cubes, ivec3(ct.texel.xy, 6 * int(cube) + ct.texel.z)).rg;
    const vec2 stored = stored_distance(texel_value.x, footprint);
    const vec3 wc = ct.centre;
    const float along = dot(ng, wc);
    const float d_plane = dot(ng, to_receiver) / along;
    const float cos_r = abs(dot(ng, w));
    bool lit;
    if (abs(along) > 0.05 * cos_r && d_plane > 0.5 * d && d_plane < 2.0 * d) {
        // kFootprintBias ≥ kLodFootprint: the allowance of simplified casters is in it.
        lit = stored.x >= d_plane - (kConstantBias * d + kFootprintBias * footprint);
    } else {
        const float tan_r = min(sqrt(max(0.0, 1.0 - cos_r * cos_r)) / max(cos_r, 1e-6), kMaxSlope);
        lit = stored.x >= d - d * (kConstantBias + kSlopeBias * pc.texel_angle * tan_r) - stored.y;
    }
    if (!lit)
        lit = occluder_plane_passes_behind(texel_value, wc, w, d, kConstantBias * d + stored.y);

//@if thin_walls
    const float cos_g = dot(ng, w);
    const vec3 towards_vpl = cos_g <= 0.0 ? ng : -ng;
    const float sin_g = sqrt(max(0.0, 1.0 - cos_g * cos_g));
    const vec3 lookup = to_receiver + towards_vpl * (kNormalOffset * footprint * sin_g);
    const float d_lookup = length(lookup);
    const CubeTexel moved = cube_texel(lookup / d_lookup, res);
    const vec2 moved_value =
        imageLoad(shadow_cubes, ivec3(moved.texel.xy, 6 * int(cube) + moved.texel.z)).rg;
    const vec2 near = stored_distance(moved_value.x, footprint);
    const float in_front = d_lookup - near.x;
    if (in_front > kConstantBias * d_lookup + near.y && in_front < kJunctionReach * footprint &&
        !occluder_plane_passes_behind(moved_value, moved.centre, lookup / d_lookup, d_lookup,
                                      kConstantBias * d_lookup + near.y))
        lit = false;
//@endif
    return lit ? 1.0 : 0.0;
}
