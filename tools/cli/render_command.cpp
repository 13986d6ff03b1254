// `mvpl render`: VPLs from a sampler, shaded on the GPU (or by the CPU oracle with --oracle).
// Its options are render_args.h's; render_runs.h forms the image.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <vector>

#include "engine/aov/aov_images.h"
#include "engine/cluster/cluster.h"

#include "engine/core/error.h"
#include "engine/core/image.h"
#include "engine/core/image_size.h"
#include "engine/core/interrupt.h"
#include "engine/core/timer.h"
#include "engine/gpu/context.h"
#include "engine/gpu/device_info.h"
#include "tools/cli/arg_parser.h"
#include "tools/cli/commands.h"
#include "tools/cli/device_choice.h"
#include "tools/cli/exr_outputs.h"
#include "tools/cli/option_groups.h"
#include "tools/cli/output_check.h"
#include "tools/cli/render_args.h"
#include "tools/cli/render_runs.h"

namespace mvpl::cli {

namespace {

// Whether every rank's renderer is a CPU implementation of Vulkan (false for the CPU oracle), so
// that the ranks resolve `--pool auto` alike and cut the same chunks. Collective under mpirun.
bool cpu_devices(cluster::Cluster& ranks, const gpu::Context* context) {
    const bool mine = context && context->device_info().type == gpu::DeviceType::cpu;
    std::vector<uint64_t> others(1, mine ? 0 : 1);
    ranks.sum_all(others);
    return others[0] == 0;
}

RenderJob make_job(const ArgParser& parser, RenderArgs& a, const session::SceneSession& session,
                   bool cpu_device) {
    RenderJob job;
    job.session = &session;
    job.quiet = a.quiet;
    job.estimate = render_estimate(parser, a, session.scene(), cpu_device);
    return job;
}

// What the EXRs hold besides the image (exr_outputs.h): the AOVs at the render's sub-pixel
// positions (engine/aov) and the run's attributes.
ExrExtras exr_extras(const ArgParser& parser, const RenderArgs& a, const Args& args,
                     const RenderJob& job, const RenderOutcome& result, const Timer& total) {
    ExrExtras extras;
    const session::SceneSession& s = *job.session;
    const std::vector<aov::AovRequest> aovs = aov_requests(parser, a.aovs, s.scene(), a.outputs);
    Timer aov_time;
    extras.layers = aov::render_aovs({&s.scene(), &s.accel(), &s.lights(), &s.camera()},
                                     job.estimate, result.stats.vpls, aovs);
    if (!aovs.empty() && !a.quiet) {
        std::printf(
            "aov: %zu AOVs over %llu sub-pixel positions, %.2f s\n", aovs.size(),
            static_cast<unsigned long long>(aov::aov_positions(job.estimate, result.stats.vpls)),
            aov_time.seconds());
    }
    extras.attributes = run_attributes({"render", &args, job.estimate.sampling.seed,
                                        result.stats.vpls, std::nullopt, total.seconds()});
    return extras;
}

}  // namespace

int run_render(const Args& args) {
    // Under mpirun every rank runs this with the same arguments (engine/cluster): each loads the
    // scene and its device and renders its share; rank 0 alone writes and prints. Whatever fails
    // on one rank is met by the others at the next agreement point (cluster::together).
    cluster::Cluster& ranks = cluster::world();
    RenderArgs a;
    // SIGINT, SIGTERM: stop after the chunk in flight and write what has converged; a second
    // signal exits at once (engine/core/interrupt.h). Commands that do not poll keep the default.
    install_interrupt_handlers();
    ArgParser parser(
        "render",
        "Renders SCENE with virtual point lights: a sampler traces light paths on the CPU\n"
        "and leaves VPLs; the GPU shades them in batches with cube-map shadows.\n"
        "Under mpirun, the ranks share the work and rank 0 writes the image.");
    add_render_options(parser, a);
    bool parsed = false, defaulted = false;
    Timer total;
    std::unique_ptr<session::SceneSession> session;
    std::unique_ptr<gpu::Context> context;
    std::unique_ptr<integrator::VplIntegrator> integrator;
    cluster::together(ranks, [&] {
        parsed = parser.parse(with_local_rank_device(args));
        if (!parsed) return;
        if (!a.oracle) check_device("render", a.device);
        if (ranks.size() > 1 && a.oracle)
            throw UsageError("render: --oracle runs on one process, not under mpirun");
        a.outputs = outputs_or(a.outputs, "render.exr", defaulted);
        if (ranks.root()) check_outputs(a.outputs);
        if (!ranks.root()) a.quiet = true;
        total.reset();
        session = std::make_unique<session::SceneSession>(
            a.scene_path, a.camera.choice, a.environment.choice, a.scene_file.options);
        apply_scene_defaults(parser, session->scene(), &a.settings.tracer.max_depth, &a.width,
                             &a.height);
        apply_vpl_integrator_defaults(parser, *session, a.settings.tracer.max_depth, a.renderer);
        session->warn_if_no_light("the image shows emitters only");
        if (!a.oracle) {
            gpu::ContextOptions co;
            co.device_index = a.device;
            context = std::make_unique<gpu::Context>(co);
        }
    });
    if (!parsed) return 0;
    integrator = std::make_unique<integrator::VplIntegrator>(
        session->view(), context.get(),
        context ? a.renderer.devices_for(context->device_info()) : 1,
        ranks.size() > 1 ? &ranks : nullptr);
    RenderJob job = make_job(parser, a, *session, cpu_devices(ranks, context.get()));
    job.integrator = integrator.get();
    if (ranks.size() > 1) job.cluster = &ranks;
    job.write_every = double(a.write_every);
    job.checkpoint = [&](const Image& image, uint64_t vpls) {
        if (!ranks.root()) return;
        write_images(image, a.outputs, a.exposure);
        if (!a.quiet)
            std::printf("render: wrote the image of %llu VPLs so far\n",
                        static_cast<unsigned long long>(vpls));
        std::fflush(stdout);
    };

    const RenderOutcome result =
        a.time_budget > 0.0f ? render_for(job, double(a.time_budget)) : render_once(job, a.paths);
    // Rank 0 writes; the others wait for it, so that all exit with its status.
    cluster::together(ranks, [&] {
        if (context) {
            // MVPL_VALIDATION=1: whatever the layer reported is shown, one line a message.
            for (const std::string& message : context->validation_messages())
                std::fprintf(stderr, "mvpl: validation: %s\n", message.c_str());
        }
        if (!ranks.root()) return;
        session->warn_if_black(result.image);
        const ExrExtras extras = exr_extras(parser, a, args, job, result, total);
        write_images(result.image, a.outputs, a.exposure, extras);
        say_written("render", a.outputs, defaulted, a.quiet);
        if (!a.quiet) std::fputs(summary_line(job, result, total.seconds()).c_str(), stdout);
    });
    return 0;
}

}  // namespace mvpl::cli
