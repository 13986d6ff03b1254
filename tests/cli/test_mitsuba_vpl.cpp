// A Mitsuba 0.6 scene with <integrator type="vpl"> (issue 34): `mvpl render` takes its maxDepth,
// shadowMapResolution and clamping (mapped by sampler::mitsuba_clamp) as its defaults without a
// warning — the same image to the bit as the command line that gives those values — and the
// clamp it maps to changes the image (a render with the default clamp differs).
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "engine/core/image.h"
#include "engine/light/light_sampler.h"
#include "engine/sampler/mitsuba_clamping.h"
#include "engine/scene/scene_loader.h"
#include "engine/trace/accel.h"
#include "tests/cli/run_command.h"

namespace mvpl {
namespace {

namespace fs = std::filesystem;
using test::shell_quote;

// A point light inside a closed box seen from inside: surface VPLs light the walls near them,
// where the clamp acts.
constexpr const char* kScene = R"(<scene version="0.6.0">
  <integrator type="vpl">
    <integer name="maxDepth" value="3"/>
    <integer name="shadowMapResolution" value="64"/>
    <float name="clamping" value="0.3"/>
  </integrator>
  <sensor type="perspective">
    <float name="fov" value="90"/>
    <transform name="toWorld"><lookat origin="0, 0, 0.8" target="0, -0.5, -1" up="0, 1, 0"/></transform>
    <film type="hdrfilm"><integer name="width" value="16"/><integer name="height" value="16"/></film>
  </sensor>
  <emitter type="point"><point name="position" x="0.3" y="0.6" z="-0.2"/>
    <spectrum name="intensity" value="2"/></emitter>
  <shape type="cube"><boolean name="flipNormals" value="true"/></shape>
</scene>
)";

Image render(const fs::path& scene, const fs::path& out, const std::string& options) {
    const test::CommandResult r =
        test::run_mvpl_gpu("render " + shell_quote(scene.string()) + " --vpls 16 --quiet " +
                           options + " -o " + shell_quote(out.string()));
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.err, "");  // no warning about the integrator
    return read_exr(out.string());
}

double max_difference(const Image& a, const Image& b) {
    double d = 0.0;
    for (size_t i = 0; i < a.pixels().size(); ++i) {
        const Rgb e = a.pixels()[i] - b.pixels()[i];
        d = std::max({d, double(std::abs(e.r)), double(std::abs(e.g)), double(std::abs(e.b))});
    }
    return d;
}

TEST(MitsubaVpl, TheIntegratorsParametersAreTheRendersDefaults) {
    const fs::path dir = fs::temp_directory_path() / ("mvpl_vpl06_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const fs::path scene_path = dir / "vpl.xml";
    std::ofstream(scene_path) << kScene;
    const scene::Scene scene = scene::load_scene(scene_path.string());
    const trace::Accel accel(scene);
    const light::LightSampler lights(scene);
    const float clamp = sampler::mitsuba_clamp(scene, accel, lights, 0.3f, 3);
    char given[128];
    std::snprintf(given, sizeof given, "--max-depth 3 --shadow-res 64 --clamp %.9g", double(clamp));

    const Image from_file = render(scene_path, dir / "file.exr", "");
    const Image from_options = render(scene_path, dir / "options.exr", given);
    const Image default_clamp =
        render(scene_path, dir / "default.exr", "--max-depth 3 --shadow-res 64 --clamp 0.05");
    ASSERT_EQ(from_file.pixels().size(), 16u * 16u);
    EXPECT_EQ(max_difference(from_file, from_options), 0.0) << given;
    EXPECT_GT(max_difference(from_file, default_clamp), 0.0) << "clamp " << clamp;
    fs::remove_all(dir);
}

}  // namespace
}  // namespace mvpl
