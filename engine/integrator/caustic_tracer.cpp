#include "engine/integrator/caustic_tracer.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "engine/core/parallel.h"
#include "engine/core/rng.h"
#include "engine/light/path_partition.h"
#include "engine/light/specular_chain.h"
#include "engine/reference/pass_mean.h"
#include "engine/scene/camera.h"
#include "engine/trace/interaction.h"
#include "engine/trace/ray.h"
#include "engine/trace/shading_point.h"

namespace mvpl::integrator {

using reference::PassMean;  // engine/reference/pass_mean.h

namespace {

// Light paths per work item of a pass: the unit of parallelism whose splats are summed in order,
// so that a pass is the same whatever the thread count.
constexpr uint64_t kBlockPaths = 256;
// Keeps the caustic tracer's streams apart from the clamping compensation's, which derives its
// pass seeds from the same user seed.
constexpr uint64_t kSeedSalt = 0xca057ca057ca057cULL;
// The camera ray through a splat's projection must meet its vertex: within this share of the
// distance (float rounding of two rays that meet at one point from different origins).
constexpr float kSameHitTolerance = 1e-3f;

struct Splat {
    size_t pixel = 0;
    Rgb value{0.0f};
};

// The caustic light one path brought (the luminance of its splats) and the emitter it left.
struct PathYield {
    int emitter = -1;
    double luminance = 0.0;
};

Vec2 next_2d(Rng& rng) {
    const float a = rng.next_float();
    return Vec2(a, rng.next_float());
}

}  // namespace

struct CausticTracer::Impl {
    const scene::Scene& scene;
    const trace::Accel& accel;
    const light::LightSampler& lights;
    CausticOptions options;
    scene::Camera camera;  // options.camera's, copied: the caller may move its own
    bool is_active = false;
    uint64_t paths_per_pass = 0;
    // The pinhole (header comment): the eye and 1/A_pix.
    Vec3 eye{0.0f};
    float inv_pixel_area = 1.0f;
    float d_min2 = 0.0f;     // the compensation's d_min² (header comment); 0 without it
    bool lobe_wise = false;  // the compensation's share is the diffuse lobes' alone
    // The emitters' probabilities after the pilot (header comment) and their running sum;
    // empty before it: by power.
    std::vector<float> pick;
    std::vector<float> pick_cdf;
    std::vector<Rgb> pass_image;  // the pass under way
    PassMean mean;                // of the passes done

    Impl(const scene::Scene& s, const trace::Accel& a, const light::LightSampler& l,
         const CausticOptions& o)
        : scene(s),
          accel(a),
          lights(l),
          options(o),
          camera(o.camera ? *o.camera : s.camera),
          pass_image(size_t(o.width) * size_t(o.height)),
          mean(o.width, o.height) {
        paths_per_pass = o.paths_per_pass > 0 ? o.paths_per_pass : uint64_t(pass_image.size());
        is_active = !l.empty() && (o.max_depth < 0 || o.max_depth >= 3) &&
                    light::scene_may_need_caustics(s, o.specular, l);
        eye = camera.position();
        const float tan_half = std::tan(0.5f * camera.yfov);
        const float aspect = float(o.width) / float(o.height);
        const float area = sqr(2.0f * tan_half) * aspect / (float(o.width) * float(o.height));
        inv_pixel_area = 1.0f / area;
        d_min2 = sqr(o.clamp * s.bounds().diagonal());
        lobe_wise = o.vsl_radius > 0.0f;
    }

    // β · f · |n_g·ω_cam| / d² · W_e of light-path vertex p lit from wi_world, into the pixel it
    // projects to, if the camera sees p there as a receiver (header comment).
    // `overlap` (per channel) times f_D (lobe_wise) or f at p is the compensation's share, left
    // out (header comment).
    void splat(const Vec3& p, const Vec3& wi_world, const Rgb& beta, const Rgb& overlap,
               std::vector<Splat>& out) const {
        const Vec3 from_eye = p - eye;
        const float d2 = glm::dot(from_eye, from_eye);
        if (!(d2 > 0.0f)) return;
        const std::optional<scene::FilmPoint> projected =
            scene::project_to_film(camera, options.width, options.height, p);
        // Behind the eye, or nearer than the near plane, where camera rays start.
        if (!projected || !(projected->cos_theta * std::sqrt(d2) > camera.znear)) return;
        const Vec2& film = projected->film;
        const float cos_theta = projected->cos_theta;
        if (!(film.x >= 0.0f && film.x < float(options.width) && film.y >= 0.0f &&
              film.y < float(options.height)))
            return;
        const scene::CameraRay cr =
            scene::generate_camera_ray(camera, options.width, options.height, film);
        const trace::Ray ray{cr.origin, cr.direction};
        const std::optional<trace::Hit> hit = accel.intersect_camera(ray);
        if (!hit) return;
        const float expected = glm::length(p - cr.origin);
        if (!(std::abs(hit->t - expected) <= kSameHitTolerance * expected)) return;
        // The receiver as the camera sees it (make_receiver's, whose side and class decide).
        const trace::SurfaceInteraction si = trace::make_interaction(scene, *hit, ray);
        const trace::ShadingPoint sp = trace::make_shading_point(accel.materials(), si);
        const Vec3 wo_world = -glm::normalize(cr.direction);
        const Vec3 wo = sp.frame.to_local(wo_world);
        if (!(wo.z > 0.0f) || light::continues_chain(sp.bsdf, wo, options.specular)) return;
        const Vec3 wi = sp.frame.to_local(wi_world);
        if (!trace::same_side(wi_world, sp.ng, wi.z)) return;
        const Rgb f = sp.bsdf.eval(wo, wi);
        if (is_black(f)) return;
        Rgb kept = beta * f;
        if (!is_black(overlap))
            kept = glm::max(kept - overlap * (lobe_wise ? sp.bsdf.eval_diffuse(wo, wi) : f),
                            Rgb(0.0f));
        const float importance = inv_pixel_area / (cos_theta * cos_theta * cos_theta);
        const Rgb value = kept * (std::abs(glm::dot(sp.ng, wo_world)) / d2 * importance);
        if (!is_finite(value)) return;
        const size_t x = std::min(size_t(film.x), size_t(options.width - 1));
        const size_t y = std::min(size_t(film.y), size_t(options.height - 1));
        out.push_back({y * size_t(options.width) + x, value});
    }

