// `mvpl info`: the Vulkan devices mvpl can use and the limits that size its passes (cube-map
// array layers for shadow batches, work groups, timestamps, memory), so that a user can pick
// `--device N` and a bug report can say what the machine is.
#include <cstdio>
#include <string>
#include <vector>

#include "engine/core/error.h"
#include "engine/gpu/device_info.h"
#include "engine/gpu/gpu_error.h"
#include "engine/gpu/validation.h"
#include "tools/cli/arg_parser.h"
#include "tools/cli/commands.h"
#include "tools/cli/option_groups.h"

namespace mvpl::cli {
namespace {

std::string format_bytes(uint64_t bytes) {
    char text[32];
    if (bytes >= (uint64_t(1) << 30)) {
        std::snprintf(text, sizeof(text), "%.2f GiB", double(bytes) / double(uint64_t(1) << 30));
    } else {
        std::snprintf(text, sizeof(text), "%.0f MiB", double(bytes) / double(1 << 20));
    }
    return text;
}

void print_device(const gpu::DeviceInfo& d, bool is_default) {
    const gpu::DeviceLimits& l = d.limits;
    std::printf("[%d] %s%s\n", d.index, d.name.c_str(), is_default ? "  (default)" : "");
    if (!d.usable()) std::printf("    not usable: %s\n", d.unusable_reason().c_str());
    std::printf("    type                 %s (vendor 0x%04x, device 0x%04x)\n",
                gpu::device_type_name(d.type), d.vendor_id, d.device_id);
    std::string driver = d.driver_name.empty() ? std::string("?") : d.driver_name;
    if (!d.driver_info.empty()) driver += ", " + d.driver_info;
    std::printf("    driver               %s (version %s)\n", driver.c_str(),
                d.driver_version_string.c_str());
    std::printf("    Vulkan API           %s\n", gpu::format_api_version(d.api_version).c_str());
    std::printf("    image 2D / cube      %u / %u px\n", l.max_image_dimension_2d,
                l.max_image_dimension_cube);
    std::printf("    image array layers   %u (%u cubes per cube-map array)\n",
                l.max_image_array_layers, l.max_image_array_layers / 6);
    std::printf("    cube-map arrays      %s\n", d.image_cube_array ? "yes" : "no");
    std::printf("    framebuffer          %u x %u x %u layers\n", l.max_framebuffer_width,
                l.max_framebuffer_height, l.max_framebuffer_layers);
    std::printf("    compute work group   %u invocations, size %u x %u x %u, count %u x %u x %u\n",
                l.max_compute_work_group_invocations, l.max_compute_work_group_size[0],
                l.max_compute_work_group_size[1], l.max_compute_work_group_size[2],
                l.max_compute_work_group_count[0], l.max_compute_work_group_count[1],
                l.max_compute_work_group_count[2]);
    std::printf("    push constants       %u bytes\n", l.max_push_constants_size);
    std::printf("    storage buffer range %s\n", format_bytes(l.max_storage_buffer_range).c_str());
    std::printf("    timestamps           %g ns per tick, %u valid bits%s\n", l.timestamp_period,
                d.timestamp_valid_bits,
                l.timestamp_compute_and_graphics ? "" : " (not on all graphics/compute queues)");
    for (size_t i = 0; i < d.heaps.size(); ++i) {
        std::printf("    memory heap %zu        %s%s\n", i, format_bytes(d.heaps[i].size).c_str(),
                    d.heaps[i].device_local ? ", device-local" : "");
    }
}

}  // namespace

int run_info(const Args& args) {
    int device = -1;
    ArgParser parser("info",
                     "Lists the Vulkan devices (the index is what --device takes) and the limits "
                     "that matter to mvpl.");
    add_device_option(parser, device, "show only this device");
    if (!parser.parse(args)) return 0;
    if (device < -1) throw UsageError("info: --device must not be negative");

    std::vector<gpu::DeviceInfo> devices;
    uint32_t loader = 0;
    try {
        loader = gpu::loader_api_version();
        devices = gpu::enumerate_devices();
    } catch (const gpu::GpuError& e) {
        std::fprintf(stderr, "mvpl: error: %s\n", e.what());
        return 1;
    }
    if (device >= int(devices.size())) {
        throw UsageError("info: no device " + std::to_string(device) + " (there are " +
                         std::to_string(devices.size()) + ")");
    }
    const int default_index = gpu::default_device_index(devices);
    std::printf("Vulkan loader %s, %zu device%s\n", gpu::format_api_version(loader).c_str(),
                devices.size(), devices.size() == 1 ? "" : "s");
    for (const gpu::DeviceInfo& d : devices) {
        if (device >= 0 && d.index != device) continue;
        std::printf("\n");
        print_device(d, d.index == default_index);
    }
    if (default_index < 0) std::printf("\nno device is usable by mvpl (Vulkan 1.3 needed)\n");
    std::printf("\nvalidation layer %s: %s (MVPL_VALIDATION=1 turns it on)\n",
                gpu::kValidationLayerName,
                gpu::validation_layer_available() ? "installed" : "not installed");
    return 0;
}

}  // namespace mvpl::cli
