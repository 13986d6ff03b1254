// `mvpl reference`: the CPU path tracer, the ground truth for every error report. It traces in
// chunks of whole samples per pixel (engine/reference/progressive_trace.h), so that SIGINT or
// SIGTERM ends it after the chunk in flight with the image of the samples so far, and
// --write-every rewrites its outputs between chunks; the image is the same whatever the chunks.
#include <tbb/global_control.h>

#include <algorithm>
#include <cstdio>
#include <memory>
#include <optional>

#include "engine/aov/aov_images.h"
#include "engine/core/error.h"
#include "engine/core/image.h"
#include "engine/core/interrupt.h"
#include "engine/core/timer.h"
#include "engine/reference/path_tracer.h"
#include "engine/reference/progressive_trace.h"
#include "tools/cli/arg_parser.h"
#include "tools/cli/checkpoints.h"
#include "tools/cli/commands.h"
#include "tools/cli/exr_outputs.h"
#include "tools/cli/option_groups.h"
#include "tools/cli/output_check.h"
#include "tools/cli/reference_args.h"
#include "tools/session/scene_session.h"

namespace mvpl::cli {

namespace {

// What the EXRs hold besides the image: the AOVs and the run's attributes, at the samples per
// pixel the film holds (fewer than --spp when interrupted or at a checkpoint).
ExrExtras exr_extras(const Args& args, const ReferenceArgs& a,
                     const std::optional<aov::ReferenceAovs>& aovs, const reference::PathFilm& film,
                     const Timer& wall) {
    ExrExtras extras;
    if (aovs) extras.layers = aovs->images(film.spp());
    extras.attributes = run_attributes(
        {"reference", &args, a.options.seed, std::nullopt, film.spp(), wall.seconds()});
    return extras;
}

void print_summary(const reference::PathTracerOptions& options, int spp,
                   const session::SceneSession& session, const reference::RenderStats& stats) {
    const double seconds = std::max(stats.seconds, 1e-9);
    std::printf(
        "reference: %dx%d, %d spp, max depth %d, %zu triangles: setup %.2f s, render %.2f s, "
        "%.2f Mrays/s, %.2f Mpaths/s%s\n",
        options.width, options.height, spp, options.max_depth, session.scene().triangle_count(),
        session.setup_seconds(), stats.seconds, double(stats.rays) / seconds * 1e-6,
        double(stats.paths) / seconds * 1e-6,
        // The image holds the samples of the chunks before the signal.
        interrupted() ? "; interrupted" : "");
}

}  // namespace

int run_reference(const Args& args) {
    ReferenceArgs a;
    // SIGINT, SIGTERM: end after the chunk in flight and write the samples so far; a second
    // signal exits at once (engine/core/interrupt.h).
    install_interrupt_handlers();
    ArgParser parser(
        "reference",
        "Renders SCENE with the CPU reference path tracer (next-event estimation, MIS,\n"
        "Russian roulette). Writes EXR (linear float) or PNG (sRGB) by the extension of -o.");
    add_reference_options(parser, a);
    if (!parser.parse(args)) return 0;
    reference::PathTracerOptions& options = a.options;
    std::vector<std::string>& outputs = a.outputs;
    Timer wall;
    bool defaulted = false;
    outputs = outputs_or(outputs, "reference.exr", defaulted);
    check_outputs(outputs);
    std::unique_ptr<tbb::global_control> limit;
    if (a.threads > 0) {
        limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                      a.threads);
    }

    const session::SceneSession session(a.scene_path, a.camera.choice, a.environment.choice,
                                        a.scene_file.options);
    apply_scene_defaults(parser, session.scene(), &options.max_depth, &options.width,
                         &options.height);
    session.warn_if_no_light("the image is black");
    check_host_memory(options);

    reference::RenderStats stats;
    const reference::PathTracer tracer(session.scene(), session.accel(), session.lights());
    const std::vector<aov::AovRequest> aovs =
        aov_requests(parser, a.aov_list, session.scene(), outputs);
    std::optional<aov::ReferenceAovs> aov_film;
    if (!aovs.empty()) aov_film.emplace(session.scene(), session.accel(), options, aovs);
    reference::PathFilm film(options.width, options.height, options.seed);
    Checkpoints checkpoints(double(a.write_every));
    reference::trace_progressively(
        tracer, film, options, &stats, aov_film ? aov_film->hook() : reference::CameraSampleHook{},
        [&](const reference::PathFilm& so_far) {
            if (interrupted()) return false;
            if (so_far.spp() == 0) return true;  // nothing to write before the first chunk
            checkpoints.after_chunk(false, [&] {
                write_images(so_far.image(), outputs, a.exposure,
                             exr_extras(args, a, aov_film, so_far, wall));
                if (!options.quiet)
                    std::printf("reference: wrote the image of %d spp so far\n", so_far.spp());
                std::fflush(stdout);
            });
            return true;
        });
    const Image image = film.image();
    session.warn_if_black(image);
    write_images(image, outputs, a.exposure, exr_extras(args, a, aov_film, film, wall));
    say_written("reference", outputs, defaulted, options.quiet);

    if (stats.nonfinite_samples > 0) {
        std::fprintf(stderr, "mvpl: warning: %llu non-finite path samples were discarded\n",
                     static_cast<unsigned long long>(stats.nonfinite_samples));
    }
    if (!options.quiet) print_summary(options, film.spp(), session, stats);
    return 0;
}

}  // namespace mvpl::cli