    // One light path, as sampler::LightTracer::trace walks it (the same throughput), splatting
    // every vertex whose previous one leaves no VPL that reflects towards it.
    // Returns the emitter it started from (−1: none).
    int trace_path(Rng& rng, std::vector<Splat>& out) const {
        const float u_pick = rng.next_float();
        const Vec2 u_pos = next_2d(rng);
        const Vec2 u_dir = next_2d(rng);
        std::optional<light::EmissionSample> es;
        if (pick_cdf.empty()) {
            es = lights.sample_le(u_pick, u_pos, u_dir);
        } else {
            const size_t e = std::min<size_t>(
                std::upper_bound(pick_cdf.begin(), pick_cdf.end(), u_pick) - pick_cdf.begin(),
                pick.size() - 1);
            es = lights.sample_le_from(int(e), pick[e], u_pos, u_dir);
        }
        if (!es) return -1;
        trace_from(*es, rng, out);
        return es->emitter;
    }

    void trace_from(const light::EmissionSample& es, Rng& rng, std::vector<Splat>& out) const {
        trace::Ray ray{es.p, es.direction};
        if (es.type == light::EmitterType::Triangle)
            ray = trace::spawn_ray(es.p, es.n, es.direction, accel.coordinate_scale());
        Rgb beta = es.throughput;
        const float beta_start = max_component(beta);
        if (!(beta_start > 0.0f) || !is_finite(beta)) return;
        // x_j lights the eye through j + 1 segments.
        const int max_length =
            options.max_depth < 0 ? std::numeric_limits<int>::max() : options.max_depth - 1;
        bool covered = true;  // x_0's emitter VPL lights x_1
        const light::ChainOptions vpl_class = light::path_chain_class(options.specular, es.type);
        Vec3 previous = es.p;
        Rgb previous_diffuse(0.0f);  // f_D/f of the last bounce (lobe-wise compensation)
        for (int length = 1; length <= max_length; ++length) {
            const std::optional<trace::Hit> hit = accel.intersect(ray);
            if (!hit) break;
            const trace::SurfaceInteraction si = trace::make_interaction(scene, *hit, ray);
            const trace::ShadingPoint sp = trace::make_shading_point(accel.materials(), si);
            const Vec3 wi_world = -glm::normalize(ray.direction);
            const Vec3 wi = sp.frame.to_local(wi_world);
            const float cos_geometric = glm::dot(wi_world, sp.ng);
            if (!(wi.z > 0.0f || sp.bsdf.transmits()) || !trace::same_side(wi_world, sp.ng, wi.z))
                break;
            beta *= wi.z / cos_geometric;  // shading cosine at arrival (light_tracer.h)
            if (!covered) {
                // The compensation's share is its own (header comment).
                const Vec3 d = sp.p - previous;
                const float d2 = glm::dot(d, d);
                const float near = d2 < d_min2 ? 1.0f - d2 / d_min2 : 0.0f;
                const Rgb overlap = near * (lobe_wise ? beta * previous_diffuse : beta);
                splat(sp.p, wi_world, beta, overlap, out);
            }
            previous = sp.p;
            if (length == max_length) break;

            const Vec2 u_bsdf = next_2d(rng);
            const float u_lobe = rng.next_float();
            const float u_rr = rng.next_float();
            const std::optional<material::BsdfSample> bs =
                sp.bsdf.sample(wi, u_bsdf, u_lobe, material::Transport::Importance);
            if (!bs) break;
            const Vec3 wo_world = sp.frame.to_world(bs->wi);
            if (!trace::same_side(wo_world, sp.ng, bs->wi.z)) break;
            beta *= bs->weight * (glm::dot(wo_world, sp.ng) / bs->wi.z);
            if (!is_finite(beta)) break;
            if (lobe_wise && d_min2 > 0.0f) {
                const Rgb f = sp.bsdf.eval(wi, bs->wi);
                const Rgb fd = sp.bsdf.eval_diffuse(wi, bs->wi);
                previous_diffuse =
                    Rgb(f.r > 0.0f ? fd.r / f.r : 0.0f, f.g > 0.0f ? fd.g / f.g : 0.0f,
                        f.b > 0.0f ? fd.b / f.b : 0.0f);
            }
            // A VPL here reflects towards the side it was lit on (path_partition.h).
            covered = light::leaves_vpl(sp.bsdf, wi, vpl_class) && bs->wi.z > 0.0f;
            if (length + 3 >= options.rr_depth) {
                const float survive = std::min(0.95f, max_component(beta) / beta_start);
                if (!(survive > 0.0f) || u_rr >= survive) break;
                beta /= survive;
            }
            ray = trace::spawn_ray(sp.p, sp.ng, wo_world, accel.coordinate_scale());
        }
    }

