// `mvpl vpls`: where a sampler puts its VPLs (the seed's Figure 4a/b) — VPL positions drawn as
// dots over a flat-shaded CPU view of the scene, from above (a cutaway: back faces are skipped,
// so closed rooms show their floors) or from the scene camera.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

#include "engine/core/error.h"
#include "engine/core/image.h"
#include "engine/core/timer.h"
#include "engine/light/chain_options.h"
#include "engine/sampler/sampler_factory.h"
#include "engine/scene/camera.h"
#include "engine/trace/accel.h"
#include "engine/trace/interaction.h"
#include "engine/trace/ray.h"
#include "tools/cli/arg_parser.h"
#include "tools/cli/commands.h"
#include "tools/cli/exr_outputs.h"
#include "tools/cli/option_groups.h"
#include "tools/cli/output_check.h"
#include "tools/session/scene_session.h"
#include "tools/session/vpl_dots.h"

namespace mvpl::cli {

namespace {

// The first front-facing hit along `ray` (back faces are looked through, at most 32 of them).
std::optional<trace::SurfaceInteraction> first_front_hit(const scene::Scene& scene,
                                                         const trace::Accel& accel,
                                                         trace::Ray ray) {
    for (int i = 0; i < 32; ++i) {
        const std::optional<trace::Hit> hit = accel.intersect(ray);
        if (!hit) return std::nullopt;
        const trace::SurfaceInteraction si = trace::make_interaction(scene, *hit, ray);
        if (si.front_face) return si;
        ray = trace::spawn_ray(si.p, -si.ng, ray.direction, accel.coordinate_scale());
    }
    return std::nullopt;
}

// A view: film position of a world point (false when it is behind the view) and the ray
// through a pixel.
struct View {
    bool top = true;
    int width = 512, height = 512;
    // top: x → column, z → row over [lo, lo + extent·(w, h)]
    float x0 = 0.0f, z0 = 0.0f, metres_per_pixel = 1.0f, y_above = 1.0f;
    scene::Camera camera;

