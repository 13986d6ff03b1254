#include "tools/cli/device_choice.h"

#include <algorithm>
#include <cstdlib>

#include "engine/core/error.h"
#include "engine/gpu/device_info.h"

namespace mvpl::cli {

Args with_local_rank_device(Args args) {
    for (size_t i = 0; i + 1 < args.size(); ++i) {
        if (args[i] != "--device" || args[i + 1] != "local-rank") continue;
        const char* local = std::getenv("OMPI_COMM_WORLD_LOCAL_RANK");
        const size_t count = std::max<size_t>(gpu::enumerate_devices().size(), 1);
        args[i + 1] = std::to_string(size_t(local ? std::atoi(local) : 0) % count);
    }
    return args;
}

void check_device(const std::string& command, int device) {
    if (device < 0) return;
    const size_t count = gpu::enumerate_devices().size();
    if (size_t(device) >= count) {
        throw UsageError(command + ": --device " + std::to_string(device) +
                         ": no such Vulkan device (there are " + std::to_string(count) +
                         "; see mvpl info)");
    }
}

}  // namespace mvpl::cli
