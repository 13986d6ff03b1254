#pragma once
// The `mvpl` subcommands, listed once: main dispatches through this table and prints it as the
// usage, and `mvpl completion` reads each command's options from it.
#include <string>
#include <vector>

#include "tools/cli/commands.h"

namespace mvpl::cli {

struct Command {
    std::string name;
    std::string arguments;  // for the usage, e.g. "SCENE"
    std::string summary;
    int (*run)(const Args& args);
    // Whether the ranks under mpirun share its work (the others run as one process only).
    bool over_ranks = false;
};

const std::vector<Command>& command_table();
// The command named `name`, or null.
const Command* find_command(const std::string& name);
// "usage: mvpl COMMAND [options]", the commands with their summaries, and where to read more.
std::string usage_text();

}  // namespace mvpl::cli
