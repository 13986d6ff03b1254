#include "engine/render/render_memory.h"

#include <algorithm>
#include <cstdio>

#include "engine/core/host_memory.h"
#include "engine/render/g_buffer_pass.h"
#include "engine/render/shadow_texel.h"
#include "shaders/shared/chain_record.h"

namespace mvpl::render {

namespace {

constexpr uint64_t kRgba32f = 16;
constexpr uint64_t kD32f = 4;

}  // namespace

MemoryEstimate estimate_memory(const RenderOptions& o) {
    const uint64_t pixels = uint64_t(o.width) * o.height;
    const uint64_t texels = uint64_t(o.shadow_resolution) * o.shadow_resolution;
    // The passes' images (g_buffer_pass.cpp, shadow_pass.cpp, shading_pass.cpp): the G-buffer
    // layers and their depth, the accumulation and the emission sum (emission_sum.cpp), one cube
    // of six faces per VPL of a batch with one depth cube, and the directional maps (at least two
    // layers) with one depth face.
    const uint64_t g_buffer = pixels * kRgba32f * kGBufferLayerCount;
    const uint64_t cubes = texels * kShadowTexelBytes * 6 * o.batch;
    const uint64_t ortho = texels * kShadowTexelBytes * std::max(o.batch, 2u);
    MemoryEstimate e;
    e.device_bytes = g_buffer + pixels * kD32f + 2 * pixels * kRgba32f + cubes +
                     texels * kD32f * 6 + ortho + texels * kD32f;
    e.largest_image = std::max({g_buffer, cubes, ortho});
    // The accumulation and the emission sum read back as RGBA32F, then the linear RGB image.
    e.host_bytes = pixels * (2 * kRgba32f + 12);
    if (o.chains.enabled()) {
        // Specular chains (chain_layer.h), counted whenever asked for (the scene decides whether
        // they are built): a host-visible ChainRecord per pixel and the host's emission sum.
        const uint64_t records = pixels * sizeof(shared::ChainRecord);
        e.device_bytes += records;
        e.largest_image = std::max(e.largest_image, records);
        e.host_bytes += pixels * 12;
    }
    return e;
}

std::string memory_shortfall(const RenderOptions& o, const gpu::DeviceInfo& device,
                             uint64_t host_bytes, uint32_t devices) {
    MemoryEstimate e = estimate_memory(o);
    e.device_bytes *= devices;
    e.host_bytes *= devices;
    uint64_t heap = 0;
    for (const gpu::MemoryHeapInfo& h : device.heaps) {
        if (h.device_local) heap = std::max(heap, h.size);
    }
    char what[160];
    std::snprintf(what, sizeof what, "a %ux%u image with %u² shadow faces and %u VPLs a batch%s",
                  o.width, o.height, o.shadow_resolution, o.batch,
                  devices > 1 ? (" on " + std::to_string(devices) + " devices").c_str() : "");
    uint64_t max_allocation = device.limits.max_memory_allocation_size;
    if (device.type == gpu::DeviceType::cpu) {
        // A CPU device's memory is the host's: lavapipe reports a 2 GiB heap and allocation limit
        // but serves what the host has (4096² images, 2.8 GB in all, render there), so only the
        // host's memory bounds it.
        heap = 0;
        max_allocation = 0;
        e.host_bytes += e.device_bytes;
    }
    if (heap > 0 && e.device_bytes > heap) {
        return std::string(what) + " needs about " + gigabytes(e.device_bytes) +
               " of GPU memory; " + device.name + " has " + gigabytes(heap);
    }
    if (max_allocation > 0 && e.largest_image > max_allocation) {
        return std::string(what) + " needs one image of " + gigabytes(e.largest_image) + "; " +
               device.name + " allocates at most " + gigabytes(max_allocation) + " at once";
    }
    return host_memory_shortfall(what, e.host_bytes, host_bytes);
}

uint64_t kept_maps_budget(uint64_t requested, const gpu::DeviceInfo& device, uint64_t host_bytes) {
    uint64_t available = host_bytes;  // a CPU device's memory is the host's (above)
    if (device.type != gpu::DeviceType::cpu) {
        available = 0;
        for (const gpu::MemoryHeapInfo& h : device.heaps) {
            if (h.device_local) available = std::max(available, h.size);
        }
    }
    if (available == 0) return requested;  // unknown
    return std::min(requested, available / kKeptMapsShare);
}

}  // namespace mvpl::render
