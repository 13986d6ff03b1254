#include "tools/cli/command_table.h"

#include <cstdio>

namespace mvpl::cli {

const std::vector<Command>& command_table() {
    static const std::vector<Command> table = {
        {"render", "SCENE", "render with virtual point lights on the GPU", run_render, true},
        {"reference", "SCENE", "render with the CPU reference path tracer", run_reference},
        {"compare", "A B", "error of image A against reference B", run_compare},
        {"info", "", "Vulkan devices and their limits", run_info},
        {"preview", "SCENE", "interactive window, refining while the camera rests", run_preview},
        {"vpls", "SCENE", "where a sampler puts its VPLs, drawn over the scene", run_vpls},
        {"bench", "SCENE", "VPL throughput: light paths, shadow and shading passes, memory",
         run_bench, true},
        {"convergence", "SCENE", "error against run time: path tracer and VPL samplers vs --ref",
         run_convergence, true},
        {"completion", "bash", "shell completion script, generated from the options",
         run_completion},
    };
    return table;
}

const Command* find_command(const std::string& name) {
    for (const Command& c : command_table())
        if (c.name == name) return &c;
    return nullptr;
}

std::string usage_text() {
    std::string text = "usage: mvpl COMMAND [options]\n\ncommands:\n";
    for (const Command& c : command_table()) {
        const std::string call = c.arguments.empty() ? c.name : c.name + " " + c.arguments;
        char line[160];
        // Two spaces at least before the summary, which help2man reads as a tagged paragraph.
        std::snprintf(line, sizeof line, "  %-17s  %s\n", call.c_str(), c.summary.c_str());
        text += line;
    }
    return text + "\n`mvpl COMMAND --help` describes a command's options.\n";
}

}  // namespace mvpl::cli
