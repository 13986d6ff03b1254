#include "tests/render/render_test_util.h"

#include "engine/material/graph_eval.h"

#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

#include "engine/material/bsdf.h"
#include "engine/scene/camera.h"

namespace mvpl::render::testing {
namespace {

using DVec3 = glm::dvec3;

// Möller–Trumbore in double: the reference must be more accurate than the rasteriser.
struct TriangleHit {
    double t, u, v;  // distance and the barycentrics of p1 and p2
};

std::optional<TriangleHit> intersect(const DVec3& o, const DVec3& d, const DVec3& p0,
                                     const DVec3& p1, const DVec3& p2) {
    const DVec3 e1 = p1 - p0;
    const DVec3 e2 = p2 - p0;
    const DVec3 pv = glm::cross(d, e2);
    const double det = glm::dot(e1, pv);
    if (std::abs(det) < 1e-300) return std::nullopt;
    const DVec3 tv = o - p0;
    const double u = glm::dot(tv, pv) / det;
    if (u < 0.0 || u > 1.0) return std::nullopt;
    const DVec3 qv = glm::cross(tv, e1);
    const double v = glm::dot(d, qv) / det;
    if (v < 0.0 || u + v > 1.0) return std::nullopt;
    const double t = glm::dot(e2, qv) / det;
    return t > 0.0 ? std::optional<TriangleHit>(TriangleHit{t, u, v}) : std::nullopt;
}

}  // namespace

std::optional<CpuHit> cast_camera_ray(const scene::Scene& scene, int width, int height, int x,
                                      int y, Vec2 subpixel) {
    const scene::CameraRay ray = scene::generate_camera_ray(
        scene.camera, width, height, Vec2(float(x) + subpixel.x, float(y) + subpixel.y));
    const DVec3 o(ray.origin);
    const DVec3 d(ray.direction);
    std::optional<CpuHit> best;
    double best_t = 1e300;
    for (size_t m = 0; m < scene.meshes.size(); ++m) {
        const scene::Mesh& mesh = scene.meshes[m];
        for (size_t t = 0; t < mesh.triangle_count(); ++t) {
            const DVec3 p0(mesh.positions[mesh.indices[3 * t]]);
            const DVec3 p1(mesh.positions[mesh.indices[3 * t + 1]]);
            const DVec3 p2(mesh.positions[mesh.indices[3 * t + 2]]);
            const std::optional<TriangleHit> hit = intersect(o, d, p0, p1, p2);
            if (!hit || hit->t >= best_t) continue;
            best_t = hit->t;
            const DVec3 ng = glm::normalize(glm::cross(p1 - p0, p2 - p0));
            // As trace::make_interaction: the interpolated normal on the winding normal's side.
            DVec3 ns = ng;
            if (!mesh.normals.empty()) {
                const DVec3 n = (1.0 - hit->u - hit->v) * DVec3(mesh.normals[mesh.indices[3 * t]]) +
                                hit->u * DVec3(mesh.normals[mesh.indices[3 * t + 1]]) +
                                hit->v * DVec3(mesh.normals[mesh.indices[3 * t + 2]]);
                ns = glm::normalize(n);
                if (glm::dot(ns, ng) < 0.0) ns = -ns;
            }
            best = CpuHit{Vec3(o + hit->t * d), Vec3(ng), Vec3(ns), int(m), glm::dot(d, ng) < 0.0};
        }
    }
    return best;
}

bool segment_hits_mesh(const scene::Mesh& mesh, const Vec3& a, const Vec3& b) {
    const DVec3 o(a);
    const DVec3 d = DVec3(b) - o;
    for (size_t t = 0; t < mesh.triangle_count(); ++t) {
        const std::optional<TriangleHit> hit =
            intersect(o, d, DVec3(mesh.positions[mesh.indices[3 * t]]),
                      DVec3(mesh.positions[mesh.indices[3 * t + 1]]),
                      DVec3(mesh.positions[mesh.indices[3 * t + 2]]));
        if (hit && hit->t < 1.0) return true;
    }
    return false;
}

namespace {

// The virtual sphere's lobe (light/virtual_sphere.h), written out from its formula: the GGX α
// (perceptual roughness squared) widened to √(α² + r²/(4 max(d², r²))), at most 1.
material::ClosureParams sphere_lobe(material::ClosureParams c, float radius, float d2) {
    if (radius <= 0.0f || c.is_lambertian()) return c;
    const float roughness = std::clamp(c.roughness, 0.0f, 1.0f);
    const float alpha = std::max(roughness * roughness, 1e-4f);
    const float widened = std::min(
        1.0f, std::sqrt(alpha * alpha + radius * radius / (4.0f * std::max(d2, radius * radius))));
    c.roughness = std::sqrt(widened);
    return c;
}

}  // namespace

Rgb cpu_contribution(const light::Vpl& vpl, const Vec3& p, const Vec3& n,
                     const material::ClosureParams& receiver_closure, const Vec3& camera,
                     float d_min, float vsl_radius, bool clamp_whole) {
    const bool sphere = vpl.type == light::VplType::Area || vpl.type == light::VplType::Surface;
    const float vpl_d2 = glm::dot(p - vpl.position, p - vpl.position);
    const material::ClosureParams receiver =
        sphere ? sphere_lobe(receiver_closure, vsl_radius, vpl_d2) : receiver_closure;
    const material::Bsdf f_r(receiver);
    const Frame frame(n);
    const Vec3 wo = frame.to_local(glm::normalize(camera - p));
    if (vpl.type == light::VplType::Directional) {
        const Vec3 to_light = -vpl.normal;
        const float cos_r = std::max(0.0f, glm::dot(n, to_light));
        return vpl.power * f_r.eval(wo, frame.to_local(to_light)) * cos_r;
    }
    const Vec3 r = p - vpl.position;
    const float d2 = glm::dot(r, r);
    const Vec3 w = r / std::sqrt(d2);
    const float cos_r = std::max(0.0f, glm::dot(n, -w));
    const Vec3 wi = frame.to_local(-w);
    // The VPL's own factor, and the part of it through its diffuse lobe (an area VPL's emission
    // counts as diffuse).
    Rgb factor(1.0f), factor_diffuse(1.0f);
    switch (vpl.type) {
        case light::VplType::Spot: {
            const float scale = 1.0f / std::max(1e-3f, vpl.cos_inner - vpl.cos_outer);
            const float t =
                std::clamp((glm::dot(vpl.normal, w) - vpl.cos_outer) * scale, 0.0f, 1.0f);
            factor = factor_diffuse = Rgb(t * t);
            break;
        }
        case light::VplType::Area:
            factor = factor_diffuse = Rgb(std::max(0.0f, glm::dot(vpl.normal, w)));
            break;
        case light::VplType::Surface: {
            const Frame vpl_frame(vpl.shading_normal);
            const Vec3 v_in = vpl_frame.to_local(vpl.wi);
            const Vec3 v_out = vpl_frame.to_local(w);
            const float cos_j = std::max(0.0f, glm::dot(vpl.normal, w));
            factor =
                material::Bsdf(sphere_lobe(vpl.closure, vsl_radius, d2)).eval(v_in, v_out) * cos_j;
            factor_diffuse = material::Bsdf(vpl.closure).eval_diffuse(v_in, v_out) * cos_j;
            break;
        }
        default:
            break;
    }
    const Rgb all = vpl.power * f_r.eval(wo, wi) * factor * cos_r;
    const float d_min2 = d_min * d_min;
    const float r2 = vsl_radius * vsl_radius;
    if (!sphere || !(r2 > 0.0f) || !(d_min2 > 0.0f) || clamp_whole)
        return all / std::max(d2, d_min2);
    // Lobe by lobe (vpl.h): the diffuse × diffuse product clamped at d_min, the rest at
    // min(r, d_min).
    const Rgb diffuse =
        vpl.power * material::Bsdf(receiver_closure).eval_diffuse(wo, wi) * factor_diffuse * cos_r;
    return diffuse / std::max(d2, d_min2) +
           glm::max(all - diffuse, Rgb(0.0f)) / std::max(d2, std::min(r2, d_min2));
}

material::ClosureParams closure_of(const scene::Material& m) {
    // The graph with no texture bound reads each texture as its factor.
    return material::evaluate_closure(material::graph_from_gltf(m), {}, material::SurfacePoint{});
}

}  // namespace mvpl::render::testing
