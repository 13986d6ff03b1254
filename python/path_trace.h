#pragma once
// mvpl.reference: the command line's reference options (tools/cli/reference_args.h) parsed from
// the keywords, the engine's path tracer run chunk by chunk
// (engine/reference/progressive_trace.h) with the GIL released, so that Ctrl-C and the progress
// callback act between chunks; the image is `mvpl reference`'s whatever the chunks.
#include <string>
#include <vector>

#include "python/scene_handle.h"
#include "python/vpl_render.h"

namespace mvpl::python {

// The image `mvpl reference SCENE TOKENS…` would write, and the AOVs `--aov` asks for.
// `between_chunks` is called before each chunk and once at the end with the share done. Throws
// UsageError or InputError with the command line's message for bad options.
RenderResult path_trace(const SceneHandle& scene, const std::vector<std::string>& tokens,
                        const ChunkHook& between_chunks);

}  // namespace mvpl::python
