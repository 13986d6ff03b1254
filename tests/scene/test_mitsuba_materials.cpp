// The Mitsuba loader's materials (issue 16): every named conductor of Mitsuba's presets against an
// independent integration of the same spectra, textured roughness, rotated texture transforms, and
// a textured mask over a textured BSDF.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "engine/core/error.h"
#include "engine/core/image.h"
#include "engine/material/graph_eval.h"
#include "engine/material/node_graph.h"
#include "engine/scene/scene_loader.h"
#include "tests/scene/mitsuba_xml.h"

namespace mvpl::scene {
namespace {

using testing::scene_xml;
using testing::write_file;

// One conductor in front of vacuum; the material mvpl makes of it.
Material conductor(const std::string& name) {
    const auto p = write_file("conductor.xml", scene_xml(R"(<shape type="rectangle">
    <bsdf type="conductor"><string name="material" value=")" +
                                                         name + R"("/></bsdf>
</shape>)"));
    const Scene s = load_scene(p.string());
    return s.materials.at(size_t(s.meshes.at(0).material));
}

float f0(float eta, float k) {
    return ((eta - 1.0f) * (eta - 1.0f) + k * k) / ((eta + 1.0f) * (eta + 1.0f) + k * k);
}

// Mitsuba 3's table of conductor presets (plugin `conductor`, "conductor-ior-list") and the
// three that Mitsuba 0.6 adds (Se-e, Te-e, TiO2-e): each loads as a metal whose F0 is a
// reflectance.
TEST(MitsubaConductors, EveryPresetOfMitsubaLoads) {
    for (const char* name :
         {"a-C",        "Ag",       "Al",        "AlAs",     "AlAs_palik", "AlSb",
          "AlSb_palik", "Au",       "Be",        "Be_palik", "Cr",         "CsI",
          "CsI_palik",  "Cu",       "Cu_palik",  "Cu2O",     "Cu2O_palik", "CuO",
          "CuO_palik",  "d-C",      "d-C_palik", "Hg",       "Hg_palik",   "HgTe",
          "HgTe_palik", "Ir",       "Ir_palik",  "K",        "K_palik",    "Li",
          "Li_palik",   "MgO",      "MgO_palik", "Mo",       "Mo_palik",   "Na_palik",
          "Nb",         "Nb_palik", "Ni_palik",  "Rh",       "Rh_palik",   "Se",
          "Se_palik",   "SiC",      "SiC_palik", "SnTe",     "SnTe_palik", "Ta",
          "Ta_palik",   "Te",       "Te_palik",  "ThF4",     "ThF4_palik", "TiC",
          "TiC_palik",  "TiN",      "TiN_palik", "TiO2",     "TiO2_palik", "VC",
          "VC_palik",   "V_palik",  "VN",        "VN_palik", "W",          "Se-e",
          "Te-e",       "TiO2-e",   "none"}) {
        SCOPED_TRACE(name);
        const Material m = conductor(name);
        EXPECT_EQ(m.metallic, 1.0f);
        for (int c = 0; c < 3; ++c) {
            EXPECT_GE(m.base_color[c], 0.0f);
            EXPECT_LE(m.base_color[c], 1.0f);
        }
    }
    const auto bad = write_file("conductor-bad.xml", scene_xml(R"(<shape type="rectangle">
    <bsdf type="conductor"><string name="material" value="Unobtainium"/></bsdf>
</shape>)"));
    EXPECT_THROW(load_scene(bad.string()), InputError);
}

// The RGB η and k of Tungsten's ComplexIorData: the same .spd files through the same projection,
// computed by other code than tools/conductor_ior_rgb.py (numerical quadrature, where the script
// integrates the piecewise-linear products exactly). Quadrature error and the table's 6-digit
// rounding keep the two within ~1e-5 relative of each other (7e-6 measured on these and on
// Ag, Al, Au, Cr, Cu); F0's relative derivative in η and k is below 2 for these four (1.2 at most,
// a-C's red η), so F0 within 1e-4 relative holds with a margin of 5, and a wrong spectrum,
// observer or matrix is off by far more.
TEST(MitsubaConductors, F0AgreesWithAnIndependentIntegrationOfTheSpectra) {
    struct Expected {
        const char* name;
        float eta[3];
        float k[3];
    };
    const Expected expected[] = {
        {"a-C",
         {2.9440999183f, 2.2271502925f, 1.9681668794f},
         {0.8874329109f, 0.7993216383f, 0.8152862927f}},
        {"W",
         {4.3707029924f, 3.3002972445f, 2.9982666528f},
         {3.5006778591f, 2.6048652781f, 2.2731930614f}},
        {"TiN",
         {1.6484691607f, 1.1504482522f, 1.3797795097f},
         {3.3684596226f, 1.9434888540f, 1.1020123347f}},
        {"Hg",
         {2.3989314904f, 1.4400254917f, 0.9095512090f},
         {6.3276269444f, 4.3719414152f, 3.4217899270f}},
    };
    for (const Expected& e : expected) {
        SCOPED_TRACE(e.name);
        const Material m = conductor(e.name);
        for (int c = 0; c < 3; ++c) {
            const float want = f0(e.eta[c], e.k[c]);
            EXPECT_NEAR(m.base_color[c], want, 1e-4f * want);
        }
    }
}

// roughconductor with alpha_u and alpha_v checkerboards (bsdf_roughconductor_textured_carbon):
// rendered isotropic with their mean, as constants are, texel by texel. Swapped checkers mean
// (0.05 + 0.3)/2 everywhere, stored as G = √α in the metallic-roughness texture; a texture beside
// a constant is averaged with the constant; textures that do not line up are refused.
TEST(MitsubaConductors, TexturedAnisotropicRoughnessIsTheMeanOfAlphaUAndAlphaV) {
    const auto checker = [](const char* name, float c0, float c1) {
        return std::string(R"(<texture name=")") + name + R"(" type="checkerboard">
    <transform name="to_uv"><scale x="25" y="25"/></transform>
    <float name="color0" value=")" +
               std::to_string(c0) + R"("/>
    <float name="color1" value=")" +
               std::to_string(c1) + R"("/>
</texture>)";
    };
    const auto load = [](const std::string& alphas) {
        const auto p = write_file("carbon.xml", scene_xml(R"(<shape type="rectangle">
    <bsdf type="roughconductor"><string name="material" value="a-C"/>)" +
                                                          alphas + R"(</bsdf>
</shape>)"));
        return load_scene(p.string());
    };
    const auto expect_alpha = [](const Scene& s, float alpha) {
        const Material& m = s.materials.at(0);
        ASSERT_TRUE(m.metallic_roughness_texture.valid());
        EXPECT_EQ(m.roughness, 1.0f);
        EXPECT_EQ(m.metallic_roughness_texture.scale, Vec2(25.0f));
        const Texture& t = s.textures.at(size_t(m.metallic_roughness_texture.texture));
        for (float u = 0.01f; u < 1.0f; u += 0.0973f) {
            const Vec4 v = t.sample(m.metallic_roughness_texture.transform(Vec2(u, 0.37f)));
            EXPECT_NEAR(v.g, std::sqrt(alpha), 1e-6f) << u;
            EXPECT_EQ(v.b, 1.0f);  // metallic
        }
    };
    const Scene carbon = load(checker("alpha_u", 0.05f, 0.3f) + checker("alpha_v", 0.3f, 0.05f));
    expect_alpha(carbon, 0.175f);
    EXPECT_FALSE(carbon.warnings.empty());
    expect_alpha(load(checker("alpha_u", 0.2f, 0.2f) + R"(<float name="alpha_v" value="0.4"/>)"),
                 0.3f);
    const std::string unaligned =
        checker("alpha_u", 0.05f, 0.3f) + R"(<texture name="alpha_v" type="checkerboard"/>)";
    EXPECT_THROW(load(unaligned), InputError);
}

// A checkerboard under a rotated to_uv (scale, then 30° about z, then translate: Mitsuba applies
// to_world-style steps in order, so uv' = T·R·S·uv): at every sample point the loaded texture,
// looked up through the KHR_texture_transform that mvpl maps to_uv onto, gives the colour of
// Mitsuba's rule (colour0 where u' mod 1 > ½ equals v' mod 1 > ½) at uv' worked out here by hand.
// Points within 1e-4 of a checker edge are skipped (float rounding of the two computations may
// put them on either side). A shear has no KHR_texture_transform and is refused at its line.
TEST(MitsubaTextures, RotatedToUvMatchesTheAnalyticCheckerboard) {
    const auto p = write_file("checker-rotated.xml", scene_xml(R"(<bsdf type="diffuse" id="c">
    <texture type="checkerboard" name="reflectance">
        <rgb name="color0" value="0.9"/>
        <rgb name="color1" value="0.1"/>
        <transform name="to_uv">
            <scale x="3" y="5"/><rotate z="1" angle="30"/><translate x="0.25" y="0.1"/>
        </transform>
    </texture>
</bsdf>
<shape type="rectangle"><ref id="c"/></shape>)"));
    const Scene s = load_scene(p.string());
    const Material& m = s.materials.at(size_t(s.meshes.at(0).material));
    ASSERT_TRUE(m.base_color_texture.valid());
    EXPECT_NE(m.base_color_texture.rotation, 0.0f);
    const Texture& t = s.textures.at(size_t(m.base_color_texture.texture));
    const double angle = 30.0 * 3.14159265358979323846 / 180.0;
    int compared = 0, near_edge = 0;
    for (float u = 0.013f; u < 1.0f; u += 0.0317f) {
        for (float v = 0.011f; v < 1.0f; v += 0.0293f) {
            const double su = 3.0 * u, sv = 5.0 * v;
            const double tu = std::cos(angle) * su - std::sin(angle) * sv + 0.25;
            const double tv = std::sin(angle) * su + std::cos(angle) * sv + 0.1;
            const double fu = tu - std::floor(tu), fv = tv - std::floor(tv);
            const auto near = [](double f) {
                return std::min({std::abs(f), std::abs(f - 0.5), std::abs(f - 1.0)}) < 1e-4;
            };
            if (near(fu) || near(fv)) {
                ++near_edge;
                continue;
            }
            const float expected = (fu > 0.5) == (fv > 0.5) ? 0.9f : 0.1f;
            EXPECT_FLOAT_EQ(t.sample(m.base_color_texture.transform(Vec2(u, v))).r, expected)
                << u << ", " << v;
            ++compared;
        }
    }
    EXPECT_GT(compared, 900);
    EXPECT_LT(near_edge, 20);

    const auto sheared =
        write_file("checker-sheared.xml", scene_xml(R"(<shape type="rectangle"><bsdf type="diffuse">
    <texture type="checkerboard" name="reflectance">
        <transform name="to_uv">
            <matrix value="1 0.5 0 0  0 1 0 0  0 0 1 0  0 0 0 1"/>
        </transform>
    </texture>
</bsdf></shape>)"));
    try {
        load_scene(sheared.string());
        ADD_FAILURE() << "a sheared to_uv loaded";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("checker-sheared.xml:4: to_uv with shear"),
                  std::string::npos)
            << e.what();
    }
}

// A textured mask over a textured BSDF (tests/data/mitsuba/masked_textured.xml): the material
// graph's alpha reads the 8×8 opacity bitmap (an opaque disc, a clear texel at (5, 2)) while the
// base colour reads the 4×4 reflectance bitmap, each at its own resolution; checked at the centre
// of every opacity texel against the two bitmaps' patterns as written into the files (the
// reflectance sRGB-decoded, Mitsuba's default for colours).
TEST(MitsubaMask, TexturedOpacityBesideATexturedReflectance) {
    const Scene s = load_scene(std::string(MVPL_TEST_DATA_DIR) + "/mitsuba/masked_textured.xml");
    const Material& m = s.materials.at(size_t(s.meshes.at(0).material));
    ASSERT_TRUE(m.base_color_texture.valid());
    ASSERT_TRUE(m.opacity_texture.valid());
    EXPECT_EQ(m.alpha_mode, AlphaMode::Blend);
    const material::MaterialGraph g = material::graph_from_gltf(m);
    ASSERT_GE(g.alpha.node, 0);
    const int colours[4][3] = {{230, 60, 40}, {40, 180, 70}, {50, 80, 220}, {235, 200, 40}};
    for (int y = 0; y < 8; ++y) {
        for (int x = 0; x < 8; ++x) {
            material::SurfacePoint p;
            p.uv0 = Vec2((float(x) + 0.5f) / 8.0f, (float(y) + 0.5f) / 8.0f);
            const bool opaque =
                (x - 3.5f) * (x - 3.5f) + (y - 3.5f) * (y - 3.5f) < 10.0f && !(x == 5 && y == 2);
            EXPECT_EQ(material::evaluate_input(g, g.alpha, s.textures, p).x, opaque ? 1.0f : 0.0f)
                << x << ", " << y;
            const int* c = colours[(x / 2 + 2 * (y / 2)) % 4];
            const Vec4 base = s.textures.at(size_t(m.base_color_texture.texture))
                                  .sample(m.base_color_texture.transform(p.uv0));
            EXPECT_NEAR(base.r, srgb_to_linear(float(c[0]) / 255.0f), 1e-5f) << x << ", " << y;
            EXPECT_NEAR(base.b, srgb_to_linear(float(c[2]) / 255.0f), 1e-5f) << x << ", " << y;
        }
    }
}

}  // namespace
}  // namespace mvpl::scene
