// `mvpl preview`: the interactive window (tools/preview).
#include <algorithm>
#include <string>

#include "engine/core/error.h"
#include "sampler/sampler_factory.h"
#include "tools/cli/arg_parser.h"
#include "tools/cli/commands.h"
#include "tools/cli/output_check.h"
#include "tools/preview/preview_app.h"

namespace mvpl::cli {

int run_preview(const Args& args) {
    preview::PreviewOptions o;
    int width = o.width, height = o.height;
    float budget = float(o.budget_ms);
    int shadow_res = int(o.shadow_resolution), batch = int(o.batch);
    bool no_hud = false, no_motion_scaling = false;
    ArgParser parser(
        "preview",
        "Opens a window that renders SCENE progressively with virtual point lights: each frame\n"
        "shades as many VPL batches as fit --budget-ms (or --paths-per-frame light paths) and\n"
        "shows the running average; moving the camera restarts it.\n"
        "\n"
        "Controls: left drag orbit, middle or shift+left drag pan, wheel zoom, WASD (Q/E down/up)\n"
        "and right drag fly, R reset view, +/- exposure, M switch sampler (mc/metropolis),\n"
        "C clamping on/off, P screenshot (mvpl-preview-N.png and .exr), Esc quit.\n"
        "\n"
        "--script FILE drives the window without a user: one event a line, `#` comments,\n"
        "  FRAME orbit YAW PITCH     degrees        FRAME look YAW PITCH    degrees about the eye\n"
        "  FRAME pan RIGHT UP        view heights   FRAME zoom FACTOR       distance x FACTOR\n"
        "  FRAME fly FWD RIGHT UP    scene diagonals\n"
        "  FRAME resize W H          window size    FRAME key NAME          r plus minus m c p "
        "escape\n"
        "where FRAME is the index (from 0) of the frame at whose start the event happens.\n"
        "--frames N with --screenshot FILE renders N frames, writes the last (.png: the window's\n"
        "picture without the HUD; .exr: linear radiance) and exits.");
    parser.add_positional("SCENE", &o.scene_path, "glTF 2.0 scene (.gltf or .glb)");
    parser.add_string("--sampler", &o.sampler, "VPL sampler: mc (default) or metropolis");
    parser.add_resolution("--res", &width, &height, "initial window size WxH");
    parser.add_float("--budget-ms", &budget, "shading time per frame in milliseconds");
    parser.add_uint64("--paths-per-frame", &o.paths_per_frame,
                      "fixed sampler work (light paths / chain steps) per frame instead of "
                      "--budget-ms");
    parser.add_uint64("--vpls", &o.max_paths,
                      "stop sampling after this many light paths / steps (0 = never)");
    parser.add_uint64("--frames", &o.frames, "exit after N frames (0 = when closed)");
    parser.add_string("--screenshot", &o.screenshot, "image written after the last frame");
    parser.add_string("--script", &o.script, "timed input events (format above)");
    parser.add_float("--clamp", &o.clamp,
                     "clamping distance as a fraction of the scene diagonal (C toggles it)");
    parser.add_float("--exposure", &o.exposure, "exposure in stops");
    parser.add_uint64("--seed", &o.seed, "random seed");
    parser.add_int("--max-depth", &o.max_depth,
                   "path segments from the camera to the light (-1 = unlimited)");
    parser.add_int("--shadow-res", &shadow_res, "side of a shadow cube face in texels");
    parser.add_int("--batch", &batch, "VPLs per shadow/shading batch");
    parser.add_flag("--no-hud", &no_hud, "no text overlay");
    parser.add_flag("--no-motion-scaling", &no_motion_scaling,
                    "render at full resolution while the camera moves too");
    parser.add_flag("--quiet", &o.quiet, "no summary line");
    if (!parser.parse(args)) return 0;

    const std::vector<std::string>& names = sampler::sampler_names();
    if (std::find(names.begin(), names.end(), o.sampler) == names.end())
        throw UsageError("preview: unknown --sampler '" + o.sampler + "' (mc or metropolis)");
    if (width < 16 || height < 16 || width > 8192 || height > 8192)
        throw UsageError("preview: --res must be in 16..8192 on each side");
    if (!(budget > 0.0f && budget <= 10000.0f))
        throw UsageError("preview: --budget-ms must be in (0, 10000]");
    if (shadow_res < 4 || shadow_res > 4096)
        throw UsageError("preview: --shadow-res must be in 4..4096");
    if (batch < 1 || batch > 256) throw UsageError("preview: --batch must be in 1..256");
    if (!(o.clamp >= 0.0f && o.clamp <= 1.0f))
        throw UsageError("preview: --clamp must be in [0, 1]");
    if (!o.screenshot.empty()) {
        if (o.frames == 0) throw UsageError("preview: --screenshot needs --frames N");
        check_output_extensions({o.screenshot});
    }
    o.width = width;
    o.height = height;
    o.budget_ms = budget;
    o.shadow_resolution = uint32_t(shadow_res);
    o.batch = uint32_t(batch);
    o.hud = !no_hud;
    o.motion_scaling = !no_motion_scaling;
    return preview::run_preview(o);
}

}  // namespace mvpl::cli
