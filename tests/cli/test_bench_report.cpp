// bench's JSON (tools/cli/bench_report.cpp, issue 34): it parses, and strings that need escaping
// (a scene path with quotes, a backslash, a control character and non-ASCII letters; a device
// name with bytes that are not UTF-8) come back as written; numbers round-trip and a non-finite
// one is null.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "tools/cli/bench_report.h"

namespace mvpl::cli {
namespace {

BenchReport report_with(const std::string& scene, const std::string& device) {
    BenchReport b;
    b.scene = scene;
    b.device = device;
    b.triangles = 38;
    b.paths = 16;
    b.vpls = 41;
    b.sampling_s = 0.1;
    b.main.config.chain_roughness = 0.25f;
    b.main.median.shadow_ms = 1.0 / 3.0;
    b.main.end_to_end_s = std::nan("");
    b.sweep.push_back(b.main);
    return b;
}

TEST(BenchReport, JsonParsesAndEscapesStrings) {
    const std::string scene = "/tmp/a \"quoted\" sc\u00e8ne \\ \u2713\t.gltf";
    const nlohmann::json j = nlohmann::json::parse(bench_json(report_with(scene, "lavapipe")));
    EXPECT_EQ(j["scene"], scene);
    EXPECT_EQ(j["device"], "lavapipe");
    EXPECT_EQ(j["triangles"], 38);
    EXPECT_EQ(j["light_paths"]["paths_per_s"].get<double>(), 16 / 0.1);
    EXPECT_EQ(j["render"]["shadow_ms"].get<double>(), 1.0 / 3.0);  // all 17 digits
    EXPECT_EQ(j["render"]["chain_roughness"].get<double>(), double(0.25f));
    EXPECT_TRUE(j["render"]["end_to_end_s"].is_null());
    ASSERT_EQ(j["sweep"].size(), 1u);
    EXPECT_EQ(j["sweep"][0]["shadow_ms"], j["render"]["shadow_ms"]);
}

TEST(BenchReport, BytesThatAreNotUtf8BecomeReplacementCharacters) {
    const nlohmann::json j =
        nlohmann::json::parse(bench_json(report_with("x\xff.gltf", "gpu\xc3")));
    EXPECT_EQ(j["scene"], "x\uFFFD.gltf");
    EXPECT_EQ(j["device"], "gpu\uFFFD");
}

}  // namespace
}  // namespace mvpl::cli
