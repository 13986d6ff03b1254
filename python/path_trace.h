#pragma once
// mvpl.reference: the command line's reference options (tools/cli/reference_args.h) parsed from
// the keywords, the engine's path tracer run with the GIL released.
#include <string>
#include <vector>

#include "engine/core/image.h"
#include "python/scene_handle.h"

namespace mvpl::python {

// The image `mvpl reference SCENE TOKENS…` would write. Throws UsageError or InputError with the
// command line's message for bad options.
Image path_trace(const SceneHandle& scene, const std::vector<std::string>& tokens);

}  // namespace mvpl::python
