// The reduced matrix (engine/manylights/reduced_matrix.h) traces a column's shadow rays together
// (Accel::occluded over a span). Against the one-ray path, light::vpl_contribution entry by
// entry, on scenes with occluders (the Cornell box's blocks; the two rooms' dividing wall): every
// entry and every column norm the same to the bit, with a share of the pairs occluded so that
// the comparison tests the visibility.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "engine/light/light_sampler.h"
#include "engine/light/vpl_contribution.h"
#include "engine/manylights/reduced_matrix.h"
#include "engine/manylights/row_set.h"
#include "engine/sampler/monte_carlo_stream.h"
#include "engine/scene/scene_loader.h"
#include "engine/trace/accel.h"
#include "tests/manylights/unbiased_draws.h"

namespace mvpl {
namespace {

class ReducedMatrix : public ::testing::TestWithParam<std::string> {};

TEST_P(ReducedMatrix, ColumnsTracedTogetherAreTheOneRayEntries) {
    const scene::Scene scene = scene::load_scene(MVPL_ASSETS_DIR "/" + GetParam());
    const trace::Accel accel(scene);
    const light::LightSampler lights(scene);
    const std::vector<light::Vpl> pool = manylights_test::stream_pool(scene, accel, lights, 384, 3);
    const std::vector<manylights::Row> rows =
        manylights::make_rows(scene, accel, scene.camera, {32, 32, 48, {}}, 5, 0);
    ASSERT_GT(rows.size(), 24u);
    const float d_min = 0.01f * scene.bounds().diagonal();
    const manylights::MatrixContext mc{&accel, rows, d_min * d_min, 0.0f};
    const manylights::ColumnSketches s = manylights::sketch_columns(mc, pool, 16, 7);
    std::vector<float> column(3 * rows.size());
    size_t lit = 0, occluded = 0;
    for (size_t j = 0; j < pool.size(); ++j) {
        manylights::reduced_column(mc, pool[j], column);
        const light::PreparedVpl pv = light::prepare_vpl(pool[j]);
        double norm2 = 0.0;
        for (size_t r = 0; r < rows.size(); ++r) {
            Rgb one(0.0f);
            if (pool[j].path_length <= rows[r].max_vpl_length) {
                one = rows[r].throughput *
                      light::vpl_contribution(accel, rows[r].receiver, pv, mc.d_min2, 0.0f);
                trace::Ray shadow;
                if (!is_black(light::unshadowed_contribution(rows[r].receiver, pv, mc.d_min2, 0.0f,
                                                             accel.coordinate_scale(), shadow))) {
                    ++lit;
                    occluded += is_black(one) ? 1 : 0;
                }
            }
            ASSERT_EQ(column[3 * r + 0], one.r) << "column " << j << ", row " << r;
            ASSERT_EQ(column[3 * r + 1], one.g) << "column " << j << ", row " << r;
            ASSERT_EQ(column[3 * r + 2], one.b) << "column " << j << ", row " << r;
            for (const float v : {one.r, one.g, one.b})  // in sketch_columns' order
                norm2 += double(v) * double(v);
        }
        ASSERT_EQ(s.norms[j], float(std::sqrt(norm2))) << "column " << j;
    }
    std::printf("%s: %zu rows × %zu columns, %zu pairs lit unshadowed, %zu of them occluded\n",
                GetParam().c_str(), rows.size(), pool.size(), lit, occluded);
    EXPECT_GT(occluded, lit / 50) << "too few occluded pairs to test the visibility";
    EXPECT_LT(occluded, lit) << "every pair occluded";
}

INSTANTIATE_TEST_SUITE_P(Scenes, ReducedMatrix,
                         ::testing::Values("cornell-box/cbox.gltf", "two-room/two-room.gltf"),
                         [](const auto& info) { return info.index == 0 ? "Cornell" : "TwoRooms"; });

}  // namespace
}  // namespace mvpl
