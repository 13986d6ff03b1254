// How a renderer on several devices shares out its VPLs and runs the devices
// (engine/render/device_split.h), without a device.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <span>
#include <stdexcept>
#include <thread>
#include <vector>

#include "engine/gpu/gpu_error.h"
#include "engine/render/device_split.h"

namespace mvpl::render {
namespace {

std::vector<light::Vpl> numbered(size_t n) {
    std::vector<light::Vpl> vpls(n);
    for (size_t i = 0; i < n; ++i)
        vpls[i].power = Rgb(float(i));
    return vpls;
}

// VPLs 3 … 42 since begin() in batches of 8 (batches 0 … 5 of the call: 3–7 is batch 0): each
// device gets a contiguous run of whole batches, in order, the runs' lengths within one batch of
// each other, every VPL on exactly one device with its index.
TEST(SplitIntoRuns, EachDeviceGetsAContiguousRunOfBatches) {
    const std::vector<light::Vpl> vpls = numbered(40);
    for (const uint32_t devices : {1u, 2u, 3u, 4u, 8u}) {
        SCOPED_TRACE(devices);
        const std::vector<DeviceShare> shares = split_into_runs(vpls, {}, 3, 8, devices);
        ASSERT_EQ(shares.size(), devices);
        size_t total = 0;
        uint64_t next = 3;
        size_t shortest = 99, longest = 0;
        for (const DeviceShare& s : shares) {
            ASSERT_EQ(s.vpls.size(), s.index.size());
            total += s.vpls.size();
            for (size_t i = 0; i < s.vpls.size(); ++i) {
                EXPECT_EQ(uint64_t(s.vpls[i].power.r) + 3, s.index[i]);
                EXPECT_EQ(s.index[i], next++);  // in order, no gaps: contiguous runs
            }
            if (!s.index.empty()) {
                // Runs start and end at batch boundaries (or the call's ends).
                EXPECT_TRUE(s.index.front() == 3 || s.index.front() % 8 == 0);
                EXPECT_TRUE(s.index.back() == 42 || s.index.back() % 8 == 7);
            }
            const size_t batches =
                s.index.empty() ? 0 : size_t(s.index.back() / 8 - s.index.front() / 8 + 1);
            shortest = std::min(shortest, batches);
            longest = std::max(longest, batches);
        }
        EXPECT_EQ(total, vpls.size());
        // Six batches: 6 / n each, within one (8 devices: six get one, two get none).
        EXPECT_LE(longest - shortest, 1u);
    }
}

// A rank's share names its VPLs' indices: they, not the order, decide the batches.
TEST(SplitIntoRuns, GivenIndicesDecideTheBatches) {
    const std::vector<light::Vpl> vpls = numbered(5);
    const std::vector<uint64_t> index{0, 7, 8, 23, 40};
    // Batches 0, 0, 1, 2, 5 of 0 … 5: the first half (0–2) and the second (3–5).
    const std::vector<DeviceShare> shares = split_into_runs(vpls, index, 1000, 8, 2);
    EXPECT_EQ(shares[0].index, (std::vector<uint64_t>{0, 7, 8, 23}));
    EXPECT_EQ(shares[1].index, (std::vector<uint64_t>{40}));
    EXPECT_EQ(shares[1].vpls[0].power.r, 4.0f);
    EXPECT_TRUE(split_into_runs({}, {}, 0, 8, 2)[1].vpls.empty());
    const std::vector<uint64_t> decreasing{9, 3, 4, 5, 6};
    EXPECT_THROW(split_into_runs(vpls, decreasing, 0, 8, 2), gpu::GpuError);
}

// With kept maps a VPL's device depends on its index alone: the same VPLs cut into calls of any
// lengths (a replay after a camera move) land on the same devices, batch k on device k mod n.
TEST(DealBatches, AVplFallsOnTheSameDeviceWhateverTheCalls) {
    const std::vector<light::Vpl> vpls = numbered(40);
    for (const uint32_t devices : {1u, 2u, 3u}) {
        SCOPED_TRACE(devices);
        std::vector<int> device_of(40, -1);
        for (const size_t call : {size_t(40), size_t(5), size_t(13)}) {
            for (size_t begin = 0; begin < vpls.size(); begin += call) {
                const size_t n = std::min(call, vpls.size() - begin);
                const std::vector<DeviceShare> shares =
                    deal_batches(std::span(vpls).subspan(begin, n), {}, begin, 8, devices);
                ASSERT_EQ(shares.size(), devices);
                for (uint32_t d = 0; d < devices; ++d) {
                    for (size_t i = 0; i < shares[d].index.size(); ++i) {
                        const uint64_t k = shares[d].index[i];
                        EXPECT_EQ(uint64_t(shares[d].vpls[i].power.r), k);
                        EXPECT_EQ(k / 8 % devices, d);
                        if (device_of[k] < 0) device_of[k] = int(d);
                        EXPECT_EQ(device_of[k], int(d));  // the same in every cut
                    }
                }
            }
        }
        EXPECT_EQ(std::count(device_of.begin(), device_of.end(), -1), 0);
    }
}

// Every device's work runs, device 0's on the caller's thread, and an error of one device comes
// back after all have finished.
TEST(RunOnDevices, RunsEveryDeviceAndRethrows) {
    std::atomic<int> ran{0};
    std::vector<char> on_caller(3, 0);  // not vector<bool>: its bits share a word
    const std::thread::id caller = std::this_thread::get_id();
    run_on_devices(3, [&](uint32_t d) {
        on_caller[d] = std::this_thread::get_id() == caller;
        ++ran;
    });
    EXPECT_EQ(ran.load(), 3);
    EXPECT_EQ(on_caller, (std::vector<char>{1, 0, 0}));
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
