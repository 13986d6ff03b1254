// Mitsuba 0.6's `vpl` integrator (issue 34): maxDepth, shadowMapResolution and clamping are
// read without a warning, Mitsuba's defaults where the file leaves them out (5, 512, 0.1), and
// values mvpl cannot render are refused with the property's line.
#include <gtest/gtest.h>

#include <string>

#include "engine/core/error.h"
#include "engine/scene/scene_loader.h"
#include "tests/scene/mitsuba_xml.h"

namespace mvpl::scene {
namespace {

Scene load_with(const std::string& name, const std::string& integrator) {
    const std::string body =
        "<integrator type=\"vpl\">" + integrator + "</integrator>\n<shape type=\"rectangle\"/>";
    return load_scene(testing::write_file(name, testing::scene_xml(body, "0.6.0")).string());
}

TEST(MitsubaVplIntegrator, ItsParametersBecomeTheScenesDefaults) {
    const Scene s = load_with("vpl.xml", R"(<integer name="maxDepth" value="6"/>
        <integer name="shadowMapResolution" value="128"/>
        <float name="clamping" value="0.25"/>)");
    EXPECT_EQ(s.max_depth, 6);
    EXPECT_EQ(s.shadow_resolution, 128);
    EXPECT_EQ(s.vpl_clamping, 0.25f);
    EXPECT_TRUE(s.warnings.empty()) << s.warnings.front();
}

TEST(MitsubaVplIntegrator, MitsubasDefaultsWhereTheFileSaysNothing) {
    const Scene s = load_with("vpl-defaults.xml", "");
    EXPECT_EQ(s.max_depth, 5);
    EXPECT_EQ(s.shadow_resolution, 512);
    EXPECT_EQ(s.vpl_clamping, 0.1f);
    EXPECT_TRUE(s.warnings.empty()) << s.warnings.front();
}

TEST(MitsubaVplIntegrator, OtherIntegratorsLeaveTheRenderersDefaults) {
    const Scene s = load_scene(
        testing::write_file("path.xml", testing::scene_xml("<integrator type=\"path\"/>\n"
                                                           "<shape type=\"rectangle\"/>"))
            .string());
    EXPECT_EQ(s.shadow_resolution, 0);
    EXPECT_LT(s.vpl_clamping, 0.0f);
}

TEST(MitsubaVplIntegrator, ValuesOutOfRangeAreRefusedWithTheirLine) {
    const struct {
        const char* property;
        const char* message;
    } cases[] = {
        {R"(<integer name="shadowMapResolution" value="2"/>)", "shadowMapResolution 2"},
        {R"(<float name="clamping" value="1.5"/>)", "clamping must be in [0, 1]"},
        {R"(<integer name="maxDepth" value="0"/>)", "maxDepth 0 is not a depth"},
    };
    for (const auto& c : cases) {
        try {
            load_with("vpl-bad.xml", c.property);
            ADD_FAILURE() << c.property << " was accepted";
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find(c.message), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find("vpl-bad.xml:2:"), std::string::npos) << e.what();
        }
    }
}

}  // namespace
}  // namespace mvpl::scene
