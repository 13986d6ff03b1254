#include "engine/trace/interaction.h"

namespace mvpl::trace {

material::SurfacePoint surface_attributes(const scene::Mesh& mesh, int triangle, const Vec2& b) {
    const uint32_t* idx = &mesh.indices[3 * size_t(triangle)];
    const float b0 = 1.0f - b.x - b.y;
    material::SurfacePoint p;
    if (!mesh.uv0.empty())
        p.uv0 = b0 * mesh.uv0[idx[0]] + b.x * mesh.uv0[idx[1]] + b.y * mesh.uv0[idx[2]];
    if (!mesh.uv1.empty())
        p.uv1 = b0 * mesh.uv1[idx[0]] + b.x * mesh.uv1[idx[1]] + b.y * mesh.uv1[idx[2]];
    if (!mesh.colors.empty())
        p.color = b0 * mesh.colors[idx[0]] + b.x * mesh.colors[idx[1]] + b.y * mesh.colors[idx[2]];
    return p;
}

SurfaceInteraction make_interaction(const scene::Scene& scene, const Hit& hit, const Ray& ray) {
    const scene::Mesh& mesh = scene.meshes[hit.mesh];
    const uint32_t i0 = mesh.indices[3 * hit.triangle + 0];
    const uint32_t i1 = mesh.indices[3 * hit.triangle + 1];
    const uint32_t i2 = mesh.indices[3 * hit.triangle + 2];
    const float b1 = hit.barycentric.x;
    const float b2 = hit.barycentric.y;
    const float b0 = 1.0f - b1 - b2;

    SurfaceInteraction si;
    si.mesh = hit.mesh;
    si.triangle = hit.triangle;
    si.material = mesh.material;
    const Vec3& p0 = mesh.positions[i0];
    const Vec3& p1 = mesh.positions[i1];
    const Vec3& p2 = mesh.positions[i2];
    // Interpolating the vertices is more accurate than origin + t·direction far from the origin.
    si.p = b0 * p0 + b1 * p1 + b2 * p2;
    const Vec3 e1 = p1 - p0;
    const Vec3 e2 = p2 - p0;
    const Vec3 cross = glm::cross(e1, e2);
    const float len = glm::length(cross);
    si.ng = len > 0.0f ? cross / len : -glm::normalize(ray.direction);
    si.front_face = glm::dot(ray.direction, si.ng) < 0.0f;

    Vec3 ns = si.ng;
    if (!mesh.normals.empty()) {
        const Vec3 n = b0 * mesh.normals[i0] + b1 * mesh.normals[i1] + b2 * mesh.normals[i2];
        const float nlen = glm::length(n);
        if (nlen > 0.0f && std::isfinite(nlen)) ns = n / nlen;
    }
    if (glm::dot(ns, si.ng) < 0.0f) ns = -ns;
    si.ns = ns;

    const material::SurfacePoint attributes =
        surface_attributes(mesh, hit.triangle, hit.barycentric);
    si.uv0 = attributes.uv0;
    si.uv1 = attributes.uv1;
    si.color = attributes.color;

    // Tangent: the file's TANGENT if present, else ∂p/∂u of the UV parametrisation (pbrt-v3
    // §3.6.2), else any vector perpendicular to the normal.
    Vec3 dpdu(0.0f);
    if (!mesh.tangents.empty()) {
        const Vec4 t = b0 * mesh.tangents[i0] + b1 * mesh.tangents[i1] + b2 * mesh.tangents[i2];
        dpdu = Vec3(t);
        si.tangent_sign = mesh.tangents[i0].w < 0.0f ? -1.0f : 1.0f;
    } else if (!mesh.uv0.empty()) {
        const Vec2 duv02 = mesh.uv0[i0] - mesh.uv0[i2];
        const Vec2 duv12 = mesh.uv0[i1] - mesh.uv0[i2];
        const float det = duv02.x * duv12.y - duv02.y * duv12.x;
        if (std::abs(det) > 1e-12f) {
            dpdu = ((p0 - p2) * duv12.y - (p1 - p2) * duv02.y) / det;
        }
    }
    // Gram-Schmidt against the shading normal; fall back to an arbitrary frame when degenerate.
    dpdu -= ns * glm::dot(ns, dpdu);
    const float tlen = glm::length(dpdu);
    si.dpdu = tlen > 1e-20f && std::isfinite(tlen) ? dpdu / tlen : Frame(ns).s;
    return si;
}

}  // namespace mvpl::trace
