#pragma once
// Which Vulkan device a command's rank uses (`--device`): checked before the scene is loaded, and
// `--device local-rank` under mpirun (engine/cluster) so that ranks on one machine spread over its
// GPUs.
#include <string>

#include "tools/cli/commands.h"

namespace mvpl::cli {

// `--device local-rank` replaced by the device of index OMPI_COMM_WORLD_LOCAL_RANK (this rank's
// place among the ranks on its machine; 0 without mpirun), modulo the devices there, so that
// ranks share the machine's GPUs round-robin when there are fewer.
Args with_local_rank_device(Args args);

// Throws UsageError naming `command` unless --device `device` names a device (-1: the default).
void check_device(const std::string& command, int device);

}  // namespace mvpl::cli
