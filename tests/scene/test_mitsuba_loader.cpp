// The Mitsuba XML loader (issue 16): each transform against its matrix worked by hand, $-
// substitution with <default> and -D, <include>, ids and <ref>, Mitsuba 0.6's camelCase names,
// the sensor's field of view and orientation, the envmap's orientation against Mitsuba's own
// lookup formula, and the serialized meshes of ../shared/mitsuba-scenes when present.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "engine/core/error.h"
#include "engine/core/image.h"
#include "engine/scene/scene_loader.h"
#include "tests/scene/mitsuba_xml.h"

namespace mvpl::scene {
namespace {

namespace fs = std::filesystem;

using testing::scene_xml;

fs::path temp_dir() {
    return testing::mitsuba_temp_dir();
}

fs::path write(const std::string& name, const std::string& text) {
    return testing::write_file(name, text);
}

// A rectangle (corners (±1, ±1, 0)) under `transform`; the world position of its corner (1, 1).
Vec3 corner_under(const std::string& transform) {
    const fs::path p = write("transform.xml", scene_xml("<shape type=\"rectangle\"><transform "
                                                        "name=\"to_world\">" +
                                                        transform + "</transform></shape>"));
    const Scene s = load_scene(p.string());
    EXPECT_EQ(s.meshes.size(), 1u);
    return s.meshes[0].positions[2];  // rectangle_mesh's third corner is (1, 1, 0)
}

void expect_near(const Vec3& a, const Vec3& b, float tolerance = 1e-5f) {
    EXPECT_NEAR(a.x, b.x, tolerance);
    EXPECT_NEAR(a.y, b.y, tolerance);
    EXPECT_NEAR(a.z, b.z, tolerance);
}

TEST(MitsubaTransforms, EachStepMovesTheCornerAsWorkedByHand) {
    expect_near(corner_under("<translate x=\"1\" y=\"2\" z=\"3\"/>"), Vec3(2, 3, 3));
    expect_near(corner_under("<translate value=\"1, 2, 3\"/>"), Vec3(2, 3, 3));
    expect_near(corner_under("<scale value=\"2\"/>"), Vec3(2, 2, 0));
    expect_near(corner_under("<scale x=\"3\"/>"), Vec3(3, 1, 0));
    // Right-handed 90° about +z: (1, 1, 0) → (−1, 1, 0).
    expect_near(corner_under("<rotate z=\"1\" angle=\"90\"/>"), Vec3(-1, 1, 0));
    expect_near(corner_under("<rotate value=\"0, 0, 1\" angle=\"90\"/>"), Vec3(-1, 1, 0));
    // 90° about +x: (1, 1, 0) → (1, 0, 1).
    expect_near(corner_under("<rotate x=\"1\" angle=\"90\"/>"), Vec3(1, 0, 1));
    // Row-major as written: the last column is the translation.
    expect_near(corner_under("<matrix value=\"1 0 0 5  0 1 0 6  0 0 1 7  0 0 0 1\"/>"),
                Vec3(6, 7, 7));
    expect_near(corner_under("<matrix value=\"0 -1 0  1 0 0  0 0 1\"/>"), Vec3(-1, 1, 0));
    // Later steps apply after earlier ones: scale, then translate.
    expect_near(corner_under("<scale value=\"2\"/><translate x=\"1\"/>"), Vec3(3, 2, 0));
    expect_near(corner_under("<translate x=\"1\"/><scale value=\"2\"/>"), Vec3(4, 2, 0));
    // lookat: columns (left, up, forward, origin); looking down −z from (0, 0, 5) with up +y,
    // left = up × forward = (+y) × (−z) = −x, so local (1, 1, 0) lands at (−1, 1, 5).
    expect_near(corner_under("<lookat origin=\"0, 0, 5\" target=\"0, 0, 0\" up=\"0, 1, 0\"/>"),
                Vec3(-1, 1, 5));
}

TEST(MitsubaParameters, DefaultsAreSubstitutedAndDefinesOverrideThem) {
    const fs::path p = write("defaults.xml", scene_xml(R"(<default name="r" value="2"/>
<shape type="sphere"><float name="radius" value="$r"/></shape>)"));
    EXPECT_NEAR(load_scene(p.string()).bounds().hi.x, 2.0f, 1e-4f);
    LoadOptions options;
    options.defines = {{"r", "3"}};
    EXPECT_NEAR(load_scene(p.string(), options).bounds().hi.x, 3.0f, 1e-4f);
    const fs::path undefined =
        write("undefined.xml",
              scene_xml(R"(<shape type="sphere"><float name="radius" value="$r"/></shape>)"));
    EXPECT_NO_THROW(load_scene(undefined.string(), options));
    try {
        load_scene(undefined.string());
        ADD_FAILURE() << "an undefined parameter loaded";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("undefined.xml:2: undefined parameter '$r'"),
                  std::string::npos)
            << e.what();
    }
}

TEST(MitsubaInclude, IncludedShapesJoinTheSceneAndErrorsNameTheIncludedFile) {
    write("included.xml", scene_xml(R"(<shape type="cube"/>)"));
    const fs::path p = write("includer.xml", scene_xml(R"(<include filename="included.xml"/>
<shape type="rectangle"/>)"));
    EXPECT_EQ(load_scene(p.string()).meshes.size(), 2u);
    write("bad-included.xml", scene_xml("\n<shape type=\"hair\"/>"));
    const fs::path bad =
        write("bad-includer.xml", scene_xml(R"(<include filename="bad-included.xml"/>)"));
    try {
        load_scene(bad.string());
        ADD_FAILURE() << "an unsupported shape loaded";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("bad-included.xml:3: shape type 'hair'"),
                  std::string::npos)
            << e.what();
    }
}

TEST(MitsubaReferences, ABsdfReferencedTwiceIsOneMaterial) {
    const fs::path p = write("refs.xml", scene_xml(R"(<bsdf type="diffuse" id="red">
    <rgb name="reflectance" value="0.8, 0.1, 0.1"/>
</bsdf>
<shape type="rectangle"><ref id="red"/></shape>
<shape type="cube"><ref name="bsdf" id="red"/></shape>)"));
    const Scene s = load_scene(p.string());
    ASSERT_EQ(s.meshes.size(), 2u);
    EXPECT_EQ(s.meshes[0].material, s.meshes[1].material);
    const Material& m = s.materials[size_t(s.meshes[0].material)];
    EXPECT_FLOAT_EQ(m.base_color.r, 0.8f);
    EXPECT_EQ(m.metallic, 0.0f);
    EXPECT_EQ(m.specular, 0.0f);
}

TEST(MitsubaVersions, Mitsuba06CamelCaseNamesAreUpgraded) {
    const fs::path p = write("v06.xml", scene_xml(R"(<bsdf type="plastic" id="p">
    <float name="intIOR" value="1.7"/>
    <rgb name="diffuseReflectance" value="0.2"/>
</bsdf>
<shape type="rectangle"><ref id="p"/>
    <transform name="toWorld"><translate x="4"/></transform>
</shape>)",
                                                  "0.6.0"));
    const Scene s = load_scene(p.string());
    EXPECT_NEAR(s.bounds().hi.x, 5.0f, 1e-5f);
    const Material& m = s.materials[size_t(s.meshes[0].material)];
    EXPECT_NEAR(m.ior, 1.7f / 1.000277f, 1e-5f);
    EXPECT_FLOAT_EQ(m.base_color.g, 0.2f);
}

TEST(MitsubaSensor, FieldOfViewAxisFilmAndOrientation) {
    const fs::path p = write("sensor.xml", scene_xml(R"(<integrator type="path">
    <integer name="max_depth" value="3"/>
</integrator>
<sensor type="perspective">
    <float name="fov" value="90"/>
    <transform name="to_world"><lookat origin="0, 0, -2" target="0, 0, 0" up="0, 1, 0"/></transform>
    <film type="hdrfilm"><integer name="width" value="200"/><integer name="height" value="100"/></film>
</sensor>
<shape type="rectangle"/>)"));
    const Scene s = load_scene(p.string());
    EXPECT_EQ(s.max_depth, 3);
    EXPECT_EQ(s.film_width, 200);
    EXPECT_EQ(s.film_height, 100);
    // fov along x (Mitsuba's default axis) on a 2:1 film: tan(yfov/2) = tan(45°) / 2.
    EXPECT_NEAR(s.camera.yfov, 2.0f * std::atan(0.5f), 1e-6f);
    expect_near(s.camera.position(), Vec3(0, 0, -2));
    // mvpl's camera looks down its −Z: towards +z here; its +X (image right) is Mitsuba's −X
    // (Mitsuba's camera +X points left), so world −x: the viewer at −z looking at +z has +x on
    // the left.
    expect_near(-Vec3(s.camera.camera_to_world[2]), Vec3(0, 0, 1));
    expect_near(Vec3(s.camera.camera_to_world[0]), Vec3(-1, 0, 0));
    expect_near(Vec3(s.camera.camera_to_world[1]), Vec3(0, 1, 0));
}

// Mitsuba 3's aov integrator: the AOVs it names in mvpl's kinds, the nested integrator's depth,
// the types mvpl does not write warned about, and a malformed list refused.
TEST(MitsubaIntegrator, AovIntegratorRecordsItsAovs) {
    const fs::path p = write("aov.xml", scene_xml(R"(<integrator type="aov">
    <string name="aovs" value="dd.y:depth, nn:sh_normal,alb:albedo,pp:position,uv:uv"/>
    <integrator type="path" name="image"><integer name="max_depth" value="4"/></integrator>
</integrator>
<shape type="rectangle"/>)"));
    const Scene s = load_scene(p.string());
    ASSERT_EQ(s.aovs.size(), 4u);
    const std::pair<const char*, const char*> expected[] = {
        {"depth", "dd.y"}, {"normal", "nn"}, {"albedo", "alb"}, {"position", "pp"}};
    for (size_t i = 0; i < 4; ++i) {
        EXPECT_EQ(s.aovs[i].kind, expected[i].first) << i;
        EXPECT_EQ(s.aovs[i].name, expected[i].second) << i;
    }
    EXPECT_EQ(s.max_depth, 4);
    ASSERT_EQ(s.warnings.size(), 1u);
    EXPECT_NE(s.warnings[0].find("'uv' of type 'uv' is not written"), std::string::npos)
        << s.warnings[0];
    for (const char* bad : {"nn", "nn:normal", "a:depth,a:albedo"}) {
        const fs::path q = write("aov_bad.xml", scene_xml(std::string(R"(<integrator type="aov">
    <string name="aovs" value=")") + bad + R"("/></integrator><shape type="rectangle"/>)"));
        EXPECT_THROW(load_scene(q.string()), InputError) << bad;
    }
}

// Mitsuba's envmap: u = atan2(d.x, −d.z) / 2π, v = acos(d.y) / π in the emitter's local frame.
// A bright 5 × 5 patch of a 64 × 32 map must be seen from the direction of its centre texel's
// centre, under to_world turned about +x (a rotation mvpl's own --env-rotate cannot express).
// The patch, not one texel: the map is resampled into mvpl's orientation, and any lookup within
// a texel of the centre reads the patch alone.
TEST(MitsubaEnvmap, TheBrightTexelIsSeenWhereMitsubaLooksItUp) {
    Image map(64, 32);
    const int bx = 10, by = 9;
    for (int y = by - 2; y <= by + 2; ++y)
        for (int x = bx - 2; x <= bx + 2; ++x)
            map.at(x, y) = Rgb(100.0f);
    const fs::path exr = temp_dir() / "bright.exr";
    write_exr(map, exr.string());
    const fs::path p = write("envmap.xml", scene_xml(R"(<emitter type="envmap">
    <string name="filename" value="bright.exr"/>
    <float name="scale" value="2"/>
    <transform name="to_world"><rotate x="1" angle="90"/></transform>
</emitter>
<shape type="rectangle"/>)"));
    const Scene s = load_scene(p.string());
    ASSERT_TRUE(s.environment.has_map());
    const double pi = std::acos(-1.0);
    const double u = (bx + 0.5) / 64.0, v = (by + 0.5) / 32.0;
    const DVec3 local(std::sin(v * pi) * std::sin(2 * pi * u), std::cos(v * pi),
                      -std::sin(v * pi) * std::cos(2 * pi * u));
    // to_world = R_x(90°): (x, y, z) → (x, −z, y).
    const Vec3 world(float(local.x), float(-local.z), float(local.y));
    EXPECT_NEAR(s.environment.lookup(world).r, 200.0f, 1e-3f);
    EXPECT_NEAR(s.environment.lookup(-world).r, 0.0f, 1e-6f);
}

// Mitsuba's checkerboard: colour0 where (u mod 1 > ½) equals (v mod 1 > ½), colour1 elsewhere,
// through to_uv's scale and offset; the baked 2 × 2 nearest texture must say the same anywhere.
TEST(MitsubaTextures, CheckerboardMatchesMitsubasRuleThroughToUv) {
    const fs::path p = write("checker.xml", scene_xml(R"(<bsdf type="diffuse" id="c">
    <texture type="checkerboard" name="reflectance">
        <rgb name="color0" value="0.9"/>
        <rgb name="color1" value="0.1"/>
        <transform name="to_uv"><scale x="3" y="5"/><translate x="0.25"/></transform>
    </texture>
</bsdf>
<shape type="rectangle"><ref id="c"/></shape>)"));
    const Scene s = load_scene(p.string());
    const Material& m = s.materials[size_t(s.meshes[0].material)];
    ASSERT_TRUE(m.base_color_texture.valid());
    const Texture& t = s.textures[size_t(m.base_color_texture.texture)];
    for (float u = 0.013f; u < 1.0f; u += 0.0517f) {
        for (float v = 0.011f; v < 1.0f; v += 0.0423f) {
            const float tu = 3.0f * u + 0.25f, tv = 5.0f * v;
            const bool x = tu - std::floor(tu) > 0.5f, y = tv - std::floor(tv) > 0.5f;
            const float expected = x == y ? 0.9f : 0.1f;
            const Vec2 uv = m.base_color_texture.transform(Vec2(u, v));
            EXPECT_FLOAT_EQ(t.sample(uv).r, expected) << u << ", " << v;
        }
    }
}

TEST(MitsubaColours, SpectraSrgbAndNamedConductors) {
    const fs::path p = write("colours.xml", scene_xml(R"(<bsdf type="diffuse" id="flat">
    <spectrum name="reflectance" value="360:0.5, 830:0.5"/>
</bsdf>
<bsdf type="diffuse" id="red">
    <spectrum name="reflectance" value="400:0.05, 580:0.05, 600:0.9, 700:0.9"/>
</bsdf>
<bsdf type="diffuse" id="srgb"><srgb name="reflectance" value="#808080"/></bsdf>
<bsdf type="conductor" id="gold"><string name="material" value="Au"/></bsdf>
<bsdf type="conductor" id="mirror"/>
<shape type="rectangle"><ref id="flat"/></shape>
<shape type="rectangle"><ref id="red"/></shape>
<shape type="rectangle"><ref id="srgb"/></shape>
<shape type="rectangle"><ref id="gold"/></shape>
<shape type="rectangle"><ref id="mirror"/></shape>)"));
    const Scene s = load_scene(p.string());
    const auto colour = [&](size_t mesh) {
        return s.materials[size_t(s.meshes[mesh].material)].base_color;
    };
    // A flat spectrum keeps its value in every channel (the white normalisation).
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(colour(0)[c], 0.5f, 1e-4f);
    // Reflecting only above 590 nm: red, with little green and blue.
    EXPECT_GT(colour(1).r, 0.6f);
    EXPECT_LT(colour(1).b, 0.15f);
    // sRGB 128/255 decoded: 0.2158.
    EXPECT_NEAR(colour(2).g, 0.2158f, 1e-3f);
    // Gold's F0 from η = 0.143, k = 3.983 (red): ((η−1)² + k²) / ((η+1)² + k²) = 0.9667.
    EXPECT_NEAR(colour(3).r, 0.9667f, 1e-3f);
    EXPECT_EQ(s.materials[size_t(s.meshes[3].material)].metallic, 1.0f);
    // Mitsuba's default conductor ("none") is a perfect mirror.
    EXPECT_NEAR(colour(4).g, 1.0f, 1e-6f);
    EXPECT_EQ(s.materials[size_t(s.meshes[4].material)].roughness, 0.0f);
}

TEST(MitsubaSerialized, TheMatpreviewShapesLoad) {
    const fs::path common =
        fs::path(MVPL_SOURCE_DIR) / ".." / "shared" / "mitsuba-scenes" / "common";
    if (!fs::exists(common / "meshes" / "matpreview.serialized"))
        GTEST_SKIP() << "../shared/mitsuba-scenes is absent";
    const fs::path p = write("serialized.xml", scene_xml(R"(<shape type="serialized">
    <string name="filename" value="meshes/matpreview.serialized"/>
    <integer name="shape_index" value="2"/>
</shape>
<shape type="serialized">
    <string name="filename" value="meshes/matpreview.serialized"/>
    <integer name="shape_index" value="0"/>
</shape>)"));
    LoadOptions options;
    options.search_paths = {common.string()};
    const Scene s = load_scene(p.string(), options);
    ASSERT_EQ(s.meshes.size(), 2u);
    for (const Mesh& m : s.meshes) {
        EXPECT_GT(m.triangle_count(), 0u);
        EXPECT_EQ(m.normals.size(), m.positions.size());
        for (uint32_t i : m.indices)
            ASSERT_LT(i, m.positions.size());
    }
    LoadOptions beyond = options;
    const fs::path bad = write("serialized-index.xml", scene_xml(R"(<shape type="serialized">
    <string name="filename" value="meshes/matpreview.serialized"/>
    <integer name="shape_index" value="99"/>
</shape>)"));
    EXPECT_THROW(load_scene(bad.string(), beyond), InputError);
}

}  // namespace
}  // namespace mvpl::scene
