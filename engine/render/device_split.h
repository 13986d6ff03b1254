#pragma once
// One image rendered on several Vulkan devices (VplRenderer's `devices`): which VPLs each device
// shades, how their timings add up, and running the devices at once. Sub-pixel position p goes
// to device p mod n, so a position's G-buffer, its batches and its interleaving filter stay on
// one device; each VPL keeps its index since begin(), which decides its position and, where
// interleaved, its pixels, so that the devices' images sum to the one-device image.
// Vulkan-free.
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "engine/core/subpixel.h"
#include "engine/light/vpl.h"
#include "engine/render/vpl_renderer.h"

namespace mvpl::render {

// The most devices one renderer drives (each holds a copy of every pass's images).
inline constexpr uint32_t kMaxRenderDevices = 8;

struct DeviceShare {
    std::vector<light::Vpl> vpls;
    std::vector<uint64_t> index;  // each VPL's index since begin()
};

// `vpls` are VPLs first … first + size − 1 since begin() when `index` is empty, else VPL i has
// index[i] (increasing). Positions are counted in blocks of schedule.vpls_per_position also
// without jitter (one G-buffer then, drawn by every device, the same one).
std::vector<DeviceShare> split_by_position(std::span<const light::Vpl> vpls,
                                           std::span<const uint64_t> index, uint64_t first,
                                           const SubpixelSchedule& schedule, uint32_t devices);

// sum += t, every count and GPU time (wall_ms too: the caller sets the group's own).
void add_timings(RenderTimings& sum, const RenderTimings& t);

// work(0) on the calling thread and work(d) for d = 1 … devices − 1 on threads of their own, all
// at once; returns when all are done, rethrowing the first error (by device).
void run_on_devices(uint32_t devices, const std::function<void(uint32_t)>& work);

}  // namespace mvpl::render