    // Global pass `global` into `image` (scaled by 1/paths); `yields`, if given, receives each
    // emitter's caustic light.
    void trace_pass(uint64_t global, std::vector<Rgb>& image, std::vector<double>* yields) const {
        std::fill(image.begin(), image.end(), Rgb(0.0f));
        const uint64_t seed = mix_bits(mix_bits(options.seed ^ kSeedSalt) ^ (global << 32));
        const uint64_t blocks = (paths_per_pass + kBlockPaths - 1) / kBlockPaths;
        std::vector<std::vector<Splat>> splats(blocks);
        std::vector<std::vector<PathYield>> path_yields(blocks);
        parallel_for(int64_t(blocks), 1, [&](int64_t b0, int64_t b1) {
            for (int64_t b = b0; b < b1; ++b) {
                std::vector<Splat>& out = splats[size_t(b)];
                const uint64_t first = uint64_t(b) * kBlockPaths;
                const uint64_t last = std::min(first + kBlockPaths, paths_per_pass);
                for (uint64_t i = first; i < last; ++i) {
                    Rng rng(seed, i);
                    const size_t before = out.size();
                    const int emitter = trace_path(rng, out);
                    if (!yields || out.size() == before) continue;
                    PathYield y{emitter, 0.0};
                    for (size_t k = before; k < out.size(); ++k)
                        y.luminance += double(luminance(out[k].value));
                    path_yields[size_t(b)].push_back(y);
                }
            }
        });
        const float scale = float(1.0 / double(paths_per_pass));
        for (const std::vector<Splat>& block : splats) {
            for (const Splat& sp : block)
                image[sp.pixel] += sp.value * scale;
        }
        if (!yields) return;
        for (const std::vector<PathYield>& block : path_yields) {
            for (const PathYield& y : block)
                (*yields)[size_t(y.emitter)] += y.luminance;
        }
    }

    // The mixture of the header comment from the pilot's per-emitter caustic light.
    void adapt(const std::vector<double>& yields) {
        double total = 0.0;
        for (double y : yields)
            total += y;
        const size_t n = lights.emitters().size();
        pick.assign(n, 0.0f);
        pick_cdf.assign(n, 0.0f);
        float running = 0.0f;
        for (size_t e = 0; e < n; ++e) {
            const float power = lights.pick_probability(int(e));
            pick[e] = total > 0.0 ? 0.5f * power + float(0.5 * yields[e] / total) : power;
            running += pick[e];
            pick_cdf[e] = running;
        }
        for (float& c : pick_cdf)
            c /= running;
    }

    void add_pass() {
        const uint32_t pass = mean.passes();
        std::fill(pass_image.begin(), pass_image.end(), Rgb(0.0f));
        if (is_active) {
            const uint64_t global =
                uint64_t(options.first_pass) + uint64_t(pass) * uint64_t(options.pass_stride);
            bool done = false;
            if (pick_cdf.empty()) {  // the pilot, global pass 0, first
                std::vector<double> yields(lights.emitters().size(), 0.0);
                trace_pass(0, pass_image, &yields);
                adapt(yields);
                done = global == 0;
            }
            if (!done) trace_pass(global, pass_image, nullptr);
        }
        mean.add(pass_image);
    }
};

CausticTracer::CausticTracer(const scene::Scene& scene, const trace::Accel& accel,
                             const light::LightSampler& lights, const CausticOptions& options)
    : m_impl(std::make_unique<Impl>(scene, accel, lights, options)) {}

CausticTracer::~CausticTracer() = default;

bool CausticTracer::active() const {
    return m_impl->is_active;
}

void CausticTracer::add_pass() {
    m_impl->add_pass();
}

uint32_t CausticTracer::passes() const {
    return m_impl->mean.passes();
}

Image CausticTracer::image(uint32_t* passes) const {
    return m_impl->mean.mean(passes);
}

}  // namespace mvpl::integrator
