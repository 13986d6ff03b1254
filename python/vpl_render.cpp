#include "python/vpl_render.h"

#include <pybind11/pybind11.h>

#include <algorithm>
#include <memory>

#include "engine/aov/aov_images.h"
#include "engine/aov/aov_kind.h"
#include "engine/core/error.h"
#include "engine/core/timer.h"
#include "engine/gpu/context.h"
#include "engine/integrator/vpl_integrator.h"
#include "tools/cli/device_choice.h"
#include "tools/cli/render_args.h"
#include "tools/cli/render_chunks.h"

namespace py = pybind11;

namespace mvpl::python {

namespace {

// The Vulkan device a render shades on, or none with `oracle` (the integrator then shades with
// the CPU oracle).
std::unique_ptr<gpu::Context> make_context(const cli::RenderArgs& a) {
    if (a.oracle) return nullptr;
    gpu::ContextOptions options;
    options.device_index = a.device;
    return std::make_unique<gpu::Context>(options);
}

// `mvpl render`'s two loops (tools/cli/render_runs.cpp) on one process: fixed-size chunks of
// --vpls units, or chunks of about kChunkSeconds until --time-budget is spent on `clock`.
void run_chunks(integrator::VplIntegrator& run, const cli::RenderArgs& a, uint32_t devices,
                const Timer& clock, const ChunkHook& between_chunks) {
    const double seconds = double(a.time_budget);
    for (uint64_t done = 0;;) {
        double share = 0.0;
        uint64_t work = 0;
        if (seconds > 0.0) {
            const double t = clock.seconds();
            share = std::min(t / seconds, 1.0);
            if (t < seconds)
                work = cli::next_chunk(run.stream().work_done(), t, seconds - t,
                                       uint64_t(a.renderer.batch), cli::kChunkSeconds * devices);
        } else {
            share = double(done) / double(a.paths);
            work = std::min(cli::kStreamChunkUnits, a.paths - done);
        }
        between_chunks(share);
        if (work == 0 || run.unlit()) return;
        const py::gil_scoped_release unlocked;
        run.advance(work);
        done += work;
    }
}

}  // namespace

RenderResult render_vpls(const SceneHandle& scene, const std::vector<std::string>& tokens,
                         const ChunkHook& between_chunks) {
    cli::RenderArgs a;
    cli::ArgParser parser("render", "");
    cli::add_render_options(parser, a);
    std::vector<std::string> line = scene.command_line();
    line.insert(line.end(), tokens.begin(), tokens.end());
    if (!parser.parse(line)) throw UsageError("render: the options are `mvpl render --help`'s");
    if (!a.oracle) cli::check_device("render", a.device);
    if (parser.given("--write-every") || parser.given("-o"))
        throw UsageError(
            "render: mvpl.render returns arrays and writes no file (no -o, no "
            "--write-every)");
    const py::gil_scoped_release unlocked;
    const std::shared_ptr<const session::SceneSession> session =
        scene.session_for(parser, a.camera.choice, a.environment.choice);
    cli::apply_scene_defaults(parser, session->scene(), &a.settings.tracer.max_depth, &a.width,
                              &a.height);
    cli::apply_vpl_integrator_defaults(parser, *session, a.settings.tracer.max_depth, a.renderer);
    session->warn_if_no_light("the image shows emitters only");
    const std::unique_ptr<gpu::Context> context = make_context(a);
    const uint32_t devices = context ? a.renderer.devices_for(context->device_info()) : 1;
    const integrator::Estimate estimate =
        cli::render_estimate(parser, a, session->scene(),
                             context && context->device_info().type == gpu::DeviceType::cpu);
    const session::SceneSession& s = *session;
    integrator::VplIntegrator run(s.view(), context.get(), devices, nullptr);
    const Timer clock;  // the budget counts the sampler's set-up, as the command line's
    run.begin(s.view(), estimate,
              a.time_budget > 0.0f ? integrator::Pacing::OpenEnded : integrator::Pacing::Fixed);
    if (run.unlit() && !s.warn_if_clipped(a.width, a.height))
        s.warn("no light reaches anything the camera sees; the image is black");
    {
        const py::gil_scoped_acquire locked;
        run_chunks(run, a, devices, clock, between_chunks);
    }
    RenderResult result{run.finish(), {}};
    s.warn_if_black(result.image);
    // As `mvpl render` writes them (no EXR to name: --aov alone asks for them here).
    if (parser.given("--aov")) {
        result.aovs = aov::render_aovs(s.view(), estimate, run.stats().vpls,
                                       aov::parse_aov_list(a.aovs, "render: --aov"));
    }
    return result;
}

}  // namespace mvpl::python
