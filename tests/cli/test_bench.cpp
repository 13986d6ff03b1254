// `mvpl bench`: on the Cornell box at a tiny size its JSON is valid, every measured number is
// positive, and the derived rates agree with the counts and times they come from; bad flags are
// usage errors (exit 2, one line).
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>

#include "tests/cli/run_command.h"

namespace mvpl {
namespace {

using nlohmann::json;
using test::run_mvpl;
using test::shell_quote;

const std::string kCbox = MVPL_ASSETS_DIR "/cornell-box/cbox.gltf";

// The numbers are written with 17 significant digits, and each derived rate is one division of
// two written numbers: recomputing it here differs by a few ulps at most. 1e-12 relative leaves
// three orders of magnitude of room and still catches any real inconsistency (a wrong count,
// a rate from another time).
constexpr double kRelative = 1e-12;

void expect_rel(double actual, double expected, const char* what) {
    EXPECT_NEAR(actual, expected, kRelative * std::abs(expected)) << what;
}

// Every number anywhere in the document is finite and positive (counts, times, rates, bytes),
// but for the count of culled VPLs, the specular chains' time, rays and roughness bound and the
// share of triangles drawn front faces only (the Cornell box has no solid), which are ≥ 0; the rest
// are strings (scene, device) and flags.
void expect_positive_numbers(const json& j, const std::string& where) {
    if (j.is_object()) {
        for (const auto& [key, value] : j.items()) {
            // Counts that are 0 where a lever is off, and the chains' bound.
            if (key == "culled_vpls" || key == "chain_ms" || key == "chain_rays" ||
                key == "chain_roughness" || key == "shadow_front_only_share") {
                EXPECT_GE(value.get<double>(), 0.0) << where;
                continue;
            }
            expect_positive_numbers(value, where + "." + key);
        }
    } else if (j.is_array()) {
        for (size_t i = 0; i < j.size(); ++i)
            expect_positive_numbers(j[i], where + "[" + std::to_string(i) + "]");
    } else if (j.is_number()) {
        EXPECT_GT(j.get<double>(), 0.0) << where;
    } else if (!j.is_string() && !j.is_boolean()) {
        ADD_FAILURE() << where << " is neither a number nor a string: " << j.dump();
    }
}

// One render configuration's numbers against each other and the light-path counts.
void expect_consistent_render(const json& r, const json& paths, const std::string& where) {
    SCOPED_TRACE(where);
    const double vpls = paths["vpls"].get<double>();
    const double pixels = r["width"].get<double>() * r["height"].get<double>();
    EXPECT_EQ(
        r["batches"].get<int64_t>(),
        (paths["vpls"].get<int64_t>() + r["batch"].get<int64_t>() - 1) / r["batch"].get<int64_t>());
    // A G-buffer per sub-pixel position: batch × batches_per_position VPLs each.
    const int64_t per_position =
        r["batch"].get<int64_t>() * r["batches_per_position"].get<int64_t>();
    // Over several devices each device draws the G-buffers of the positions its run of batches
    // touches: a run's first position may be drawn by the device before it too
    // (render::split_into_runs; the bench shades its VPLs in one call).
    const int64_t positions = (paths["vpls"].get<int64_t>() + per_position - 1) / per_position;
    const int64_t devices = r["devices"].get<int64_t>();
    const int64_t batches = r["batches"].get<int64_t>();
    const int64_t g_buffers = r["g_buffers"].get<int64_t>();
    if (r["jitter"].get<bool>()) {
        EXPECT_GE(g_buffers, positions);
        EXPECT_LE(g_buffers, positions + std::min(devices, batches) - 1);
    } else {
        EXPECT_EQ(g_buffers, std::min(devices, batches));
    }
    expect_rel(r["shadow_ms_per_vpl"], r["shadow_ms"].get<double>() / vpls, "shadow ms/VPL");
    expect_rel(r["shading_ms_per_vpl"], r["shading_ms"].get<double>() / vpls, "shading ms/VPL");
    expect_rel(r["shading_pixel_vpls_per_s"],
               pixels * vpls / (r["shading_ms"].get<double>() * 1e-3), "pixel·VPL/s");
    expect_rel(r["end_to_end_s"], paths["seconds"].get<double>() + r["render_wall_s"].get<double>(),
               "end to end s");
    expect_rel(r["end_to_end_vpls_per_s"], vpls / r["end_to_end_s"].get<double>(), "VPL/s");
    // GPU pass times are part of the host's wall time of the render (each batch is waited for),
    // on each device: summed over the devices that ran at once, of devices × the wall time.
    EXPECT_LE((r["g_buffer_ms"].get<double>() + r["shadow_ms"].get<double>() +
               r["shading_ms"].get<double>()) *
                  1e-3,
              r["render_wall_s"].get<double>() * r["devices"].get<double>());
}

// `mvpl bench SCENE FLAGS --json FILE` on the GPU: the command's result and the JSON file's text
// (empty if it wrote none); `tag` keeps the files of tests running side by side apart.
struct BenchRun {
    test::CommandResult result;
    std::string text;
};

BenchRun run_bench(const std::string& scene, const std::string& flags, const std::string& tag) {
    const std::string json_path =
        (std::filesystem::temp_directory_path() /
         ("mvpl_bench_" + tag + "_" + std::to_string(::getpid()) + ".json"))
            .string();
    BenchRun run;
    run.result = test::run_mvpl_gpu("bench " + shell_quote(scene) + " " + flags + " --json " +
                                    shell_quote(json_path));
    std::ifstream in(json_path);
    std::stringstream text;
    text << in.rdbuf();
    run.text = text.str();
    std::filesystem::remove(json_path);
    return run;
}

// One tiny run with --sweep, checked by the three functions below in one test (each test is a
// process of its own under ctest: three tests would run it three times): 32², 16² shadow faces,
// 16 light paths.
BenchRun run_sweep() {
    return run_bench(kCbox, "--res 32x24 --shadow-res 16 --batch 8 --vpls 16 --repeat 1 --sweep",
                     "sweep");
}

void expect_valid_json_with_positive_numbers(const BenchRun& run) {
    json j;
    ASSERT_NO_THROW(j = json::parse(run.text)) << run.text;
    expect_positive_numbers(j, "bench");
    EXPECT_EQ(j["scene"], kCbox);
    EXPECT_EQ(j["repeat"], 1);
    EXPECT_EQ(j["shadows"], true);
    EXPECT_EQ(j["light_paths"]["paths"], 16);
    EXPECT_EQ(j["render"]["width"], 32);
    EXPECT_EQ(j["render"]["height"], 24);
    EXPECT_EQ(j["render"]["shadow_resolution"], 16);
    EXPECT_EQ(j["render"]["batch"], 8);
    // The scene's default for the Cornell box's 38 triangles: a position every 2 batches.
    EXPECT_EQ(j["render"]["batches_per_position"], 2);
}

void expect_rates_agree_with_counts_and_times(const BenchRun& run) {
    const json j = json::parse(run.text);
    const json& paths = j["light_paths"];
    // Each path leaves at least its emitter VPL.
    EXPECT_GE(paths["vpls"].get<int64_t>(), paths["paths"].get<int64_t>());
    expect_rel(paths["paths_per_s"], paths["paths"].get<double>() / paths["seconds"].get<double>(),
               "paths/s");
    expect_rel(paths["vpls_per_s"], paths["vpls"].get<double>() / paths["seconds"].get<double>(),
               "VPLs/s");
    const json& s = j["startup"];
    expect_rel(s["total_s"],
               s["scene_load_s"].get<double>() + s["bvh_build_s"].get<double>() +
                   s["context_s"].get<double>() + s["renderer_s"].get<double>(),
               "start-up total");
    expect_consistent_render(j["render"], paths, "render");
    for (size_t i = 0; i < j["sweep"].size(); ++i)
        expect_consistent_render(j["sweep"][i], paths, "sweep " + std::to_string(i));
    // The device holds at least the RGBA32F accumulation image: 16 bytes a pixel.
    EXPECT_GE(j["memory"]["peak_device_bytes"].get<double>(), 32.0 * 24.0 * 16.0);
}

void expect_sweep_covers_batches_and_shadow_resolutions(const BenchRun& run) {
    const json j = json::parse(run.text);
    // 5 batch sizes × 3 shadow resolutions, each pair once, then the main configuration with
    // each lever switched: shadow culling, the shadow proxy, hemicubes, VPL culling, interleave,
    // specular chains, levels of detail, back-face culling of solids, the other device count.
    ASSERT_EQ(j["sweep"].size(), 24u);
    std::set<std::pair<int, int>> pairs;
    for (size_t i = 0; i < 15; ++i) {
        const json& r = j["sweep"][i];
        EXPECT_TRUE(r["shadow_culling"].get<bool>());
        pairs.insert({r["batch"].get<int>(), r["shadow_resolution"].get<int>()});
    }
    EXPECT_EQ(pairs.size(), 15u);
    const json& unculled = j["sweep"][15];
    EXPECT_FALSE(unculled["shadow_culling"].get<bool>());
    EXPECT_EQ(unculled["batch"], j["render"]["batch"]);
    // Culling only ever removes triangles from a face.
    EXPECT_LE(j["render"]["shadow_triangles_per_vpl"].get<double>(),
              unculled["shadow_triangles_per_vpl"].get<double>());
    EXPECT_GT(j["render"]["shadow_triangles_per_vpl"].get<double>(), 0.0);
    EXPECT_FALSE(j["sweep"][16]["shadow_proxy"].get<bool>());
    EXPECT_TRUE(j["sweep"][16]["shadow_culling"].get<bool>());
    EXPECT_FALSE(j["sweep"][17]["hemicube"].get<bool>());
    EXPECT_TRUE(j["render"]["hemicube"].get<bool>());
    EXPECT_FALSE(j["sweep"][18]["vpl_culling"].get<bool>());
    EXPECT_EQ(j["sweep"][18]["culled_vpls"].get<int>(), 0);
    EXPECT_EQ(j["render"]["interleave"].get<int>(), 2);  // the command line's default
    EXPECT_EQ(j["sweep"][19]["interleave"].get<int>(), 1);
    // Chains on by default and off when switched; the Cornell box has no glossy material, so
    // neither traces a chain ray (a diffuse scene pays nothing for them).
    EXPECT_TRUE(j["render"]["chains"].get<bool>());
    EXPECT_FALSE(j["sweep"][20]["chains"].get<bool>());
    EXPECT_EQ(j["render"]["chain_rays"].get<int64_t>(), 0);
    EXPECT_EQ(j["sweep"][20]["chain_rays"].get<int64_t>(), 0);
    // Levels of detail on by default and off when switched (the Cornell box's meshes are all
    // below the threshold: the same triangles either way).
    EXPECT_TRUE(j["render"]["shadow_lod"].get<bool>());
    EXPECT_FALSE(j["sweep"][21]["shadow_lod"].get<bool>());
    EXPECT_EQ(j["sweep"][21]["shadow_triangles_per_vpl"].get<double>(),
              j["render"]["shadow_triangles_per_vpl"].get<double>());
    EXPECT_TRUE(j["render"]["backface_culling"].get<bool>());
    EXPECT_FALSE(j["sweep"][22]["backface_culling"].get<bool>());
    // One device where the run had two (lavapipe) and two where it had one (a GPU): the same
    // VPLs and batches, on a renderer of its own.
    const json& other = j["sweep"][23];
    EXPECT_EQ(other["devices"].get<int>(), j["render"]["devices"].get<int>() == 1 ? 2 : 1);
    EXPECT_EQ(other["batches"], j["render"]["batches"]);
    // Hemicubes only ever remove texels from a face.
    EXPECT_LE(j["render"]["shadow_texels_per_vpl"].get<double>(),
              j["sweep"][17]["shadow_texels_per_vpl"].get<double>());
    EXPECT_NE(run.result.out.find("levers"), std::string::npos) << run.result.out;
    // The table for people: a header and one row per configuration.
    EXPECT_NE(run.result.out.find("end to end"), std::string::npos) << run.result.out;
    EXPECT_NE(run.result.out.find("batch  shadow"), std::string::npos) << run.result.out;
}

TEST(Bench, SweepWritesValidJsonWhoseRatesAndConfigurationsAgree) {
    const BenchRun run = run_sweep();
    ASSERT_EQ(run.result.exit_code, 0) << run.result.err;
    {
        SCOPED_TRACE("valid JSON, positive numbers");
        expect_valid_json_with_positive_numbers(run);
    }
    {
        SCOPED_TRACE("rates against counts and times");
        expect_rates_agree_with_counts_and_times(run);
    }
    {
        SCOPED_TRACE("the sweep's configurations");
        expect_sweep_covers_batches_and_shadow_resolutions(run);
    }
}

// --batches-per-position N: N batches share each G-buffer (expect_consistent_render counts them).
TEST(BenchPositions, BatchesShareAGBufferAsAsked) {
    const BenchRun run = run_bench(
        kCbox,
        "--res 32x24 --shadow-res 16 --batch 4 --vpls 16 --repeat 1 --batches-per-position 3"
        " --quiet",
        "positions");
    ASSERT_EQ(run.result.exit_code, 0) << run.result.err;
    const json j = json::parse(run.text);
    EXPECT_EQ(j["render"]["batches_per_position"], 3);
    // 16 paths leave more than 12 VPLs: at least two positions of 12.
    EXPECT_GE(j["render"]["g_buffers"].get<int>(), 2);
    expect_consistent_render(j["render"], j["light_paths"], "render");
}

// --pool (row-column sampling, engine/manylights): the main render shades each pool's
// representatives, reported beside the same VPLs shaded one by one; per VPL the rates count the
// representatives, and the effective rate the VPLs they stand for; the reduced matrix, asked on
// the GPU, is reported as the GPU's.
TEST(BenchRowColumn, ReportsRepresentativesBesideEveryVplShaded) {
    const BenchRun run = run_bench(kCbox,
                                   "--res 32x24 --shadow-res 16 --batch 8 --vpls 64 --repeat 1"
                                   " --pool 64 --rows 16 --clusters 8 --matrix gpu --quiet",
                                   "row_column");
    ASSERT_EQ(run.result.exit_code, 0) << run.result.err;
    const json j = json::parse(run.text);
    const json& main = j["render"];
    ASSERT_TRUE(main.contains("row_column")) << main.dump();
    EXPECT_EQ(main["row_column"]["matrix"], "gpu");
    const double vpls = j["light_paths"]["vpls"].get<double>();
    const double reps = main["row_column"]["representatives"].get<double>();
    // 64 paths leave more than 64 VPLs: at least two pools of at most 8 representatives each.
    EXPECT_GT(vpls, 64.0);
    EXPECT_GE(reps, 2.0);
    EXPECT_LE(reps, 8.0 * std::ceil(vpls / 64.0));
    const double seconds = main["end_to_end_s"].get<double>();
    expect_rel(main["end_to_end_vpls_per_s"], reps / seconds, "representatives/s");
    expect_rel(main["effective_vpls_per_s"], vpls / seconds, "effective VPL/s");
    ASSERT_EQ(j["sweep"].size(), 1u);
    EXPECT_FALSE(j["sweep"][0].contains("row_column"));
    expect_consistent_render(j["sweep"][0], j["light_paths"], "every VPL");
}

// A scene with near-mirror metals traces specular chains in bench as in render: one chain per
// pixel and sub-pixel position (32 × 24 pixels, 2 batches of 8 VPLs: 2 positions), each at
// least one ray; `--no-chains` traces none.
TEST(BenchChains, TheGlossySceneTracesChainsUnlessTurnedOff) {
    const std::string glossy = MVPL_ASSETS_DIR "/glossy/glossy.gltf";
    for (const bool off : {false, true}) {
        const BenchRun run = run_bench(
            glossy,
            std::string("--res 32x24 --shadow-res 16 --batch 8 --vpls 8 --repeat 1 --quiet") +
                (off ? " --no-chains" : ""),
            "chains");
        ASSERT_EQ(run.result.exit_code, 0) << run.result.err;
        const json j = json::parse(run.text);
        EXPECT_EQ(j["render"]["chains"].get<bool>(), !off);
        const int64_t rays = j["render"]["chain_rays"].get<int64_t>();
        const int64_t positions = j["render"]["g_buffers"].get<int64_t>();
        if (off) {
            EXPECT_EQ(rays, 0);
        } else {
            EXPECT_GE(rays, 32 * 24 * positions);
            EXPECT_GT(j["render"]["chain_ms"].get<double>(), 0.0);
        }
    }
}

TEST(BenchUsage, BadFlagsExitTwoWithOneLine) {
    const std::string cbox = shell_quote(kCbox);
    for (const std::string& args :
         {std::string("bench"), "bench " + cbox + " --batch 0", "bench " + cbox + " --batch 257",
          "bench " + cbox + " --shadow-res 2", "bench " + cbox + " --repeat 0",
          "bench " + cbox + " --vpls 0", "bench " + cbox + " --res 0x4",
          "bench " + cbox + " --bogus", "bench " + cbox + " --clamp -1",
          "bench " + cbox + " --batch abc", std::string("bench /nonexistent/scene.gltf --quiet"),
          "bench " + cbox +
              " --quiet --vpls 1 --res 8x8 --repeat 1 --json /nonexistent/d/x.json"}) {
        SCOPED_TRACE(args);
        const test::CommandResult r = run_mvpl(args);
        EXPECT_EQ(r.exit_code, 2) << r.err;
        EXPECT_EQ(r.err.rfind("mvpl: error: ", 0), 0u) << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    }
}

}  // namespace
}  // namespace mvpl
