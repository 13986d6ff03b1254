// How a renderer on several devices shares out its VPLs and runs the devices
// (engine/render/device_split.h), without a device.
#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <thread>
#include <vector>

#include "engine/render/device_split.h"

namespace mvpl::render {
namespace {

std::vector<light::Vpl> numbered(size_t n) {
    std::vector<light::Vpl> vpls(n);
    for (size_t i = 0; i < n; ++i)
        vpls[i].power = Rgb(float(i));
    return vpls;
}

// Called for VPLs 3 … 42 since begin(), 8 a position: VPL k on device (k / 8) mod n, with its
// index, in order, and every VPL on exactly one device.
TEST(SplitByPosition, PositionsTakeTurnsAcrossTheDevices) {
    const std::vector<light::Vpl> vpls = numbered(40);
    const SubpixelSchedule schedule{true, 8, Vec2(0.0f)};
    for (const uint32_t devices : {1u, 2u, 3u}) {
        const std::vector<DeviceShare> shares = split_by_position(vpls, {}, 3, schedule, devices);
        ASSERT_EQ(shares.size(), devices);
        size_t total = 0;
        for (uint32_t d = 0; d < devices; ++d) {
            const DeviceShare& s = shares[d];
            ASSERT_EQ(s.vpls.size(), s.index.size());
            total += s.vpls.size();
            for (size_t i = 0; i < s.vpls.size(); ++i) {
                EXPECT_EQ(uint64_t(s.vpls[i].power.r) + 3, s.index[i]);
                EXPECT_EQ((s.index[i] / 8) % devices, d);
                if (i > 0) {
                    EXPECT_LT(s.index[i - 1], s.index[i]);
                }
            }
        }
        EXPECT_EQ(total, vpls.size());
    }
    // Without jitter the blocks still alternate (each device then draws the one G-buffer).
    const std::vector<DeviceShare> flat =
        split_by_position(vpls, {}, 0, SubpixelSchedule{false, 8, Vec2(0.0f)}, 2);
    EXPECT_EQ(flat[0].vpls.size(), 24u);
    EXPECT_EQ(flat[1].vpls.size(), 16u);
}

// A rank's share names its VPLs' indices: they, not the order, decide the device.
TEST(SplitByPosition, GivenIndicesDecideTheDevice) {
    const std::vector<light::Vpl> vpls = numbered(5);
    const std::vector<uint64_t> index{0, 7, 8, 23, 40};
    const std::vector<DeviceShare> shares =
        split_by_position(vpls, index, 1000, SubpixelSchedule{true, 8, Vec2(0.0f)}, 2);
    // Positions 0, 0, 1, 2, 5.
    EXPECT_EQ(shares[0].index, (std::vector<uint64_t>{0, 7, 23}));
    EXPECT_EQ(shares[1].index, (std::vector<uint64_t>{8, 40}));
    EXPECT_EQ(shares[1].vpls[1].power.r, 4.0f);
}

// Every device's work runs, device 0's on the caller's thread, and an error of one device comes
// back after all have finished.
TEST(RunOnDevices, RunsEveryDeviceAndRethrows) {
    std::atomic<int> ran{0};
    std::vector<bool> on_caller(3, false);
    const std::thread::id caller = std::this_thread::get_id();
    run_on_devices(3, [&](uint32_t d) {
        on_caller[d] = std::this_thread::get_id() == caller;
        ++ran;
    });
    EXPECT_EQ(ran.load(), 3);
    EXPECT_EQ(on_caller, (std::vector<bool>{true, false, false}));
    ran = 0;
    EXPECT_THROW(run_on_devices(3,
                                [&](uint32_t d) {
                                    ++ran;
                                    if (d == 1) throw std::runtime_error("device 1");
                                }),
                 std::runtime_error);
    EXPECT_EQ(ran.load(), 3);
}

TEST(AddTimings, SumsEveryCount) {
    RenderTimings a, b;
    a.shadow_ms = 2.0;
    a.g_buffers = 3;
    a.shadow_triangles = 10;
    b.shadow_ms = 5.0;
    b.g_buffers = 4;
    b.shadow_triangles = 7;
    b.chain_rays = 9;
    add_timings(a, b);
    EXPECT_DOUBLE_EQ(a.shadow_ms, 7.0);
    EXPECT_EQ(a.g_buffers, 7u);
    EXPECT_EQ(a.shadow_triangles, 17u);
    EXPECT_EQ(a.chain_rays, 9u);
}

}  // namespace
}  // namespace mvpl::render
