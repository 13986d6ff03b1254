#include "engine/render/gpu_vpl.h"

#include "engine/material/closure.h"
#include "engine/render/directional_frame.h"
#include "engine/render/host_vec3.h"

namespace mvpl::render {
namespace {

// The GLSL side reads VplType through these (shaders/shared/gpu_vpl.h).
static_assert(shared::kVplPoint == uint32_t(light::VplType::Point));
static_assert(shared::kVplSpot == uint32_t(light::VplType::Spot));
static_assert(shared::kVplArea == uint32_t(light::VplType::Area));
static_assert(shared::kVplSurface == uint32_t(light::VplType::Surface));
static_assert(shared::kVplDirectional == uint32_t(light::VplType::Directional));

}  // namespace

GpuVpl to_gpu_vpl(const light::Vpl& vpl, const scene::Bounds& bounds) {
    GpuVpl g{};
    store(g.position, vpl.position);
    g.type = uint32_t(vpl.type);
    store(g.normal, vpl.normal);
    store(g.shading_normal, vpl.shading_normal);
    store(g.wi, vpl.wi);
    store(g.power, Vec3(vpl.power.r, vpl.power.g, vpl.power.b));
    g.cos_inner = vpl.cos_inner;
    g.cos_outer = vpl.cos_outer;
    g.path_length = vpl.path_length;
    const material::ClosureParams c = material::clamp_to_valid_ranges(vpl.closure);
    store(g.base_color, Vec3(c.base_color.r, c.base_color.g, c.base_color.b));
    g.metallic = c.metallic;
    store(g.specular_color, Vec3(c.specular_color.r, c.specular_color.g, c.specular_color.b));
    g.specular = c.specular;
    g.roughness = c.roughness;
    g.ior = c.ior;
    g.closure_type = uint32_t(material::closure_type(c));
    if (vpl.type == light::VplType::Directional) {
        const DirectionalFrame f = directional_frame(vpl.normal, bounds);
        store(g.normal, f.dir);
        store(g.position, f.origin);
        store(g.shading_normal, f.u);
        store(g.wi, f.v);
        g.map_extent = f.extent;
        g.map_depth = f.depth;
    }
    return g;
}

std::vector<GpuVpl> to_gpu_vpls(std::span<const light::Vpl> vpls, const scene::Bounds& bounds) {
    std::vector<GpuVpl> out;
    out.reserve(vpls.size());
    for (const light::Vpl& v : vpls)
        out.push_back(to_gpu_vpl(v, bounds));
    return out;
}

}  // namespace mvpl::render
