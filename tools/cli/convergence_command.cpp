// `mvpl convergence`: error against run time for the reference path tracer and the VPL samplers,
// against a reference image (docs/design.md "Reference and oracle"; issue 6). Under mpirun every
// rank loads the scene and its device and shares each measurement's work (convergence_runs.h); rank
// 0 alone measures, writes and prints, and whatever fails on one rank is met by the others at the
// next agreement point (cluster::together).
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <system_error>

#include "engine/cluster/cluster.h"
#include "engine/core/atomic_files.h"
#include "engine/core/error.h"
#include "engine/core/finite_check.h"
#include "engine/core/image.h"
#include "engine/core/interrupt.h"
#include "engine/core/reference_noise.h"
#include "engine/gpu/context.h"
#include "engine/integrator/vpl_integrator.h"
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

// The plot script: in $MVPL_TOOLS_DIR when set; else where `cmake --install` puts it beside an
// installed binary (BIN/../share/mvpl); else tools/ of the sources this binary was built from.
std::filesystem::path plot_script() {
    constexpr const char* kScript = "plot_convergence.py";
    if (const char* dir = std::getenv("MVPL_TOOLS_DIR"))
        return std::filesystem::path(dir) / kScript;
    std::error_code error;
    const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", error);
    if (!error) {
        const std::filesystem::path installed =
            exe.parent_path().parent_path() / "share" / "mvpl" / kScript;
        if (std::filesystem::is_regular_file(installed, error)) return installed;
    }
    return std::filesystem::path(MVPL_TOOLS_DIR) / kScript;
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

// What `mvpl convergence` was asked.
struct ConvergenceArgs {
    std::string scene_path, ref_path, out_dir = "convergence";
    std::vector<std::string> more_references;
    std::string methods_text = "pt,mc,metropolis";
    float budget = 10.0f;
    int width = 0, height = 0;
    sampler::SamplerSettings settings;  // max depth and seed; the rest is each sampler's default
    RendererArgs renderer;
    CompensationArgs compensation;
    bool no_caustics = false, quiet = false, no_plot = false;
    ManyLightsArgs many_lights;
    CameraArgs camera;
    EnvironmentArgs environment;
    SceneFileArgs scene_file;
    int device = -1;
};

void add_options(ArgParser& parser, ConvergenceArgs& a) {
    parser.add_positional("SCENE", &a.scene_path, "scene file");
    parser.add_string("--ref", &a.ref_path, "reference image (.exr); its size is the image size",
                      "FILE");
    parser.add_strings("--and-ref", &a.more_references,
                       "another independent reference (a different seed, the same sample count): "
                       "errors are against the references' mean, and the summary prints their "
                       "own share of relMSE and each method's error less it",
                       "FILE");
    parser.add_float("--budget", &a.budget, "seconds per method", "SEC");
    parser.add_string("--out", &a.out_dir, "output directory", "DIR");
    parser.add_resolution("--res", &a.width, &a.height,
                          "image size (default and only allowed: the reference's)");
    parser.add_string("--methods", &a.methods_text, "comma-separated, of pt, mc and metropolis",
                      "NAME,...");
    parser.add_flag("--no-plot", &a.no_plot, "write the CSV only");
    parser.add_flag("--quiet", &a.quiet, "no progress bars and no summary");
    add_renderer_options(parser, a.renderer);
    add_compensation_options(parser, a.compensation);
    add_caustics_option(parser, a.no_caustics);
    add_many_lights_options(parser, a.many_lights);
    add_max_depth_option(parser, a.settings.tracer.max_depth);
    add_seed_option(parser, a.settings.seed);
    add_camera_options(parser, a.camera);
    add_environment_options(parser, a.environment);
    add_scene_file_options(parser, a.scene_file);
    add_device_option(parser, a.device,
                      "Vulkan device index (see mvpl info), -1 = default; under mpirun "
                      "local-rank: by the rank's place on its machine",
                      "N|local-rank");
    add_examples(parser);
}

// --ref, or the mean of it and the --and-ref images, whose own share of relMSE goes to *noise
// (0 for one reference); checked against --res.
Image read_reference(const ConvergenceArgs& a, double* noise) {
    Image reference = read_finite_exr(a.ref_path);
    *noise = 0.0;
    if (!a.more_references.empty()) {
        std::vector<Image> references{reference};
        for (const std::string& path : a.more_references) {
            references.push_back(read_finite_exr(path));
            if (references.back().width() != reference.width() ||
                references.back().height() != reference.height())
                throw InputError(path, "size differs from --ref's");
        }
        reference = average_images(references);
        *noise = reference_noise(references);
    }
    if (a.width != 0 && (a.width != reference.width() || a.height != reference.height())) {
        throw UsageError("convergence: --res " + std::to_string(a.width) + "x" +
                         std::to_string(a.height) + " differs from the reference's " +
                         std::to_string(reference.width()) + "x" +
                         std::to_string(reference.height()));
    }
    return reference;
}

// What every rank reads before the runs: the methods, the reference and the scene.
struct ConvergenceInputs {
    std::vector<std::string> methods;
    Image reference;
    double noise = 0.0;  // the references' own share of relMSE
    std::unique_ptr<session::SceneSession> session;
};

// Parses and loads on every rank (an error on one is met by all); false after --help.
bool parse_and_load(const Args& args, ArgParser& parser, ConvergenceArgs& a, ConvergenceInputs& in,
                    cluster::Cluster& ranks) {
    bool parsed = false;
    cluster::together(ranks, [&] {
        parsed = parser.parse(with_local_rank_device(args));
        if (!parsed) return;
        check_device("convergence", a.device);
        in.methods = checked_methods(a.ref_path, a.budget, a.methods_text);
        in.reference = read_reference(a, &in.noise);
        in.session = std::make_unique<session::SceneSession>(
            a.scene_path, a.camera.choice, a.environment.choice, a.scene_file.options);
        apply_scene_defaults(parser, in.session->scene(), &a.settings.tracer.max_depth, nullptr,
                             nullptr);
        apply_vpl_integrator_defaults(parser, *in.session, a.settings.tracer.max_depth, a.renderer);
        if (ranks.root()) create_output_folder(a.out_dir);
    });
    return parsed;
}

// The run's parameters; settings and render_options get the VPL samplers' and the renderer's.
ConvergenceRun configure_run(ConvergenceArgs& a, const ConvergenceInputs& in,
                             render::RenderOptions& render_options, cluster::Cluster& ranks) {
    const session::SceneSession& session = *in.session;
    sampler::SamplerSettings& settings = a.settings;
    ConvergenceRun run;
    run.session = &session;
    run.reference = &in.reference;
    run.budget_seconds = a.budget;
    run.max_depth = settings.tracer.max_depth;
    run.seed = settings.seed;
    settings.width = in.reference.width();
    settings.height = in.reference.height();
    settings.clamp = a.renderer.clamp;
    settings.vsl_radius = a.renderer.vsl();
    a.renderer.apply(render_options);
    render_options.chains.max_depth = run.max_depth;
    render_options.interleave =
        a.renderer.interleave_for(session.scene(), render_options.chains, uint32_t(settings.width),
                                  uint32_t(settings.height));
    render_options.batches_per_position = a.renderer.batches_per_position_for(session.scene());
    settings.specular_chains = render_options.chains;  // the Metropolis target follows them too
    run.quiet = a.quiet;
    run.compensate = a.compensation.enabled();
    run.compensation_passes = uint32_t(a.compensation.spp);
    run.caustics = !a.no_caustics;
    run.many_lights = a.many_lights.options();
    run.cluster = &ranks;
    return run;
}

// Each method in turn, its points appended; the device and integrator are made for the first
// VPL sampler. Stops early, with the points so far, on SIGINT/SIGTERM on any rank.
std::vector<ConvergencePoint> run_methods(const ConvergenceArgs& a, const ConvergenceInputs& in,
                                          const ConvergenceRun& run,
                                          const render::RenderOptions& render_options,
                                          cluster::Cluster& ranks) {
    std::vector<ConvergencePoint> all;
    std::unique_ptr<gpu::Context> context;
    std::unique_ptr<integrator::VplIntegrator> vpl_integrator;
    for (const std::string& method : in.methods) {
        // SIGINT/SIGTERM on any rank (interrupt.h): the methods run so far are written.
        std::vector<double> stop(1, interrupted() ? 1.0 : 0.0);
        ranks.sum_all(stop);
        if (stop[0] > 0.0) break;
        std::vector<ConvergencePoint> points;
        if (method == "pt") {
            points = run_path_tracer(run);
        } else {
            if (!vpl_integrator) {
                cluster::together(ranks, [&] {
                    gpu::ContextOptions co;
                    co.device_index = a.device;
                    context = std::make_unique<gpu::Context>(co);
                });
                vpl_integrator = std::make_unique<integrator::VplIntegrator>(
                    in.session->view(), context.get(),
                    a.renderer.devices_for(context->device_info()), &ranks);
            }
            points = run_vpl_sampler(run, method, a.settings, *vpl_integrator, render_options);
        }
        all.insert(all.end(), points.begin(), points.end());
    }
    return all;
}

// DIR/convergence.csv and the plot, written by rank 0 (the others wait for it, so that all exit
// with its status), and the summary.
void write_outputs(const ConvergenceArgs& a, const ConvergenceInputs& in,
                   const std::vector<ConvergencePoint>& all, cluster::Cluster& ranks) {
    cluster::together(ranks, [&] {
        if (!ranks.root()) return;
        const std::filesystem::path csv = std::filesystem::path(a.out_dir) / "convergence.csv";
        // Whole or not at all, every write checked (atomic_files.h).
        const std::string text = to_csv(all);
        write_files_atomically({csv.string()}, [&](size_t, const std::string& temp) {
            write_bytes(temp,
                        std::span(reinterpret_cast<const uint8_t*>(text.data()), text.size()));
        });
        if (!a.quiet) print_summary(all, in.methods, in.noise);
        if (!a.no_plot) {
            const std::filesystem::path png = std::filesystem::path(a.out_dir) / "convergence.png";
            const std::string command =
                shell_quote(python_interpreter()) + " " + shell_quote(plot_script().string()) +
                " " + shell_quote(csv.string()) + " " + shell_quote(png.string()) + " --title " +
                shell_quote(std::filesystem::path(a.scene_path).stem().string());
            if (std::system(command.c_str()) != 0) {
                std::fprintf(stderr,
                             "mvpl: warning: the plot was not made (%s failed; python3-matplotlib "
                             "installed?); %s is written\n",
                             plot_script().string().c_str(), csv.string().c_str());
            }
        }
        if (!a.quiet) std::printf("convergence: wrote %s\n", csv.string().c_str());
    });
}

}  // namespace

int run_convergence(const Args& args) {
    cluster::Cluster& ranks = cluster::world();
    // SIGINT, SIGTERM: the methods and points so far are written (engine/core/interrupt.h).
    install_interrupt_handlers();
    ConvergenceArgs a;
    ArgParser parser(
        "convergence",
        "Error against run time: the reference path tracer and the VPL samplers,\n"
        "each run progressively up to --budget seconds against --ref; writes\n"
        "DIR/convergence.csv and DIR/convergence.png and prints, per VPL sampler, the\n"
        "speed-up over the path tracer at equal relMSE and the bias floor.\n"
        "Under mpirun, the ranks share each method's work and rank 0 writes.");
    add_options(parser, a);
    ConvergenceInputs in;
    if (!parse_and_load(args, parser, a, in, ranks)) return 0;
    // Rank 0 alone prints: progress, summary and the files written.
    if (!ranks.root()) a.quiet = true;
    render::RenderOptions render_options;
    const ConvergenceRun run = configure_run(a, in, render_options, ranks);
    write_outputs(a, in, run_methods(a, in, run, render_options, ranks), ranks);
    return 0;
}

}  // namespace mvpl::cli
