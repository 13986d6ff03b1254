// The renderer's memory estimate and the up-front refusal (issue 19, item 3), against devices
// described by hand: a discrete GPU's heap bounds it, a CPU device's reported heap does not
// (lavapipe reports 2 GiB and renders 4096² images of 2.8 GB), the host's memory bounds both.
#include <gtest/gtest.h>

#include "engine/render/render_memory.h"

namespace mvpl::render {
namespace {

gpu::DeviceInfo device(gpu::DeviceType type, uint64_t heap) {
    gpu::DeviceInfo d;
    d.name = "test device";
    d.type = type;
    d.heaps.push_back({heap, true});
    d.limits.max_memory_allocation_size = heap;
    return d;
}

RenderOptions options(uint32_t side) {
    RenderOptions o;
    o.width = o.height = side;
    return o;
}

constexpr uint64_t kGiB = uint64_t(1) << 30;

TEST(RenderMemory, EstimateCountsTheGBufferAndTheShadowCubes) {
    const MemoryEstimate e = estimate_memory(options(4096));
    // 4096² × 8 RGBA32F G-buffer layers alone are 2 GiB; 256² × 6 × 32 RG32F cubes 101 MB.
    EXPECT_GE(e.device_bytes, 2 * kGiB + uint64_t(256) * 256 * 6 * 32 * 8);
    EXPECT_EQ(e.largest_image, 2 * kGiB);
    EXPECT_GE(e.host_bytes, uint64_t(4096) * 4096 * 12);
}

TEST(RenderMemory, ADiscreteHeapRefusesACpuDeviceDefersToTheHost) {
    const RenderOptions big = options(4096);
    const std::string refused =
        memory_shortfall(big, device(gpu::DeviceType::discrete_gpu, 2 * kGiB), 64 * kGiB);
    EXPECT_NE(refused.find("a 4096x4096 image with 256² shadow faces and 32 VPLs a batch needs "
                           "about"),
              std::string::npos)
        << refused;
    EXPECT_NE(refused.find("GPU memory; test device has 2.1 GB"), std::string::npos) << refused;
    EXPECT_EQ(memory_shortfall(big, device(gpu::DeviceType::cpu, 2 * kGiB), 64 * kGiB), "");
    const std::string host =
        memory_shortfall(big, device(gpu::DeviceType::cpu, 2 * kGiB), 2 * kGiB);
    EXPECT_NE(host.find("of host memory; this machine has 2.1 GB"), std::string::npos) << host;
    EXPECT_EQ(
        memory_shortfall(options(256), device(gpu::DeviceType::discrete_gpu, 2 * kGiB), 64 * kGiB),
        "");
}

// Logical devices on one physical device (VplRenderer's `devices`) each hold every image: what
// fits once may not fit twice.
TEST(RenderMemory, DevicesMultiplyTheEstimate) {
    const RenderOptions big = options(4096);
    const uint64_t once = estimate_memory(big).device_bytes + estimate_memory(big).host_bytes;
    const gpu::DeviceInfo cpu = device(gpu::DeviceType::cpu, 2 * kGiB);
    EXPECT_EQ(memory_shortfall(big, cpu, once + kGiB, 1), "");
    const std::string twice = memory_shortfall(big, cpu, once + kGiB, 2);
    EXPECT_NE(twice.find("32 VPLs a batch on 2 devices needs about"), std::string::npos) << twice;
}

// Kept shadow maps are a cache (kept_shadow_maps.h): their budget is what was asked, at most a
// quarter of the device's heap (of the host's memory on a CPU device), and never refuses the
// render; an unknown host size leaves the request.
TEST(RenderMemory, KeptMapsTakeAtMostAQuarterOfTheMemoryAndRefuseNothing) {
    const gpu::DeviceInfo gpu8 = device(gpu::DeviceType::discrete_gpu, 8 * kGiB);
    const gpu::DeviceInfo cpu = device(gpu::DeviceType::cpu, 2 * kGiB);
    EXPECT_EQ(kept_maps_budget(kGiB, gpu8, 64 * kGiB), kGiB);
    EXPECT_EQ(kept_maps_budget(4 * kGiB, gpu8, 64 * kGiB), 2 * kGiB);
    EXPECT_EQ(kept_maps_budget(kGiB, cpu, 2 * kGiB), kGiB / 2);
    EXPECT_EQ(kept_maps_budget(kGiB, cpu, 0), kGiB);
    RenderOptions o = options(512);
    const uint64_t needed = estimate_memory(o).device_bytes + estimate_memory(o).host_bytes;
    o.kept_shadow_bytes = 64 * kGiB;
    EXPECT_EQ(memory_shortfall(o, cpu, needed + kGiB, 1), "");
}

}  // namespace
}  // namespace mvpl::render