    trace::Ray ray(float px, float py) const {
        if (top) {
            const Vec3 o(x0 + px * metres_per_pixel, y_above, z0 + py * metres_per_pixel);
            return trace::Ray{o, Vec3(0.0f, -1.0f, 0.0f)};
        }
        const scene::CameraRay cr = scene::generate_camera_ray(camera, width, height, {px, py});
        return trace::Ray{cr.origin, cr.direction};
    }
    bool project(const Vec3& p, Vec2& film) const {
        if (top) {
            film = Vec2((p.x - x0) / metres_per_pixel, (p.z - z0) / metres_per_pixel);
            return true;
        }
        const std::optional<scene::FilmPoint> projected =
            scene::project_to_film(camera, width, height, p);
        if (!projected) return false;
        film = projected->film;
        return true;
    }
};

View make_view(const scene::Scene& scene, bool top, int width, int height) {
    View v;
    v.top = top;
    v.width = width;
    v.height = height;
    v.camera = scene.camera;
    const scene::Bounds b = scene.bounds();
    const float ex = std::max(b.hi.x - b.lo.x, 1e-6f), ez = std::max(b.hi.z - b.lo.z, 1e-6f);
    // Fit the x–z extent with a 4% margin, centred.
    v.metres_per_pixel = 1.04f * std::max(ex / float(width), ez / float(height));
    v.x0 = 0.5f * (b.lo.x + b.hi.x) - 0.5f * float(width) * v.metres_per_pixel;
    v.z0 = 0.5f * (b.lo.z + b.hi.z) - 0.5f * float(height) * v.metres_per_pixel;
    v.y_above = b.hi.y + 0.01f * std::max(b.diagonal(), 1e-3f);
    return v;
}

// The scene as the view sees it, flat grey.
Image flat_view(const scene::Scene& scene, const trace::Accel& accel, const View& view) {
    Image image(view.width, view.height);
    for (int y = 0; y < view.height; ++y) {
        for (int x = 0; x < view.width; ++x) {
            const trace::Ray ray = view.ray(float(x) + 0.5f, float(y) + 0.5f);
            const auto si = first_front_hit(scene, accel, ray);
            // Flat grey by the angle to the view direction: walls and floors stay apart.
            const float shade =
                si ? 0.05f + 0.25f * std::abs(glm::dot(si->ng, glm::normalize(ray.direction)))
                   : 0.0f;
            image.at(x, y) = Rgb(shade);
        }
    }
    return image;
}

}  // namespace

int run_vpls(const Args& args) {
    std::string scene_path, sampler_name = "mc", view_name = "top";
    uint64_t count = 1024;
    int width = 512, height = 512;
    std::vector<std::string> outputs;
    bool quiet = false;
    sampler::SamplerSettings settings;
    ArgParser parser("vpls",
                     "Draws where a sampler puts its VPLs: dots over a flat-shaded view of SCENE\n"
                     "(top: from above, back faces cut away; camera: the scene camera).\n"
                     "Dot area and colour grow with power (red: the largest; yellow, green, blue:\n"
                     "1/10, 1/100, 1/1000 of it); emitter VPLs ringed white.");
    parser.add_positional("SCENE", &scene_path, "scene (.gltf, .glb, .xml, .ply, .obj)");
    parser.begin_group("VPLs options");  // not "Vpls", the command's name capitalised
    parser.add_uint64("--vpls", &count, "light paths (mc) or chain steps (metropolis)");
    parser.add_string("--view", &view_name, "top (default) or camera", "top|camera");
    parser.add_resolution("--res", &width, &height, "image size");
    parser.add_strings("-o", &outputs, "output image, .png or .exr", "FILE");
    parser.add_flag("--quiet", &quiet, "no summary line");
    add_sampler_option(parser, sampler_name);
    add_metropolis_options(parser, settings);
    add_max_depth_option(parser, settings.tracer.max_depth);
    add_seed_option(parser, settings.seed);
    CameraArgs camera;
    add_camera_options(parser, camera);
    EnvironmentArgs environment;
    add_environment_options(parser, environment);
    SceneFileArgs scene_file;
    add_scene_file_options(parser, scene_file);
    if (!parser.parse(args)) return 0;
    const Timer wall;
    if (view_name != "top" && view_name != "camera")
        throw UsageError("vpls: --view must be top or camera");
    if (count < 1 || count > (uint64_t(1) << 24))
        throw UsageError("vpls: --vpls must be in 1..2^24");
    bool defaulted = false;
    outputs = outputs_or(outputs, "vpls.png", defaulted);
    check_outputs(outputs);

    const session::SceneSession session(scene_path, camera.choice, environment.choice,
                                        scene_file.options);
    apply_scene_defaults(parser, session.scene(), &settings.tracer.max_depth, &width, &height);
    // The Metropolis target follows the specular chains that `mvpl render` traces by default.
    settings.specular_chains.max_roughness = light::kDefaultChainRoughness;
    settings.specular_chains.max_depth = settings.tracer.max_depth;
    const scene::Scene& scene = session.scene();
    const trace::Accel& accel = session.accel();
    // The Metropolis target is the scene camera's view, whatever this picture shows.
    std::unique_ptr<sampler::VplStream> stream = sampler::make_vpl_stream(
        sampler_name, scene, accel, session.lights(), session.camera(), settings);
    std::vector<light::Vpl> vpls;
    stream->next(count, vpls);

    const View view = make_view(scene, view_name == "top", width, height);
    Image image = flat_view(scene, accel, view);
    const size_t drawn = session::draw_vpls(
        image, [&view](const Vec3& p, Vec2& film) { return view.project(p, film); }, vpls);
    ExrExtras extras;
    extras.attributes =
        run_attributes({"vpls", &args, settings.seed, vpls.size(), std::nullopt, wall.seconds()});
    write_images(image, outputs, 0.0f, extras);
    say_written("vpls", outputs, defaulted, quiet);
    if (!quiet) {
        const std::string stats = stream->statistics();
        std::printf("vpls: %zu VPLs (%zu drawn) from %llu %s%s%s\n", vpls.size(), drawn,
                    static_cast<unsigned long long>(stream->work_done()),
                    sampler_name == "mc" ? "paths" : "steps", stats.empty() ? "" : "; ",
                    stats.c_str());
    }
    return 0;
}

}  // namespace mvpl::cli
