#pragma once
// mvpl.render: the command line's render options (tools/cli/render_args.h) parsed from the
// keywords, the engine's VPL integrator (engine/integrator/vpl_integrator.h) advanced chunk by
// chunk as `mvpl render` advances it (tools/cli/render_chunks.h), so that the same options and
// seed give the same image; the GIL released while a chunk renders.
#include <functional>
#include <string>
#include <vector>

#include "engine/core/exr_file.h"
#include "engine/core/image.h"
#include "python/scene_handle.h"

namespace mvpl::python {

// Called between chunks with the share done (0..1) and the GIL held; it may throw (an error
// already set in Python: KeyboardInterrupt, or the callback's own) to end the render.
using ChunkHook = std::function<void(double done)>;

// What a render gives: the image, and the AOVs `--aov` asked for (engine/aov), in its order.
struct RenderResult {
    Image image;
    std::vector<ChannelImage> aovs;
};

// The image `mvpl render SCENE TOKENS…` would write, and the AOVs its EXR would hold. Throws
// UsageError or InputError with the command line's message for bad options.
RenderResult render_vpls(const SceneHandle& scene, const std::vector<std::string>& tokens,
                         const ChunkHook& between_chunks);

}  // namespace mvpl::python
