// glTF's visibility rules in the BVH (issue 12): COLOR_0 reaches the shading point, camera rays
// do not see the back faces of one-sided materials (doubleSided: false) while light paths and
// shadow rays still hit them, and alphaMode MASK cuts its surface for every ray.
#include <gtest/gtest.h>

#include "engine/trace/accel.h"
#include "engine/trace/interaction.h"
#include "engine/trace/shading_point.h"
#include "tests/support/scene_builder.h"

namespace mvpl {
namespace {

// A 2 × 2 quad in z = 0 facing +Z, u = (x + 1) / 2 along +X.
scene::Mesh unit_quad(int material) {
    return test::make_quad(Vec3(-1, -1, 0), Vec3(2, 0, 0), Vec3(0, 2, 0), material);
}

// Rays along −Z from z = 1 (the front) and along +Z from z = −1 (the back) at x.
trace::Ray from_front(float x) {
    return {Vec3(x, 0.1f, 1.0f), Vec3(0, 0, -1)};
}
trace::Ray from_back(float x) {
    return {Vec3(x, 0.1f, -1.0f), Vec3(0, 0, 1)};
}

TEST(GltfVisibility, VertexColourMultipliesTheBaseColourAtHits) {
    scene::Scene s;
    s.materials.push_back(test::diffuse_material(Rgb(0.5f)));
    scene::Mesh quad = unit_quad(0);
    // Red on the left edge, blue on the right: the colour at x is their mix at u.
    quad.colors = {Vec4(1, 0, 0, 1), Vec4(0, 0, 1, 1), Vec4(0, 0, 1, 1), Vec4(1, 0, 0, 1)};
    s.meshes.push_back(quad);
    const trace::Accel accel(s);
    for (const float x : {-0.5f, 0.0f, 0.5f}) {
        const trace::Ray ray = from_front(x);
        const auto hit = accel.intersect(ray);
        ASSERT_TRUE(hit);
        const trace::SurfaceInteraction si = trace::make_interaction(s, *hit, ray);
        const float u = 0.5f * (x + 1.0f);
        EXPECT_NEAR(si.color.r, 1.0f - u, 1e-5f);
        EXPECT_NEAR(si.color.b, u, 1e-5f);
        const trace::ShadingPoint sp = trace::make_shading_point(accel.materials(), si);
        const Rgb base = sp.bsdf.params().base_color;
        EXPECT_NEAR(base.r, 0.5f * (1.0f - u), 1e-5f) << x;
        EXPECT_NEAR(base.g, 0.0f, 1e-6f) << x;
        EXPECT_NEAR(base.b, 0.5f * u, 1e-5f) << x;
    }
}

TEST(GltfVisibility, CameraRaysPassThroughBackFacesOfOneSidedMaterials) {
    scene::Scene s;
    s.materials.push_back(test::diffuse_material(Rgb(0.5f)));  // one-sided (the glTF default)
    scene::Material two_sided = test::diffuse_material(Rgb(0.5f));
    two_sided.double_sided = true;
    s.materials.push_back(two_sided);
    s.meshes.push_back(unit_quad(0));
    // A double-sided quad behind the one-sided one, as seen from the back: z = 1, facing −Z.
    s.meshes.push_back(test::make_quad(Vec3(-1, -1, 0.5f), Vec3(0, 2, 0), Vec3(2, 0, 0), 1));
    const trace::Accel accel(s);

    const auto front = accel.intersect_camera(from_front(0.0f));
    ASSERT_TRUE(front);
    EXPECT_EQ(front->mesh, 1);  // the camera ray from z = 1 meets the z = 0.5 quad first
    const auto seen = accel.intersect_camera({Vec3(0, 0.1f, 0.25f), Vec3(0, 0, -1)});
    ASSERT_TRUE(seen);
    EXPECT_EQ(seen->mesh, 0);  // the one-sided quad's front face

    // From behind: the camera sees through the one-sided quad to the double-sided one (its
    // back face too), while light paths and shadow rays still hit it.
    const auto through = accel.intersect_camera(from_back(0.0f));
    ASSERT_TRUE(through);
    EXPECT_EQ(through->mesh, 1);
    const auto light = accel.intersect(from_back(0.0f));
    ASSERT_TRUE(light);
    EXPECT_EQ(light->mesh, 0);
    trace::Ray shadow = from_back(0.0f);
    shadow.tmax = 1.25f;  // ends before the double-sided quad
    EXPECT_TRUE(accel.occluded(shadow));
}

scene::Material masked_material(float cutoff) {
    scene::Material m = test::diffuse_material(Rgb(0.8f));
    m.alpha_mode = scene::AlphaMode::Mask;
    m.alpha_cutoff = cutoff;
    return m;
}

// A masked quad (mesh 0) over an opaque one (mesh 1) at z = −0.5: rays through cut texels reach
// the one behind.
struct MaskScene {
    scene::Scene scene;
};

MaskScene mask_scene(scene::Material m, const std::vector<Vec4>& colors = {}) {
    MaskScene out;
    out.scene.materials.push_back(m);
    out.scene.materials.push_back(test::diffuse_material(Rgb(0.5f)));
    scene::Mesh quad = unit_quad(0);
    quad.colors = colors;
    out.scene.meshes.push_back(quad);
    out.scene.meshes.push_back(
        test::make_quad(Vec3(-1, -1, -0.5f), Vec3(2, 0, 0), Vec3(0, 2, 0), 1));
    return out;
}

// Whether every kind of ray passes through the masked quad at x (camera, light path, shadow ray
// from either side) — or none does.
void expect_cut(const trace::Accel& accel, float x, bool cut) {
    const auto camera = accel.intersect_camera(from_front(x));
    ASSERT_TRUE(camera);
    EXPECT_EQ(camera->mesh, cut ? 1 : 0) << "camera ray at x = " << x;
    const auto path = accel.intersect(from_front(x));
    ASSERT_TRUE(path);
    EXPECT_EQ(path->mesh, cut ? 1 : 0) << "light path at x = " << x;
    trace::Ray shadow = from_back(x);
    shadow.origin.z = -0.25f;  // between the quads, towards z = 1
    shadow.tmax = 1.25f;
    EXPECT_EQ(accel.occluded(shadow), !cut) << "shadow ray at x = " << x;
}

TEST(GltfVisibility, MaskCutsWhereVertexAlphaIsBelowTheCutoff) {
    // Alpha = u: the left half (u < 0.5) is cut.
    const MaskScene m = mask_scene(masked_material(0.5f), {Vec4(1, 1, 1, 0), Vec4(1, 1, 1, 1),
                                                           Vec4(1, 1, 1, 1), Vec4(1, 1, 1, 0)});
    const trace::Accel accel(m.scene);
    expect_cut(accel, -0.5f, true);
    expect_cut(accel, 0.5f, false);
    // A higher cutoff cuts more: alpha 0.75 at x = 0.5 is below 0.8.
    const MaskScene high = mask_scene(masked_material(0.8f), m.scene.meshes[0].colors);
    const trace::Accel high_accel(high.scene);
    expect_cut(high_accel, 0.5f, true);
    expect_cut(high_accel, 0.8f, false);
}

TEST(GltfVisibility, MaskReadsTheFactorAndTextureAlpha) {
    // Texture: alpha 0 in its left column, 1 in its right (nearest filtering).
    scene::Texture t;
    t.width = 2;
    t.height = 1;
    t.texels = {Vec4(1, 1, 1, 0), Vec4(1, 1, 1, 1)};
    t.filter = scene::Filter::Nearest;
    scene::Material textured = masked_material(0.5f);
    textured.base_color_texture.texture = 0;
    MaskScene m = mask_scene(textured);
    m.scene.textures.push_back(t);
    const trace::Accel accel(m.scene);
    expect_cut(accel, -0.5f, true);
    expect_cut(accel, 0.5f, false);

    // baseColorFactor's alpha 0.4 is below the default cutoff everywhere; 0.6 is not.
    scene::Material faint = masked_material(0.5f);
    faint.base_alpha = 0.4f;
    const MaskScene faint_scene = mask_scene(faint);  // the BVH keeps references to its scene
    const trace::Accel faint_accel(faint_scene.scene);
    expect_cut(faint_accel, 0.0f, true);
    faint.base_alpha = 0.6f;
    const MaskScene solid_scene = mask_scene(faint);
    const trace::Accel solid_accel(solid_scene.scene);
    expect_cut(solid_accel, 0.0f, false);
}

// BLEND as hashed transparency: a ray passes through with probability 1 − alpha, the same ray
// always alike (a hash of the ray, not a random draw).
TEST(GltfVisibility, BlendPassesAFractionOneMinusAlphaDeterministically) {
    scene::Material blend = test::diffuse_material(Rgb(0.8f));
    blend.alpha_mode = scene::AlphaMode::Blend;
    blend.base_alpha = 0.3f;
    const MaskScene m = mask_scene(blend);
    const trace::Accel accel(m.scene);
    constexpr int kSide = 64;
    int camera_hits = 0;
    int shadowed = 0;
    for (int j = 0; j < kSide; ++j) {
        for (int i = 0; i < kSide; ++i) {
            const float x = -0.95f + 1.9f * (float(i) + 0.5f) / kSide;
            const float y = -0.95f + 1.9f * (float(j) + 0.5f) / kSide;
            const trace::Ray ray{Vec3(x, y, 1.0f), Vec3(0.01f * x, 0.0f, -1.0f)};
            const auto hit = accel.intersect_camera(ray);
            ASSERT_TRUE(hit);
            camera_hits += hit->mesh == 0 ? 1 : 0;
            EXPECT_EQ(accel.intersect_camera(ray)->mesh, hit->mesh);  // deterministic
            const trace::Ray shadow{Vec3(x, y, -0.25f), Vec3(0.0f, 0.01f * y, 1.0f), 1.25f};
            shadowed += accel.occluded(shadow) ? 1 : 0;
            EXPECT_EQ(accel.occluded(shadow), accel.occluded(shadow));
        }
    }
    // Binomial: 4096 rays, σ = √(0.21 / 4096) = 0.007; 5σ.
    constexpr double kCount = kSide * kSide;
    EXPECT_NEAR(camera_hits / kCount, 0.3, 0.036);
    EXPECT_NEAR(shadowed / kCount, 0.3, 0.036);
}

TEST(GltfVisibility, OpaqueIgnoresAlpha) {
    scene::Material opaque = test::diffuse_material(Rgb(0.8f));
    opaque.base_alpha = 0.0f;
    const MaskScene m = mask_scene(opaque);
    const trace::Accel accel(m.scene);
    expect_cut(accel, 0.0f, false);
}

}  // namespace
}  // namespace mvpl
