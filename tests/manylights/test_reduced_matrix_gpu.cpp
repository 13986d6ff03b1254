// The reduced matrix on the GPU (engine/render/matrix_pass.h) against the CPU oracle's
// (engine/manylights/reduced_matrix.h), entry by entry: each row is evaluated on its own, so
// that a column's GPU norm is the entry's magnitude and its sketch the entry's three channels in
// their buckets. Where the GPU and the oracle agree on visibility, the entries agree to float
// rounding (the same contribution code: vpl_contribution.glsl against light::vpl_contribution);
// they disagree on visibility only near the occluders' silhouettes seen from the row, which the
// row's cube resolves to its texels.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ostream>
#include <string>
#include <vector>

#include "engine/light/light_sampler.h"
#include "engine/light/vpl_contribution.h"
#include "engine/manylights/reduced_matrix.h"
#include "engine/manylights/row_set.h"
#include "engine/render/chain_layer.h"
#include "engine/render/vpl_renderer.h"
#include "engine/sampler/monte_carlo_stream.h"
#include "engine/scene/scene_loader.h"
#include "engine/trace/accel.h"
#include "tests/gpu/gpu_test.h"
#include "tests/manylights/unbiased_draws.h"
#include "tests/support/mirror_box.h"

namespace mvpl {
namespace {

struct MatrixScene {
    std::string name;
    std::string path;     // empty: tests/support/mirror_box.h
    bool sky = false;     // a constant environment: directional VPLs
    bool chains = false;  // glossy rows continued to their chains' rough ends (max depth 5)
};
void PrintTo(const MatrixScene& s, std::ostream* os) {
    *os << s.name;
}

class ReducedMatrixGpu : public gpu::testing::GpuTest,
                         public ::testing::WithParamInterface<MatrixScene> {};

constexpr uint32_t kResolution = 64;  // the rows' cubes
constexpr uint32_t kDims = 16;

// Counts of one scene's comparison.
struct Agreement {
    size_t lit = 0;          // pairs the oracle lights before visibility
    size_t occluded = 0;     // of those, occluded for the oracle
    size_t disagree = 0;     // of those, visibility differs between the GPU and the oracle
    double worst_value = 0;  // largest relative difference where both see the pair
    size_t dark_lit = 0;     // pairs black for the oracle before visibility, lit on the GPU
    size_t directional = 0;  // pairs of directional VPLs that both see
};

// Compares row `row`'s GPU entries (`out`: MatrixPass::evaluate's, one row) with the oracle's.
void compare_row(const manylights::MatrixContext& mc, const std::vector<light::Vpl>& pool,
                 const std::vector<uint32_t>& hash, const std::vector<float>& out, Agreement& a) {
    const manylights::Row& row = mc.rows[0];
    std::vector<float> entry(3);
    for (size_t j = 0; j < pool.size(); ++j) {
        const float gpu_norm = std::sqrt(out[j * (1 + kDims)]);
        Rgb u(0.0f);
        if (pool[j].path_length <= row.max_vpl_length) {
            trace::Ray ray;
            u = row.throughput *
                light::unshadowed_contribution(row.receiver, light::prepare_vpl(pool[j]), mc.d_min2,
                                               mc.vsl_r2, mc.accel->coordinate_scale(), ray);
        }
        const float u_norm = std::sqrt(u.r * u.r + u.g * u.g + u.b * u.b);
        if (u_norm == 0.0f) {
            a.dark_lit += gpu_norm > 0.0f ? 1 : 0;
            continue;
        }
        manylights::reduced_column(mc, pool[j], entry);
        const bool cpu_sees = entry[0] != 0.0f || entry[1] != 0.0f || entry[2] != 0.0f;
        const bool gpu_sees = gpu_norm > 0.5f * u_norm;
        ++a.lit;
        a.occluded += cpu_sees ? 0 : 1;
        a.disagree += cpu_sees != gpu_sees ? 1 : 0;
        if (!gpu_sees) continue;
        a.directional += cpu_sees && pool[j].type == light::VplType::Directional ? 1 : 0;
        a.worst_value = std::max(a.worst_value, double(std::abs(gpu_norm - u_norm) / u_norm));
        // The sketch: each channel, signed, in its bucket.
        float sketch[kDims] = {};
        const float channels[3] = {u.r, u.g, u.b};
        for (int c = 0; c < 3; ++c) {
            const uint32_t h = hash[size_t(c)];
            sketch[h & manylights::kSketchBucket] +=
                (h & manylights::kSketchNegative) ? -channels[c] : channels[c];
        }
        for (uint32_t k = 0; k < kDims; ++k)
            a.worst_value = std::max(
                a.worst_value, double(std::abs(out[j * (1 + kDims) + 1 + k] - sketch[k]) / u_norm));
    }
}

TEST_P(ReducedMatrixGpu, EntriesAreTheOraclesUpToTheRowCubes) {
    scene::Scene scene = GetParam().path.empty()
                             ? test::make_mirror_box()
                             : scene::load_scene(MVPL_ASSETS_DIR "/" + GetParam().path);
    if (GetParam().sky) scene.environment.radiance = Rgb(1.0f);
    const trace::Accel accel(scene);
    const light::LightSampler lights(scene);
    const std::vector<light::Vpl> pool =
        manylights_test::stream_pool(scene, accel, lights, 1024, 3);
    light::ChainOptions chains;
    if (GetParam().chains) {
        chains.max_roughness = light::kDefaultChainRoughness;
        chains.max_depth = 5;
    }
    const std::vector<manylights::Row> rows =
        manylights::make_rows(scene, accel, scene.camera, {32, 32, 64, chains}, 5, 0);
    ASSERT_GT(rows.size(), 12u);
    if (GetParam().chains) {
        // A row seen directly receives VPLs of paths up to 5 − 2 segments; one a bounce on, fewer.
        const auto chained = std::count_if(rows.begin(), rows.end(),
                                           [](const auto& r) { return r.max_vpl_length < 3u; });
        std::printf("%td rows at a chain's end\n", chained);
        EXPECT_GT(chained, 0) << "no row at a chain's end";
    }

    render::VplRenderer renderer(context(), scene, &accel);
    render::RenderOptions ro;
    ro.width = ro.height = 32;
    renderer.begin(scene.camera, ro);
    const float d_min = ro.clamp * scene.bounds().diagonal();
    const float radius = ro.vsl_radius * scene.bounds().diagonal();
    Agreement a;
    std::vector<float> out;
    for (size_t r = 0; r < rows.size(); ++r) {
        const manylights::MatrixContext mc{&accel, std::span(rows).subspan(r, 1), d_min * d_min,
                                           radius * radius};
        const std::vector<uint32_t> hash = manylights::sketch_hash(3, kDims, 11 + r);
        const shared::ChainRecord record =
            render::receiver_record(rows[r].receiver, rows[r].throughput, rows[r].max_vpl_length);
        renderer.reduced_matrix(std::span(&record, 1), pool, hash, kDims, kResolution, out);
        ASSERT_EQ(out.size(), pool.size() * (1 + kDims));
        compare_row(mc, pool, hash, out, a);
    }
    const double disagree = double(a.disagree) / double(std::max<size_t>(a.lit, 1));
    std::printf(
        "%s: %zu rows × %zu columns, %zu pairs lit unshadowed, %zu occluded, visibility "
        "differs in %.4f of them; %zu directional pairs seen; largest relative difference where "
        "both see %.3g\n",
        GetParam().name.c_str(), rows.size(), pool.size(), a.lit, a.occluded, disagree,
        a.directional, a.worst_value);
    EXPECT_GT(a.occluded, a.lit / 50) << "too few occluded pairs to test the visibility";
    if (GetParam().sky) {
        EXPECT_GT(a.directional, 0u) << "no directional VPL seen";
    }
    EXPECT_EQ(a.dark_lit, 0u) << "the GPU lights pairs the oracle's contribution leaves black";
    // Float rounding in a few hundred operations, and GLSL's pow/exp against the CPU's.
    EXPECT_LT(a.worst_value, 1e-3);
    // Visibility differs within about two texels of a silhouette seen from the row (the texel
    // that holds the direction, and the biases of a footprint or so): a band of angular width
    // 2 · 2τ (τ = 2 / kResolution) along silhouettes whose length on the unit sphere is at
    // most 2π for each of the few occluders in view, over the hemisphere's 2π: at most 4τ a
    // silhouette, 0.125 for one. Seen through a wrong direction or distance, visibility would
    // differ in a share like the occluded one.
    EXPECT_LT(disagree, 4.0 * 2.0 / kResolution);
}

INSTANTIATE_TEST_SUITE_P(Scenes, ReducedMatrixGpu,
                         ::testing::Values(MatrixScene{"Cornell", "cornell-box/cbox.gltf"},
                                           MatrixScene{"TwoRooms", "two-room/two-room.gltf"},
                                           MatrixScene{"GlossyUnderSky", "glossy/glossy.gltf",
                                                       true},
                                           MatrixScene{"MirrorBox", "", false, true}),
                         [](const auto& info) { return info.param.name; });

}  // namespace
}  // namespace mvpl
