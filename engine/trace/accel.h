#pragma once
// Embree 3 BVH over every triangle of a scene, with the scene's material graphs: what a ray
// hits and what is there to shade (pbrt's aggregate of primitives with their materials).
// Embree's headers stay in accel.cpp.
#include <cstdint>
#include <memory>
#include <optional>
#include <span>

#include "engine/core/math.h"
#include "engine/material/scene_materials.h"
#include "engine/scene/scene.h"
#include "engine/trace/ray.h"

namespace mvpl::trace {

struct Hit {
    float t = 0.0f;
    int mesh = -1;
    int triangle = -1;
    Vec2 barycentric{0.0f};  // (b1, b2): p = (1 − b1 − b2)·p0 + b1·p1 + b2·p2
};

class Accel {
public:
    explicit Accel(const scene::Scene& scene);
    ~Accel();
    Accel(const Accel&) = delete;
    Accel& operator=(const Accel&) = delete;

    // Every ray passes through the surfaces that a glTF MASK material cuts (alpha below its
    // cutoff), as if they were not there.
    std::optional<Hit> intersect(const Ray& ray) const;
    bool occluded(const Ray& ray) const;
    // occluded(rays[i]) into occluded[i] (1 or 0) for every i, traced together: many rays a call
    // are what Embree's packet traversal needs (the reduced matrix's columns, manylights/).
    void occluded(std::span<const Ray> rays, std::span<uint8_t> occluded) const;
    // A camera ray: as intersect, and it passes through the back faces of one-sided materials
    // too (glTF doubleSided: false), which light paths and shadow rays still hit.
    std::optional<Hit> intersect_camera(const Ray& ray) const;

    // The scene's largest |coordinate|, for offset_ray_origin (ray.h).
    float coordinate_scale() const { return m_coordinate_scale; }

    // Rays traced so far (closest-hit and shadow), for Mrays/s reports.
    uint64_t ray_count() const;

    // The graphs that shading points at this BVH's hits evaluate (make_shading_point).
    const material::SceneMaterials& materials() const { return m_materials; }

private:
    struct Impl;
    std::optional<Hit> intersect(const Ray& ray, bool camera) const;

    std::unique_ptr<Impl> m_impl;
    material::SceneMaterials m_materials;
    float m_coordinate_scale = 1.0f;
};

}  // namespace mvpl::trace
