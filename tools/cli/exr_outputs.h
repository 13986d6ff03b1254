#pragma once
// What `render` and `reference` write into their EXRs besides the image (README, "AOVs" and
// "EXR attributes"): the AOV channels (engine/aov) and the run's header attributes.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "engine/aov/aov_kind.h"
#include "engine/core/exr_file.h"
#include "engine/scene/scene.h"
#include "tools/cli/arg_parser.h"
#include "tools/cli/commands.h"

namespace mvpl::cli {

// --aov LIST; its check refuses an unknown or repeated name, and AOVs without an .exr among
// `outputs` (read when the check runs, after parsing; none given: the default .exr).
void add_aov_option(ArgParser& parser, std::string* list, const std::vector<std::string>* outputs);
// --aov's AOVs, or, where it was not given, those the scene file asks for (Mitsuba's aov
// integrator); none where no output is an EXR.
std::vector<aov::AovRequest> aov_requests(const ArgParser& parser, const std::string& list,
                                          const scene::Scene& scene,
                                          const std::vector<std::string>& outputs);

// The facts of a run that its EXRs record.
struct RunFacts {
    std::string command;  // "render", "reference"
    const Args* args = nullptr;
    uint64_t seed = 0;
    std::optional<uint64_t> vpls;  // render
    std::optional<int> spp;        // reference
    double wall_seconds = 0.0;     // from the command's start to the write
};
// mvpl/version, mvpl/commandLine (shell-quoted), mvpl/seed and mvpl/vpls (decimal text: 64-bit
// values), mvpl/spp (int), mvpl/wallSeconds (double).
std::vector<ExrAttribute> run_attributes(const RunFacts& facts);
// "mvpl COMMAND ARGS…", each argument quoted for a POSIX shell where it needs it.
std::string command_line(const std::string& command, const Args& args);

}  // namespace mvpl::cli
