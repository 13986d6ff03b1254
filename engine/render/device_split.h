#pragma once
// One image rendered on several Vulkan devices (VplRenderer's `devices`): which VPLs each device
// shades, how their timings add up, and running the devices at once. Each accumulate() call's
// batches are cut into one contiguous run per device, of nearly equal length, so that every
// call keeps every device busy (a 0.5 s chunk of a --time-budget render on a heavy scene holds a
// few batches, fewer than the positions a split by position would need). Each VPL keeps its index
// since begin(), which decides its sub-pixel position and, where interleaved, its pixels; a
// device draws the G-buffer of each position it shades (one more than one device would at each
// run's start), and the interleaving filter, being linear, may run on each device's share of a
// position: the devices' images sum to the one-device image. The emission seen directly is added
// by the device that shades a position's first VPL (vpl_renderer_impl.cpp). Vulkan-free.
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "engine/gpu/device_info.h"
#include "engine/light/vpl.h"
#include "engine/render/vpl_renderer.h"

namespace mvpl::render {

// The most devices one renderer drives (each holds a copy of every pass's images).
inline constexpr uint32_t kMaxRenderDevices = 8;

// The devices a renderer runs on where the user does not say: 2 on a CPU implementation
// (lavapipe), where one device's shadow geometry runs beside the other's rasterisation and shading
// (docs/results.md, "Two devices"), and 1 on a GPU, which overlaps its own work.
uint32_t default_render_devices(const gpu::DeviceInfo& device);

struct DeviceShare {
    std::vector<light::Vpl> vpls;
    std::vector<uint64_t> index;  // each VPL's index since begin()
};

// `vpls` are VPLs first … first + size − 1 since begin() when `index` is empty, else VPL i has
// index[i] (increasing). The batches they fall in (index / batch) are dealt out as `devices`
// contiguous runs of nearly equal length, in order; a device may get none.
std::vector<DeviceShare> split_into_runs(std::span<const light::Vpl> vpls,
                                         std::span<const uint64_t> index, uint64_t first,
                                         uint64_t batch, uint32_t devices);

// With kept shadow maps (RenderOptions::kept_shadow_bytes) a VPL shaded again after a restart
// (the preview's replay) must fall on the device that kept its map, whatever the calls' lengths:
// deal_batches() deals batch k (index / batch) to device k mod n instead (the same arguments;
// the renderer passes a sub-pixel position's VPLs as `batch`, so that one device draws each
// position's G-buffer).
std::vector<DeviceShare> deal_batches(std::span<const light::Vpl> vpls,
                                      std::span<const uint64_t> index, uint64_t first,
                                      uint64_t batch, uint32_t devices);

// sum += t, every count and GPU time (wall_ms too: the caller sets the group's own).
void add_timings(RenderTimings& sum, const RenderTimings& t);

// work(0) on the calling thread and work(d) for d = 1 … devices − 1 on threads of their own, all
// at once; returns when all are done, rethrowing the first error (by device).
void run_on_devices(uint32_t devices, const std::function<void(uint32_t)>& work);

}  // namespace mvpl::render
