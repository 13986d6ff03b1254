#include "engine/render/device_split.h"

#include <algorithm>
#include <exception>
#include <thread>

#include "engine/gpu/gpu_error.h"

namespace mvpl::render {

namespace {

// The shares of `vpls` when batch j of the call (j = 0 … batches − 1) goes to device
// device_of(j, batches).
template <class DeviceOf>
std::vector<DeviceShare> share_batches(std::span<const light::Vpl> vpls,
                                       std::span<const uint64_t> index, uint64_t first,
                                       uint64_t batch, uint32_t devices, DeviceOf device_of) {
    std::vector<DeviceShare> shares(std::max<uint32_t>(devices, 1));
    if (vpls.empty()) return shares;
    const uint64_t b = std::max<uint64_t>(batch, 1);
    auto index_of = [&](size_t i) { return index.empty() ? first + i : index[i]; };
    if (!index.empty() && !std::is_sorted(index.begin(), index.end()))
        throw gpu::GpuError("VplRenderer::accumulate: the VPLs' indices must increase");
    const uint64_t first_batch = index_of(0) / b;
    const uint64_t batches = index_of(vpls.size() - 1) / b - first_batch + 1;
    for (size_t i = 0; i < vpls.size(); ++i) {
        const uint64_t k = index_of(i);
        DeviceShare& share = shares[size_t(device_of(k / b, first_batch, batches, shares.size()))];
        share.vpls.push_back(vpls[i]);
        share.index.push_back(k);
    }
    return shares;
}

}  // namespace

uint32_t default_render_devices(const gpu::DeviceInfo& device) {
    return device.type == gpu::DeviceType::cpu ? 2u : 1u;
}

std::vector<DeviceShare> split_into_runs(std::span<const light::Vpl> vpls,
                                         std::span<const uint64_t> index, uint64_t first,
                                         uint64_t batch, uint32_t devices) {
    // Batch j of the call goes to device ⌊j·n / batches⌋: runs in order, lengths within one.
    return share_batches(vpls, index, first, batch, devices,
                         [](uint64_t k, uint64_t first_batch, uint64_t batches, size_t n) {
                             return (k - first_batch) * n / batches;
                         });
}

std::vector<DeviceShare> deal_batches(std::span<const light::Vpl> vpls,
                                      std::span<const uint64_t> index, uint64_t first,
                                      uint64_t batch, uint32_t devices) {
    return share_batches(vpls, index, first, batch, devices,
                         [](uint64_t k, uint64_t, uint64_t, size_t n) { return k % n; });
}

// Every field of RenderTimings is summed below: a new one must be added there too.
static_assert(sizeof(RenderTimings) == 15 * 8, "add_timings: sum the new field of RenderTimings");

void add_timings(RenderTimings& sum, const RenderTimings& t) {
    sum.g_buffer_ms += t.g_buffer_ms;
    sum.shadow_ms += t.shadow_ms;
    sum.shading_ms += t.shading_ms;
    sum.total_ms += t.total_ms;
    sum.wall_ms += t.wall_ms;
    sum.batches += t.batches;
    sum.shadow_triangles += t.shadow_triangles;
    sum.shadow_front_only_triangles += t.shadow_front_only_triangles;
    sum.g_buffer_front_only_triangles += t.g_buffer_front_only_triangles;
    sum.shadow_texels += t.shadow_texels;
    sum.culled_vpls += t.culled_vpls;
    sum.g_buffers += t.g_buffers;
    sum.chain_ms += t.chain_ms;
    sum.chain_rays += t.chain_rays;
    sum.kept_maps += t.kept_maps;
}

void run_on_devices(uint32_t devices, const std::function<void(uint32_t)>& work) {
    std::vector<std::exception_ptr> errors(std::max<uint32_t>(devices, 1));
    std::vector<std::thread> threads;
    try {
        for (uint32_t d = 1; d < devices; ++d) {
            threads.emplace_back([&, d] {
                try {
                    work(d);
                } catch (...) {
                    errors[d] = std::current_exception();
                }
            });
        }
        work(0);
    } catch (...) {
        // Device 0's error, or no thread for a device: the started ones still finish first.
        errors[0] = std::current_exception();
    }
    for (std::thread& t : threads)
        t.join();
    for (const std::exception_ptr& e : errors) {
        if (e) std::rethrow_exception(e);
    }
}

}  // namespace mvpl::render
