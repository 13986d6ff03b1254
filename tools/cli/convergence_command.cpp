// `mvpl convergence`: error against run time for the reference path tracer and the VPL samplers,
// against a reference image (docs/design.md "Reference and oracle"; issue 6). Under mpirun every
// rank loads the scene and its device and shares each measurement's work (convergence_runs.h); rank
// 0 alone measures, writes and prints, and whatever fails on one rank is met by the others at the
// next agreement point (cluster::together).
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>

#include "engine/cluster/cluster.h"
#include "engine/core/atomic_files.h"
#include "engine/core/error.h"
#include "engine/core/finite_check.h"
#include "engine/core/image.h"
#include "engine/core/interrupt.h"
#include "engine/core/reference_noise.h"
#include "engine/gpu/context.h"
#include "engine/render/vpl_renderer.h"
#include "engine/sampler/sampler_factory.h"
#include "tools/cli/arg_parser.h"
#include "tools/cli/commands.h"
#include "tools/cli/convergence_analysis.h"
#include "tools/cli/convergence_runs.h"
#include "tools/cli/device_choice.h"
#include "tools/cli/option_groups.h"
#include "tools/cli/output_check.h"
#include "tools/session/scene_session.h"

namespace mvpl::cli {

namespace {

std::vector<std::string> split_commas(const std::string& text) {
    std::vector<std::string> out;
    std::stringstream stream(text);
    std::string item;
    while (std::getline(stream, item, ','))
        if (!item.empty()) out.push_back(item);
    return out;
}

// tools/plot_convergence.py next to the sources this binary was built from, or $MVPL_TOOLS_DIR.
std::filesystem::path plot_script() {
    if (const char* dir = std::getenv("MVPL_TOOLS_DIR"))
        return std::filesystem::path(dir) / "plot_convergence.py";
    return std::filesystem::path(MVPL_TOOLS_DIR) / "plot_convergence.py";
}

// The interpreter that Debian's python3-matplotlib installs into is /usr/bin/python3; a `python3`
// found first on PATH (pyenv, a virtual environment) usually lacks matplotlib. $MVPL_PYTHON wins.
std::string python_interpreter() {
    if (const char* python = std::getenv("MVPL_PYTHON")) return python;
    if (std::filesystem::exists("/usr/bin/python3")) return "/usr/bin/python3";
    return "python3";
}

std::string shell_quote(const std::string& s) {
    std::string out = "'";
    for (char c : s)
        out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

// `reference_noise`: the references' own share of relMSE (0 for one reference): each method's
// last error less it is its error against the truth (engine/core/reference_noise.h).
void print_summary(const std::vector<ConvergencePoint>& all,
                   const std::vector<std::string>& methods, double reference_noise) {
    if (reference_noise > 0.0) {
        std::printf(
            "reference     the mean of several; their own share of relMSE ≈%.3g "
            "(relMSE_vs_truth = relMSE − it)\n",
            reference_noise);
    }
    const std::vector<ConvergencePoint> pt = points_of(all, "pt");
    const double c_pt = inverse_time_constant(pt);
    for (const std::string& method : methods) {
        const std::vector<ConvergencePoint> points = points_of(all, method);
        if (points.empty()) continue;
        const ConvergencePoint& last = points.back();
        std::printf("%-11s relMSE %.3g at %.2f s (%llu %s), mean ratio %.4f", method.c_str(),
                    last.rel_mse, last.seconds, static_cast<unsigned long long>(last.samples),
                    method == "pt" ? "spp" : "VPLs", last.mean_ratio);
        if (reference_noise > 0.0)
            std::printf(", relMSE_vs_truth %.3g", last.rel_mse - reference_noise);
        if (method != "pt") {
            if (c_pt > 0.0 && last.rel_mse > 0.0) {
                const double pt_seconds = c_pt / last.rel_mse;
                const double speed_up = pt_seconds / last.seconds;
                std::printf("; the path tracer needs ≈%.3g s for it: %.2g× %s", pt_seconds,
                            speed_up >= 1.0 ? speed_up : 1.0 / speed_up,
                            speed_up >= 1.0 ? "faster" : "slower");
            }
            const FloorFit fit = fit_floor(points);
            std::printf("; bias floor ≈%.3g (fit relMSE = floor + c/t)", fit.floor);
        }
        std::printf("\n");
    }
}

// The methods named by --methods, after the checks of --ref and --budget.
std::vector<std::string> checked_methods(const std::string& ref_path, float budget,
                                         const std::string& methods_text) {
    if (ref_path.empty()) throw UsageError("convergence: --ref REF.exr is required");
    if (!(budget > 0.0f && budget <= 1e6f))
        throw UsageError("convergence: --budget must be in (0, 1e6] seconds");
    const std::vector<std::string> methods = split_commas(methods_text);
    if (methods.empty()) throw UsageError("convergence: --methods names no method");
    for (const std::string& m : methods) {
        if (m != "pt" && m != "mc" && m != "metropolis")
            throw UsageError("convergence: unknown method '" + m +
                             "' (available: pt, mc, metropolis)");
    }
    return methods;
}

void add_examples(ArgParser& parser) {
    parser.add_example(
        "mvpl convergence assets/cornell-box/cbox.gltf --ref "
        "assets/cornell-box/ref-cbox-d6-4096.exr --budget 8 --out cbox-convergence",
        "path tracer, Monte Carlo and Metropolis VPLs, 8 s each, against Mitsuba's reference");
    parser.add_example(
        "mvpl convergence assets/glossy/glossy.gltf --ref docs/results/glossy-ref.exr "
        "--budget 30 --methods pt,mc --out glossy-convergence",
        "the glossy scene: the path tracer and Monte Carlo VPLs only");
    parser.add_example(
        "mvpl convergence assets/two-room/two-room.gltf --ref docs/results/two-room-ref.exr "
        "--and-ref docs/results/two-room-ref-2.exr --budget 60 --out rooms-convergence",
        "against the mean of two independent references, with their own noise reported");
}

}  // namespace

int run_convergence(const Args& args) {
    cluster::Cluster& ranks = cluster::world();
    // SIGINT, SIGTERM: the methods and points so far are written (engine/core/interrupt.h).
    install_interrupt_handlers();
    std::string scene_path, ref_path, out_dir = "convergence";
    std::vector<std::string> more_references;
    std::string methods_text = "pt,mc,metropolis";
    float budget = 10.0f;
    int width = 0, height = 0;
    sampler::SamplerSettings settings;  // max depth and seed; the rest is each sampler's default
    RendererArgs renderer_args;
    CompensationArgs compensation_args;
    bool no_caustics = false;
    bool quiet = false, no_plot = false;
    ArgParser parser(
        "convergence",
        "Error against run time: the reference path tracer and the VPL samplers,\n"
        "each run progressively up to --budget seconds against --ref; writes\n"
        "DIR/convergence.csv and DIR/convergence.png and prints, per VPL sampler, the\n"
        "speed-up over the path tracer at equal relMSE and the bias floor.\n"
        "Under mpirun, the ranks share each method's work and rank 0 writes.");
    parser.add_positional("SCENE", &scene_path, "scene file");
    parser.add_string("--ref", &ref_path, "reference image (.exr); its size is the image size",
                      "FILE");
    parser.add_strings("--and-ref", &more_references,
                       "another independent reference (a different seed, the same sample count): "
                       "errors are against the references' mean, and the summary prints their "
                       "own share of relMSE and each method's error less it",
                       "FILE");
    parser.add_float("--budget", &budget, "seconds per method", "SEC");
    parser.add_string("--out", &out_dir, "output directory", "DIR");
    parser.add_resolution("--res", &width, &height,
                          "image size (default and only allowed: the reference's)");
    parser.add_string("--methods", &methods_text, "comma-separated, of pt, mc and metropolis",
                      "NAME,...");
    parser.add_flag("--no-plot", &no_plot, "write the CSV only");
    parser.add_flag("--quiet", &quiet, "no progress bars and no summary");
    add_renderer_options(parser, renderer_args);
    add_compensation_options(parser, compensation_args);
    add_caustics_option(parser, no_caustics);
    ManyLightsArgs many_lights;
    add_many_lights_options(parser, many_lights);
    add_max_depth_option(parser, settings.tracer.max_depth);
    add_seed_option(parser, settings.seed);
    CameraArgs camera;
    add_camera_options(parser, camera);
    EnvironmentArgs environment;
    add_environment_options(parser, environment);
    SceneFileArgs scene_file;
    add_scene_file_options(parser, scene_file);
    int device = -1;
    add_device_option(parser, device,
                      "Vulkan device index (see mvpl info), -1 = default; under mpirun "
                      "local-rank: by the rank's place on its machine",
                      "N|local-rank");
    add_examples(parser);
    bool parsed = false;
    std::vector<std::string> methods;
    Image reference;
    double noise = 0.0;  // the references' own share of relMSE
    std::unique_ptr<session::SceneSession> loaded;
    cluster::together(ranks, [&] {
        parsed = parser.parse(with_local_rank_device(args));
        if (!parsed) return;
        check_device("convergence", device);
        methods = checked_methods(ref_path, budget, methods_text);
        reference = read_finite_exr(ref_path);
        if (!more_references.empty()) {
            std::vector<Image> references{reference};
            for (const std::string& path : more_references) {
                references.push_back(read_finite_exr(path));
                if (references.back().width() != reference.width() ||
                    references.back().height() != reference.height())
                    throw InputError(path, "size differs from --ref's");
            }
            reference = average_images(references);
            noise = reference_noise(references);
        }
        if (width != 0 && (width != reference.width() || height != reference.height())) {
            throw UsageError("convergence: --res " + std::to_string(width) + "x" +
                             std::to_string(height) + " differs from the reference's " +
                             std::to_string(reference.width()) + "x" +
                             std::to_string(reference.height()));
        }
        loaded = std::make_unique<session::SceneSession>(scene_path, camera.choice,
                                                         environment.choice, scene_file.options);
        apply_scene_defaults(parser, loaded->scene(), &settings.tracer.max_depth, nullptr, nullptr);
        if (ranks.root()) create_output_folder(out_dir);
    });
    if (!parsed) return 0;
    const session::SceneSession& session = *loaded;
    // Rank 0 alone prints: progress, summary and the files written.
    if (!ranks.root()) quiet = true;

    ConvergenceRun run;
    run.session = &session;
    run.reference = &reference;
    run.budget_seconds = budget;
    run.max_depth = settings.tracer.max_depth;
    run.seed = settings.seed;
    settings.width = reference.width();
    settings.height = reference.height();
    settings.clamp = renderer_args.clamp;
    settings.vsl_radius = renderer_args.vsl();
    render::RenderOptions render_options;
    renderer_args.apply(render_options);
    render_options.chains.max_depth = run.max_depth;
    render_options.interleave =
        renderer_args.interleave_for(session.scene(), render_options.chains,
                                     uint32_t(settings.width), uint32_t(settings.height));
    render_options.batches_per_position = renderer_args.batches_per_position_for(session.scene());
    settings.specular_chains = render_options.chains;  // the Metropolis target follows them too
    run.quiet = quiet;
    run.compensate = compensation_args.enabled();
    run.compensation_passes = uint32_t(compensation_args.spp);
    run.caustics = !no_caustics;
    run.many_lights = many_lights.options();
    run.cluster = &ranks;

    std::vector<ConvergencePoint> all;
    std::unique_ptr<gpu::Context> context;
    std::unique_ptr<render::VplRenderer> renderer;
    for (const std::string& method : methods) {
        // SIGINT/SIGTERM on any rank (interrupt.h): the methods run so far are written.
        std::vector<double> stop(1, interrupted() ? 1.0 : 0.0);
        ranks.sum_all(stop);
        if (stop[0] > 0.0) break;
        std::vector<ConvergencePoint> points;
        if (method == "pt") {
            points = run_path_tracer(run);
        } else {
            cluster::together(ranks, [&] {
                if (renderer) return;
                gpu::ContextOptions co;
                co.device_index = device;
                context = std::make_unique<gpu::Context>(co);
                renderer = std::make_unique<render::VplRenderer>(
                    *context, session.scene(), &session.accel(),
                    renderer_args.devices_for(context->device_info()));
            });
            points = run_vpl_sampler(run, method, settings, *renderer, render_options);
        }
        all.insert(all.end(), points.begin(), points.end());
    }

    // Rank 0 writes; the others wait for it, so that all exit with its status.
    cluster::together(ranks, [&] {
        if (!ranks.root()) return;
        const std::filesystem::path csv = std::filesystem::path(out_dir) / "convergence.csv";
        // Whole or not at all, every write checked (atomic_files.h).
        const std::string text = to_csv(all);
        write_files_atomically({csv.string()}, [&](size_t, const std::string& temp) {
            write_bytes(temp,
                        std::span(reinterpret_cast<const uint8_t*>(text.data()), text.size()));
        });
        if (!quiet) print_summary(all, methods, noise);
        if (!no_plot) {
            const std::filesystem::path png = std::filesystem::path(out_dir) / "convergence.png";
            const std::string command =
                shell_quote(python_interpreter()) + " " + shell_quote(plot_script().string()) +
                " " + shell_quote(csv.string()) + " " + shell_quote(png.string()) + " --title " +
                shell_quote(std::filesystem::path(scene_path).stem().string());
            if (std::system(command.c_str()) != 0) {
                std::fprintf(stderr,
                             "mvpl: warning: the plot was not made (%s failed; python3-matplotlib "
                             "installed?); %s is written\n",
                             plot_script().string().c_str(), csv.string().c_str());
            }
        }
        if (!quiet) std::printf("convergence: wrote %s\n", csv.string().c_str());
    });
    return 0;
}

}  // namespace mvpl::cli
