#pragma once
// The ground truth: a unidirectional path tracer with next-event estimation to every light type and
// multiple importance sampling against BSDF sampling for area lights (Veach 1997, power heuristic),
// on the same CPU material evaluators the VPL methods use.
#include <cstdint>
#include <functional>

#include "engine/core/image.h"
#include "engine/core/image_size.h"
#include "engine/core/progress.h"
#include "engine/core/rng.h"
#include "engine/light/light_sampler.h"
#include "engine/light/path_depth.h"
#include "engine/reference/path_film.h"
#include "engine/scene/scene.h"
#include "engine/trace/accel.h"

namespace mvpl::reference {

struct PathTracerOptions {
    int width = int(kDefaultImageWidth);
    int height = int(kDefaultImageHeight);
    int spp = 64;
    // Mitsuba's max_depth: segments from the camera to the light (1 = emitters seen directly,
    // 2 = direct light only); negative = unlimited (Russian roulette ends the paths).
    int max_depth = light::kDefaultMaxDepth;
    // Russian roulette starts once a path has this many segments.
    int rr_depth = light::kDefaultRrDepth;
    uint64_t seed = 0;
    bool quiet = false;
};

// Summed over the calls that filled a film (PathTracer::advance).
struct RenderStats {
    double seconds = 0.0;
    uint64_t rays = 0;
    uint64_t paths = 0;
    uint64_t nonfinite_samples = 0;  // discarded samples that were NaN or infinite
};

// What the first vertex a ray meets may scatter: all of its BSDF, or its diffuse lobe alone
// (material::Bsdf::eval_diffuse; its emission still counts) for the radiance that leaves it
// through that lobe, which the lobe-wise clamp's compensation needs
// (integrator/clamp_compensation.h). Deeper vertices always scatter through the whole BSDF.
enum class FirstVertex { AllLobes, DiffuseLobe };

// Called once per camera sample with its pixel, its index in the pixel and its film point
// (pixels, scene::generate_camera_ray), from the thread that renders the pixel: what the AOVs
// average over (engine/aov), so that they see the image's own sub-pixel positions.
using CameraSampleHook = std::function<void(int x, int y, int sample, const Vec2& film)>;

class PathTracer {
public:
    PathTracer(const scene::Scene& scene, const trace::Accel& accel,
               const light::LightSampler& lights);

    // Box-filtered image, deterministic for a seed whatever the thread count.
    Image render(const PathTracerOptions& options, RenderStats* stats = nullptr,
                 const CameraSampleHook& on_sample = {}) const;
    // `spp` more samples in every pixel of `film` (options.width × options.height, seeded with
    // options.seed), added to `stats`; `progress`, if given, advances by `spp` per row. Films
    // advanced to the same count hold the same sums whatever the chunks (path_film.h).
    void advance(PathFilm& film, int spp, const PathTracerOptions& options, RenderStats* stats,
                 const CameraSampleHook& on_sample = {}, Progress* progress = nullptr) const;
    // Host bytes a render with `options` holds at its peak, written out included: checked
    // against host_memory_bytes() before rendering (host_memory.h).
    static uint64_t host_bytes(const PathTracerOptions& options);
    // Radiance arriving along one ray: a camera ray (which does not see the back faces of
    // one-sided materials), or from_camera false for one leaving a surface (clamping
    // compensation), whose max_depth counts its segments from there.
    Rgb radiance(const trace::Ray& ray, Rng& rng, int max_depth, int rr_depth,
                 bool from_camera = true, FirstVertex first = FirstVertex::AllLobes) const;

private:
    const scene::Scene& m_scene;
    const trace::Accel& m_accel;
    const light::LightSampler& m_lights;
};

}  // namespace mvpl::reference
