// `mvpl preview`: the interactive window (tools/preview).
#include <cstdio>
#include <string>

#include "engine/core/error.h"
#include "tools/cli/arg_parser.h"
#include "tools/cli/commands.h"
#include "tools/cli/option_groups.h"
#include "tools/cli/output_check.h"
#include "tools/preview/preview_app.h"
#include "tools/preview/settings.h"

namespace mvpl::cli {

namespace {

void add_examples(ArgParser& parser) {
    parser.add_example("mvpl preview assets/glossy/glossy.gltf",
                       "the glossy scene in a window: drag to orbit, P for a screenshot");
    parser.add_example(
        "mvpl preview assets/two-room/two-room.gltf --sampler metropolis "
        "--budget-ms 100",
        "Metropolis VPLs, 100 ms of shading a frame");
    parser.add_example(
        "mvpl preview assets/cornell-box/cbox.gltf --frames 120 --screenshot cbox.png",
        "120 frames without a user, the last one written to cbox.png");
}

// What `mvpl preview` was asked: PreviewOptions' own fields, and what is checked or converted
// before it gets them.
struct PreviewArgs {
    preview::PreviewOptions o;
    int width = o.width, height = o.height;
    float budget = float(o.budget_ms);
    RendererArgs renderer;
    CompensationArgs compensation;
    bool no_caustics = false, no_hud = false, no_motion_scaling = false;
    uint64_t kept_mib = o.kept_shadow_bytes >> 20;
    float catch_up = float(o.catch_up_seconds);
    CameraArgs camera;
    EnvironmentArgs environment;
    SceneFileArgs scene_file;
    std::string per_path;
    ManyLightsArgs many_lights;
};

void add_options(ArgParser& parser, PreviewArgs& a) {
    preview::PreviewOptions& o = a.o;
    parser.add_positional("SCENE", &o.scene_path, "scene (.gltf, .glb, .xml, .ply, .obj)");
    parser.add_resolution("--res", &a.width, &a.height, "initial window size");
    parser.add_float("--budget-ms", &a.budget, "shading time per frame in milliseconds", "MS");
    parser.add_uint64("--paths-per-frame", &o.paths_per_frame,
                      "fixed sampler work (light paths / chain steps) per frame instead of "
                      "--budget-ms");
    parser.add_uint64("--vpls", &o.max_paths,
                      "stop sampling after this many light paths / steps (0 = never)");
    parser.add_uint64("--frames", &o.frames, "exit after N frames (0 = when closed)");
    parser.add_string("--screenshot", &o.screenshot, "image written after the last frame", "FILE");
    parser.add_string("--script", &o.script, "timed input events (format above)", "FILE");
    parser.add_float("--exposure", &o.exposure, "exposure in stops");
    parser.add_flag("--no-hud", &a.no_hud, "no text overlay");
    parser.add_flag("--no-motion-scaling", &a.no_motion_scaling,
                    "render at full resolution while the camera moves too");
    parser.add_uint64("--kept-maps", &a.kept_mib,
                      "device memory in MiB for shadow cubes kept across camera moves (0 = none)",
                      "MIB");
    parser.add_float("--catch-up", &a.catch_up,
                     "the first frame at rest after a move shades the recorded VPLs until it "
                     "holds 90 % of the picture's before the move, for at most SEC seconds (0 = "
                     "the frame budget)",
                     "SEC");
    parser.add_flag("--quiet", &o.quiet, "no summary line");
    add_sampler_option(parser, o.sampler);
    add_renderer_options(parser, a.renderer, true);  // C toggles clamping in the window
    add_compensation_options(parser, a.compensation);
    add_caustics_option(parser, a.no_caustics);
    add_max_depth_option(parser, o.max_depth);
    add_seed_option(parser, o.seed);
    add_vpl_per_path_option(parser, a.per_path);
    add_many_lights_options(parser, a.many_lights);
    add_camera_options(parser, a.camera);
    add_environment_options(parser, a.environment);
    add_scene_file_options(parser, a.scene_file);
    add_examples(parser);
}

// The window's options, after the checks of what the window cannot do.
preview::PreviewOptions checked_options(const PreviewArgs& a) {
    preview::PreviewOptions o = a.o;
    const RendererArgs& renderer = a.renderer;
    if (a.width < 16 || a.height < 16 || a.width > 8192 || a.height > 8192)
        throw UsageError("preview: --res must be in 16..8192 on each side");
    if (!(a.budget > 0.0f && a.budget <= 10000.0f))
        throw UsageError("preview: --budget-ms must be in (0, 10000]");
    if (!o.screenshot.empty()) {
        if (o.frames == 0) throw UsageError("preview: --screenshot needs --frames N");
        check_outputs({o.screenshot});
    }
    o.width = a.width;
    o.height = a.height;
    o.budget_ms = a.budget;
    o.shadow_resolution = uint32_t(renderer.shadow_res);
    o.batch = uint32_t(renderer.batch);
    o.jitter = !renderer.no_jitter;
    o.clamp = renderer.clamp;
    renderer.apply(o.levers);
    o.interleave_auto = renderer.interleave == 0;
    o.interleave_min_pixels = RendererArgs::kInterleaveMinPixels;
    o.batches_per_position_auto = renderer.batches_per_position == 0;
    o.compensate = a.compensation.enabled();
    o.compensation_passes = uint32_t(a.compensation.spp);
    o.caustics = !a.no_caustics;
    o.hud = !a.no_hud;
    o.motion_scaling = !a.no_motion_scaling;
    if (a.kept_mib > (uint64_t(1) << 24))
        throw UsageError("preview: --kept-maps must be at most 16 TiB");
    o.kept_shadow_bytes = a.kept_mib << 20;
    if (!(a.catch_up >= 0.0f && a.catch_up <= 60.0f))
        throw UsageError("preview: --catch-up must be in [0, 60] seconds");
    o.catch_up_seconds = a.catch_up;
    o.devices = uint32_t(a.renderer.devices);
    sampler::SamplerSettings per_path;
    apply_vpl_per_path(a.per_path, per_path);
    o.per_path = per_path.per_path;
    o.metropolis_per_path = per_path.metropolis_per_path;
    o.many_lights = a.many_lights.options();
    o.camera = a.camera.choice;
    o.environment = a.environment.choice;
    o.load = a.scene_file.options;
    return o;
}

// The help's description: controls, the script format and the settings it sets (settings.h).
std::string description() {
    std::string text =
        "Opens a window that renders SCENE progressively with virtual point lights: each frame\n"
        "shades as many VPL batches as fit --budget-ms (or --paths-per-frame light paths) and\n"
        "shows the running average; moving the camera restarts it.\n"
        "\n"
        "Controls: left drag orbit, middle or shift+left drag pan, wheel zoom, WASD (Q/E down/up)\n"
        "and right drag fly, R reset view, +/- exposure, M switch sampler (mc/metropolis),\n"
        "C clamping on/off, P screenshot (SCENE-NNNN.png and .exr in the working directory, at\n"
        "the first number no file has), V view (image; albedo, normal, depth: the AOVs of\n"
        "render --aov; vpls: the VPLs over the image, as mvpl vpls --view camera; error: each\n"
        "pixel's relative standard error from the variance between frames), Tab the\n"
        "settings panel (shown at the start unless\n"
        "--frames is given), Esc quit. Drop a scene file (.gltf .glb .xml .ply .obj)\n"
        "on the window to open it, an .hdr or .exr to light the scene with it; a file that cannot\n"
        "be read is reported (in the window and on stderr) and changes nothing.\n"
        "\n"
        "--script FILE drives the window without a user: one event a line, `#` comments,\n"
        "  FRAME orbit YAW PITCH     degrees        FRAME look YAW PITCH    degrees about the eye\n"
        "  FRAME pan RIGHT UP        view heights   FRAME zoom FACTOR       distance x FACTOR\n"
        "  FRAME fly FWD RIGHT UP    scene diagonals\n"
        "  FRAME resize W H          window size    FRAME key NAME          r plus minus m c p v "
        "tab escape\n"
        "  FRAME camera N            the file's camera N (as render --camera N)\n"
        "  FRAME fov DEGREES         vertical field of view\n"
        "  FRAME view NAME           image, albedo, normal, depth, vpls or error (as V)\n"
        "  FRAME drop FILE           as a file dropped on the window\n"
        "  FRAME set NAME ARGS...    a setting (exposure only re-tonemaps; the others restart\n"
        "                            the average, some draw the VPLs again):\n";
    for (const preview::SettingSpec& spec : preview::setting_specs()) {
        char line[160];
        std::snprintf(line, sizeof line, "      %-18s %s\n", spec.name, spec.meaning);
        text += line;
    }
    text +=
        "where FRAME is the index (from 0) of the frame at whose start the event happens.\n"
        "--frames N with --screenshot FILE renders N frames, writes the last (.png: the window's\n"
        "picture without the HUD; .exr: linear radiance) and exits.";
    return text;
}

}  // namespace

int run_preview(const Args& args) {
    PreviewArgs a;
    ArgParser parser("preview", description());
    add_options(parser, a);
    if (!parser.parse(args)) return 0;
    return preview::run_preview(checked_options(a));
}

}  // namespace mvpl::cli
