#include "engine/render/vpl_culling.h"

#include <algorithm>
#include <array>

#include "engine/scene/camera.h"

namespace mvpl::render {

VplCulling::VplCulling(const scene::Scene& scene) {
    m_margin = 1e-5f * scene.bounds().diagonal();
    for (const scene::Mesh& mesh : scene.meshes) {
        const size_t triangles = mesh.triangle_count();
        for (size_t first = 0; first < triangles; first += kChunkTriangles) {
            const size_t end = std::min(triangles, first + kChunkTriangles);
            Vec3 lo(1e30f), hi(-1e30f);
            for (size_t i = 3 * first; i < 3 * end; ++i) {
                lo = glm::min(lo, mesh.positions[mesh.indices[i]]);
                hi = glm::max(hi, mesh.positions[mesh.indices[i]]);
            }
            m_chunks.push_back({0.5f * (lo + hi), 0.5f * (hi - lo) + Vec3(m_margin)});
        }
    }
    m_visible = m_chunks;
}

void VplCulling::set_view(const scene::Camera& camera, uint32_t width, uint32_t height) {
    // The frustum's four side planes through the eye, from the rays through the image's corners
    // (sub-pixel positions lie inside them); inward normals.
    const Vec3 eye = camera.position();
    const float w = float(width), h = float(height);
    const std::array<Vec2, 4> corners = {Vec2(0, 0), Vec2(w, 0), Vec2(w, h), Vec2(0, h)};
    std::array<Vec3, 4> d;
    for (size_t i = 0; i < 4; ++i)
        d[i] = scene::generate_camera_ray(camera, int(width), int(height), corners[i]).direction;
    const Vec3 centre =
        scene::generate_camera_ray(camera, int(width), int(height), Vec2(0.5f * w, 0.5f * h))
            .direction;
    std::array<Vec3, 4> planes;
    for (size_t i = 0; i < 4; ++i) {
        Vec3 n = glm::normalize(glm::cross(d[i], d[(i + 1) % 4]));
        if (glm::dot(n, centre) < 0.0f) n = -n;
        planes[i] = n;
    }
    m_visible.clear();
    for (const Box& b : m_chunks) {
        bool inside = b.support(centre, eye) >= 0.0f;  // not wholly behind the eye
        for (const Vec3& n : planes)
            inside = inside && b.support(n, eye) >= 0.0f;
        if (inside) m_visible.push_back(b);
    }
}

bool VplCulling::may_reach_view(const light::Vpl& vpl) const {
    if (vpl.type != light::VplType::Area && vpl.type != light::VplType::Surface) return true;
    // n·(x − p) ≤ 0 at every point x of every visible box means max(0, n·ω) = 0 there.
    return std::any_of(m_visible.begin(), m_visible.end(), [&](const Box& b) {
        return b.support(vpl.normal, vpl.position) + m_margin > 0.0f;
    });
}

}  // namespace mvpl::render
