#include "tests/sampler/vpl_test_util.h"

#include <cmath>

#include "engine/light/light_sampler.h"
#include "engine/reference/vpl_gather.h"
#include "engine/trace/accel.h"
#include "tests/support/scene_builder.h"

namespace mvpl::test {

scene::Scene area_lit_plane() {
    scene::Scene s;
    s.materials.push_back(diffuse_material(Rgb(0.6f)));
    scene::Material light = diffuse_material(Rgb(0.0f));
    light.emissive = Rgb(4.0f, 3.0f, 2.0f);
    s.materials.push_back(light);
    s.meshes.push_back(make_quad(Vec3(-2, 0, -2), Vec3(0, 0, 4), Vec3(4, 0, 0), 0));
    // cross(a, b) = (1,0,0)×(0,0,1) = (0,−1,0): facing down onto the plane.
    s.meshes.push_back(make_quad(Vec3(-0.4f, 1.0f, -0.4f), Vec3(0.8f, 0, 0), Vec3(0, 0, 0.8f), 1));
    s.camera = look_at(Vec3(0.0f, 0.8f, 2.2f), Vec3(0.0f, 0.0f, 0.0f), 0.7f);
    s.has_camera = true;
    return s;
}

BatchedImage batched_oracle(const scene::Scene& scene, sampler::MonteCarloOptions options,
                            int batches, int resolution, int max_depth, bool jitter) {
    const trace::Accel accel(scene);
    const light::LightSampler lights(scene);
    const sampler::MonteCarloSampler mc(scene, accel, lights);
    reference::GatherOptions g;
    g.width = g.height = resolution;
    g.max_depth = max_depth;
    g.clamp = 0.0f;
    g.subpixel.jitter = jitter;
    options.tracer.max_depth = max_depth;
    BatchedImage out;
    const uint64_t seed = options.seed;
    for (int b = 0; b < batches; ++b) {
        options.seed = seed + uint64_t(b);
        out.batches.push_back(reference::gather_vpls(scene, accel, mc.generate(options), g));
    }
    out.mean = Image(resolution, resolution);
    out.standard_error = Image(resolution, resolution);
    for (size_t i = 0; i < out.mean.pixels().size(); ++i) {
        DVec3 sum(0.0), sum2(0.0);
        for (const Image& im : out.batches) {
            const DVec3 v(im.pixels()[i]);
            sum += v;
            sum2 += v * v;
        }
        const DVec3 mean = sum / double(batches);
        const DVec3 var = glm::max(
            DVec3(0.0), (sum2 - double(batches) * mean * mean) / double(std::max(batches - 1, 1)));
        out.mean.pixels()[i] = Rgb(mean);
        out.standard_error.pixels()[i] = Rgb(glm::sqrt(var / double(batches)));
    }
    return out;
}

Rgb mean_standard_error(const BatchedImage& b) {
    const int n = int(b.batches.size());
    DVec3 sum(0.0), sum2(0.0);
    for (const Image& im : b.batches) {
        const DVec3 m(im.mean());
        sum += m;
        sum2 += m * m;
    }
    const DVec3 mean = sum / double(n);
    const DVec3 var =
        glm::max(DVec3(0.0), (sum2 - double(n) * mean * mean) / double(std::max(n - 1, 1)));
    return Rgb(glm::sqrt(var / double(n)));
}

}  // namespace mvpl::test
