#pragma once
// `mvpl reference`'s options, declared once for the command line (reference_command.cpp) and the
// Python module (python/), whose keywords are these options' names.
#include <string>
#include <vector>

#include "engine/reference/path_tracer.h"
#include "tools/cli/arg_parser.h"
#include "tools/cli/option_groups.h"

namespace mvpl::cli {

// Everything `mvpl reference` reads from its command line.
struct ReferenceArgs {
    std::string scene_path;
    reference::PathTracerOptions options;
    std::vector<std::string> outputs;
    std::string aov_list;  // --aov (exr_outputs.h)
    float exposure = 0.0f;
    float write_every = 0.0f;  // --write-every SEC (0: only at the end)
    int threads = 0;
    CameraArgs camera;
    EnvironmentArgs environment;
    SceneFileArgs scene_file;
};

// SCENE and the options, with their checks.
void add_reference_options(ArgParser& parser, ReferenceArgs& a);

// Throws UsageError when the path tracer's image of `options` cannot fit in host memory.
void check_host_memory(const reference::PathTracerOptions& options);

}  // namespace mvpl::cli
