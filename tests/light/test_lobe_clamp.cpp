// Clamping lobe by lobe (issue 15, item 2; engine/light/vpl.h, shared::vsl_glossy_d2): a VSL
// pair's diffuse × diffuse product keeps max(d², d_min²), its glossy products are divided by
// max(d², min(r², d_min²)) and stay bounded as the pair closes; without spheres or without the
// clamp the contribution is the formula as it was.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "engine/light/virtual_sphere.h"
#include "engine/light/vpl_contribution.h"
#include "shaders/shared/virtual_sphere.h"
#include "tests/support/scene_builder.h"

namespace mvpl::light {
namespace {

// A floor y = 0 of `material`, front face up.
scene::Scene floor_scene(const scene::Material& material) {
    scene::Scene s;
    s.materials.push_back(material);
    s.meshes.push_back(test::make_quad(Vec3(-2, 0, -2), Vec3(0, 0, 4), Vec3(4, 0, 0), 0));
    return s;
}

scene::Material glossy_material(float metallic, float roughness) {
    scene::Material m;
    m.base_color = metallic > 0.0f ? Rgb(1.0f) : Rgb(0.6f, 0.5f, 0.4f);
    m.metallic = metallic;
    m.roughness = roughness;
    m.specular = 1.0f;
    return m;
}

// The camera looks at the origin from `toward` (unit, above the floor).
const Vec3 kToward = glm::normalize(Vec3(0.0f, 1.0f, 1.0f));

Receiver receiver_at_origin(const scene::Scene& s, const trace::Accel& accel) {
    const std::optional<Receiver> r = make_receiver(s, accel, trace::Ray{3.0f * kToward, -kToward});
    EXPECT_TRUE(r);
    return *r;
}

// An area VPL at distance d along the receiver's mirror direction, facing it.
Vpl area_vpl_at(float d) {
    const Vec3 mirror(-kToward.x, kToward.y, -kToward.z);
    Vpl v;
    v.type = VplType::Area;
    v.position = d * mirror;
    v.normal = -mirror;
    v.power = Rgb(1.0f);
    return v;
}

// The glossy part's bound (shared/virtual_sphere.h): the widened lobe's D ≤ 4 max(d², r²)/(π r²),
// and F ≤ 1, G₂ ≤ 1, so f·cos θ' = F·D·G₂/(4 cos θo) ≤ D/(4 cos θo); with the emitter's cosine
// ≤ 1 and the divisor max(d², r²), a unit-power VPL contributes at most 1/(π r² cos θo). A white
// conductor (F → 1 at the mirror direction) is all glossy part. Point VPLs (no sphere, no clamp)
// grow as 1/(α² d²): the same scan must exceed the bound by orders of magnitude, or the bound
// would not show anything.
TEST(LobeClamp, TheGlossyPartStaysBoundedAsThePairCloses) {
    const scene::Scene s = floor_scene(glossy_material(1.0f, 0.1f));
    const trace::Accel accel(s);
    const Receiver r = receiver_at_origin(s, accel);
    const float radius = 0.05f;
    const float d_min = 0.5f;
    const float bound = 1.0f / (kPi * radius * radius * r.wo.z);
    float largest = 0.0f, largest_point = 0.0f;
    for (float d = 0.5f; d > 1e-4f; d *= 0.8f) {
        const Vpl v = area_vpl_at(d);
        const float c =
            vpl_contribution(accel, r, prepare_vpl(v), d_min * d_min, radius * radius).r;
        ASSERT_TRUE(std::isfinite(c)) << d;
        largest = std::max(largest, c);
        largest_point = std::max(largest_point, vpl_contribution(accel, r, prepare_vpl(v), 0.0f).r);
        EXPECT_LE(c, bound) << "d = " << d;
    }
    EXPECT_GT(largest, 0.1f * bound) << "the scan reaches the bound's order";
    EXPECT_GT(largest_point, 100.0f * bound) << "point VPLs are singular";
    RecordProperty("largest_over_bound", std::to_string(largest / bound));
    RecordProperty("point_largest_over_bound", std::to_string(largest_point / bound));
}

// A glossy plastic receiver and a glossy surface VPL at r < d < d_min and at d < r: the
// diffuse × diffuse product over d_min², the rest over d² or r², the lobes evaluated as vpl.h
// says (independently here: Bsdf::eval of the widened closures and Bsdf::eval_diffuse). Float
// rounding of the same operations in another order: 1e-5 relative.
TEST(LobeClamp, OnlyTheDiffuseProductIsClamped) {
    const scene::Scene s = floor_scene(glossy_material(0.0f, 0.3f));
    const trace::Accel accel(s);
    const Receiver r = receiver_at_origin(s, accel);
    const float radius = 0.05f, d_min = 0.5f;
    for (const float d : {0.2f, 0.03f}) {
        Vpl v;
        v.type = VplType::Surface;
        v.position = d * glm::normalize(Vec3(0.3f, 1.0f, -0.8f));
        v.normal = glm::normalize(Vec3(0.1f, -1.0f, 0.3f));
        v.shading_normal = v.normal;
        v.wi = glm::normalize(Vec3(0.5f, -0.4f, 0.6f));
        v.power = Rgb(1.0f, 2.0f, 3.0f);
        v.closure.base_color = Rgb(0.3f, 0.7f, 0.5f);
        v.closure.metallic = 0.4f;
        v.closure.roughness = 0.25f;
        v.closure.specular = 1.0f;
        const Rgb c = vpl_contribution(accel, r, prepare_vpl(v), d_min * d_min, radius * radius);

        const float d2 = glm::dot(v.position, v.position);
        const Vec3 to_vpl = v.position / std::sqrt(d2);
        const Vec3 wi = r.sp.frame.to_local(to_vpl);
        const float spread2 = shared::vsl_spread2(radius * radius, d2);
        const Frame vf(v.shading_normal);
        const Vec3 v_in = vf.to_local(v.wi), v_out = vf.to_local(-to_vpl);
        const float cos_j = glm::dot(v.normal, -to_vpl);
        const Rgb f_r = material::Bsdf(widen_closure(r.sp.bsdf.params(), spread2)).eval(r.wo, wi);
        const Rgb f_j = material::Bsdf(widen_closure(v.closure, spread2)).eval(v_in, v_out);
        const Rgb d_r = r.sp.bsdf.eval_diffuse(r.wo, wi);
        const Rgb d_j = material::Bsdf(v.closure).eval_diffuse(v_in, v_out);
        const Rgb diffuse = v.power * d_r * d_j * cos_j * wi.z;
        const Rgb glossy = v.power * (f_r * f_j - d_r * d_j) * cos_j * wi.z;
        const Rgb expected = diffuse / (d_min * d_min) + glossy / std::max(d2, radius * radius);
        ASSERT_GT(std::min({diffuse.r, diffuse.g, diffuse.b}), 0.0f);
        ASSERT_GT(std::min({glossy.r, glossy.g, glossy.b}), 0.1f * max_component(diffuse))
            << "a glossy pair";
        for (int k = 0; k < 3; ++k)
            EXPECT_NEAR(c[k], expected[k], 1e-5f * expected[k]) << "d = " << d << ", " << k;
    }
}

// --no-vsl (r = 0) and --clamp 0 (d_min = 0): vpl.h's formula as before issue 15, bit for bit
// (the same operations in the same order as before the lobes were split).
TEST(LobeClamp, WithoutSpheresOrClampTheFormulaIsUnchanged) {
    const scene::Scene s = floor_scene(glossy_material(0.0f, 0.3f));
    const trace::Accel accel(s);
    const Receiver r = receiver_at_origin(s, accel);
    const Vpl v = area_vpl_at(0.1f);
    for (const auto& [d_min2, r2] : {std::pair{0.25f, 0.0f}, std::pair{0.0f, 0.0025f}}) {
        const Vec3 d = v.position - r.sp.p;
        const float dist2 = glm::dot(d, d);
        const Vec3 to_light = d / std::sqrt(dist2);
        const float spread2 = shared::vsl_spread2(r2, dist2);
        const float emitter = std::max(0.0f, glm::dot(v.normal, -to_light));
        const Vec3 wi = r.sp.frame.to_local(to_light);
        const Rgb f =
            spread2 > 0.0f
                ? material::Bsdf(widen_closure(r.sp.bsdf.params(), spread2)).eval(r.wo, wi)
                : r.sp.bsdf.eval(r.wo, wi);
        // Φ f_r cos θr · e / max(d², d_min²), in shaders/shared/vpl_pair.h's order of operations.
        const Rgb before = v.power * f * wi.z * emitter / std::max(dist2, d_min2);
        EXPECT_EQ(vpl_contribution(accel, r, prepare_vpl(v), d_min2, r2), before) << d_min2;
    }
}

}  // namespace
}  // namespace mvpl::light
