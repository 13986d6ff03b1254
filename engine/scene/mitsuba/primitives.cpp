#include "engine/scene/mitsuba/primitives.h"

#include <cmath>

namespace mvpl::scene::mitsuba {

namespace {

// Segments round a full circle. The inscribed polygon's area falls short of the circle's by
// 1 − sin(2π/n)/(2π/n) ≈ (2π/n)²/6 = 1.0·10⁻⁴ for n = 256 (and the sphere's by about as much
// again from its rings): below anything a preview shows.
constexpr int kSegments = 256;
constexpr int kRings = 128;

void add_quad(Mesh& m, uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
    m.indices.insert(m.indices.end(), {a, b, c, a, c, d});
}

}  // namespace

Mesh rectangle_mesh() {
    Mesh m;
    m.name = "rectangle";
    for (const Vec2& p : {Vec2(-1, -1), Vec2(1, -1), Vec2(1, 1), Vec2(-1, 1)}) {
        m.positions.emplace_back(p, 0.0f);
        m.normals.emplace_back(0.0f, 0.0f, 1.0f);
        m.uv0.push_back((p + 1.0f) * 0.5f);
    }
    add_quad(m, 0, 1, 2, 3);
    return m;
}

Mesh cube_mesh() {
    Mesh m;
    m.name = "cube";
    for (int axis = 0; axis < 3; ++axis) {
        for (float sign : {-1.0f, 1.0f}) {
            Vec3 n(0.0f);
            n[axis] = sign;
            // Two tangents so that (t, b, n) is right-handed: counter-clockwise seen from outside.
            Vec3 t(0.0f), b(0.0f);
            t[(axis + 1) % 3] = 1.0f;
            b[(axis + 2) % 3] = sign;
            const uint32_t base = uint32_t(m.positions.size());
            for (const Vec2& c : {Vec2(-1, -1), Vec2(1, -1), Vec2(1, 1), Vec2(-1, 1)}) {
                m.positions.push_back(n + c.x * t + c.y * b);
                m.normals.push_back(n);
                m.uv0.push_back((c + 1.0f) * 0.5f);
            }
            add_quad(m, base, base + 1, base + 2, base + 3);
        }
    }
    return m;
}

Mesh sphere_mesh() {
    Mesh m;
    m.name = "sphere";
    for (int i = 0; i <= kRings; ++i) {
        const float v = float(i) / float(kRings);
        const float theta = v * kPi;
        for (int j = 0; j <= kSegments; ++j) {
            const float u = float(j) / float(kSegments);
            const float phi = u * 2.0f * kPi;
            const Vec3 n(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                         std::cos(theta));
            m.positions.push_back(n);
            m.normals.push_back(n);
            m.uv0.emplace_back(u, v);
        }
    }
    const uint32_t row = kSegments + 1;
    for (uint32_t i = 0; i < uint32_t(kRings); ++i) {
        for (uint32_t j = 0; j < uint32_t(kSegments); ++j) {
            const uint32_t a = i * row + j, b = a + 1, c = a + row + 1, d = a + row;
            // θ grows downward from +z, φ counter-clockwise about +z: (a, d, c, b) faces out.
            if (i > 0) m.indices.insert(m.indices.end(), {a, d, b});
            if (i + 1 < uint32_t(kRings)) m.indices.insert(m.indices.end(), {b, d, c});
        }
    }
    return m;
}

Mesh disk_mesh() {
    Mesh m;
    m.name = "disk";
    m.positions.emplace_back(0.0f);
    m.normals.emplace_back(0.0f, 0.0f, 1.0f);
    m.uv0.emplace_back(0.0f, 0.0f);
    for (int j = 0; j <= kSegments; ++j) {
        const float u = float(j) / float(kSegments);
        const float phi = u * 2.0f * kPi;
        m.positions.emplace_back(std::cos(phi), std::sin(phi), 0.0f);
        m.normals.emplace_back(0.0f, 0.0f, 1.0f);
        m.uv0.emplace_back(1.0f, u);
    }
    for (uint32_t j = 1; j <= uint32_t(kSegments); ++j)
        m.indices.insert(m.indices.end(), {0u, j, j + 1});
    return m;
}

Mesh cylinder_mesh() {
    Mesh m;
    m.name = "cylinder";
    for (int j = 0; j <= kSegments; ++j) {
        const float u = float(j) / float(kSegments);
        const float phi = u * 2.0f * kPi;
        const Vec3 n(std::cos(phi), std::sin(phi), 0.0f);
        for (float z : {0.0f, 1.0f}) {
            m.positions.push_back(n + Vec3(0.0f, 0.0f, z));
            m.normals.push_back(n);
            m.uv0.emplace_back(u, z);
        }
    }
    for (uint32_t j = 0; j < uint32_t(kSegments); ++j) {
        const uint32_t a = 2 * j, b = a + 1, c = a + 3, d = a + 2;
        m.indices.insert(m.indices.end(), {a, d, c, a, c, b});
    }
    return m;
}

}  // namespace mvpl::scene::mitsuba
