// Every scene of ../shared/mitsuba-scenes/docs/scenes (beside a checkout in this workplace;
// skipped without them) either loads and renders a finite image with the path tracer, or is
// refused with one line `mvpl: error: FILE:LINE: …` and exit code 2 for the reason the README's
// table gives (issue 16); nothing crashes or hangs (a minute each at most, far beyond the
// fraction of a second they take).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "tests/cli/run_command.h"

namespace mvpl {
namespace {

namespace fs = std::filesystem;
using test::run_mvpl;
using test::shell_quote;

const fs::path kScenes = fs::path(MVPL_SOURCE_DIR) / ".." / "shared" / "mitsuba-scenes";

// The scenes mvpl refuses and what the message must say (README.md, "Mitsuba scenes").
const std::map<std::string, std::string> kRefused = {
    {"bsdf_hair_blonde", "shape type 'bsplinecurve' is not supported"},
    {"bsdf_hair_brown", "shape type 'bsplinecurve' is not supported"},
    {"bsdf_measured_polarized_fakegold", "bsdf type 'measured_polarized' is not supported"},
    {"bsdf_measured_polarized_fakegold_stokes", "bsdf type 'measured_polarized' is not supported"},
    {"bsdf_measured_polarized_gold", "bsdf type 'measured_polarized' is not supported"},
    {"bsdf_measured_polarized_gold_stokes", "bsdf type 'measured_polarized' is not supported"},
    {"bsdf_polarizer_absorbing", "bsdf type 'polarizer' is not supported"},
    {"bsdf_polarizer_aligned", "bsdf type 'polarizer' is not supported"},
    {"bsdf_polarizer_middle", "bsdf type 'polarizer' is not supported"},
    {"bsdf_pplastic", "bsdf type 'pplastic' is not supported"},
    {"bsdf_pplastic_diffuse", "bsdf type 'pplastic' is not supported"},
    {"bsdf_pplastic_diffuse_stokes", "bsdf type 'pplastic' is not supported"},
    {"bsdf_pplastic_specular", "bsdf type 'pplastic' is not supported"},
    {"bsdf_pplastic_specular_stokes", "bsdf type 'pplastic' is not supported"},
    {"emitter_projector_constant", "emitter type 'projector' is not supported"},
    {"emitter_projector_textured", "emitter type 'projector' is not supported"},
    {"emitter_spot_texture", "a spot light with a texture is not supported"},
    {"medium_homogeneous_sss", "participating media"},
    {"medium_homogeneous_sss_textured", "participating media"},
    {"sensor_orthographic", "sensor type 'orthographic' is not supported"},
    {"sensor_orthographic_2", "sensor type 'orthographic' is not supported"},
    {"shape_bsplinecurve_basic", "shape type 'bsplinecurve' is not supported"},
    {"shape_bsplinecurve_parameterization", "shape type 'bsplinecurve' is not supported"},
    {"shape_linearcurve_basic", "shape type 'linearcurve' is not supported"},
    {"shape_linearcurve_parameterization", "shape type 'linearcurve' is not supported"},
    {"shape_sdfgrid", "shape type 'sdfgrid' is not supported"},
    {"shape_sdfgrid_analytic", "shape type 'sdfgrid' is not supported"},
    {"texture_mesh_attribute_face", "texture type 'mesh_attribute' is not supported"},
    {"texture_mesh_attribute_vertex", "texture type 'mesh_attribute' is not supported"},
};

TEST(MitsubaScenes, EveryDocumentationSceneLoadsOrIsRefusedInOneLine) {
    std::vector<fs::path> files;
    std::error_code ec;
    for (const fs::directory_entry& e : fs::directory_iterator(kScenes / "docs" / "scenes", ec)) {
        if (e.path().extension() == ".xml") files.push_back(e.path());
    }
    if (files.empty()) GTEST_SKIP() << "../shared/mitsuba-scenes is absent";
    std::sort(files.begin(), files.end());
    const fs::path out = fs::temp_directory_path() / "mvpl_mitsuba_scenes.exr";
    int loaded = 0;
    for (const fs::path& file : files) {
        const std::string name = file.stem().string();
        SCOPED_TRACE(name);
        const auto r = run_mvpl("reference " + shell_quote(file.string()) + " -a " +
                                shell_quote((kScenes / "common").string()) +
                                " --spp 1 --res 32x24 --quiet -o " + shell_quote(out.string()));
        const auto refused = kRefused.find(name);
        if (refused == kRefused.end()) {
            EXPECT_EQ(r.exit_code, 0) << r.err;  // writing the EXR refuses NaN and infinity
            loaded += r.exit_code == 0;
        } else {
            test::expect_one_line_error(r, file.string() + ":");
            EXPECT_NE(r.err.find(refused->second), std::string::npos) << r.err;
        }
    }
    EXPECT_GE(loaded, 67);
}

}  // namespace
}  // namespace mvpl
