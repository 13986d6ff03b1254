#include "engine/trace/accel.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <atomic>
#include <bit>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine/core/rng.h"
#include "engine/trace/interaction.h"

namespace mvpl::trace {

namespace {

// What a mesh's Embree filters need: every ray skips hits on texels that an alpha-tested
// material cuts (glTF MASK, or BLEND by a hash of the ray), camera rays also the back faces of
// one-sided materials.
struct MeshFilter {
    const scene::Mesh* mesh = nullptr;
    const material::SceneMaterials* materials = nullptr;
    int material = 0;
    bool alpha_tested = false;  // MASK or BLEND
    bool one_sided = false;
};

// A uniform number in [0, 1) from a ray and the triangle it hits: hashed transparency (glTF
// BLEND) that is the same for the same ray, so renders are deterministic per seed.
float ray_hash(const RTCFilterFunctionNArguments* args, unsigned i, int triangle) {
    const float values[6] = {
        RTCRayN_org_x(args->ray, args->N, i), RTCRayN_org_y(args->ray, args->N, i),
        RTCRayN_org_z(args->ray, args->N, i), RTCRayN_dir_x(args->ray, args->N, i),
        RTCRayN_dir_y(args->ray, args->N, i), RTCRayN_dir_z(args->ray, args->N, i)};
    uint64_t h = mix_bits(uint64_t(uint32_t(triangle)) + 0x9e3779b97f4a7c15ULL);
    for (const float v : values)
        h = mix_bits(h ^ std::bit_cast<uint32_t>(v));
    return float(h >> 40) * 0x1p-24f;
}

// The intersect context of camera rays: Embree hands back the pointer it was given to its
// context filter (set for camera rays only, so that other rays pay nothing for it).
struct CameraContext {
    RTCIntersectContext context;
    const std::vector<MeshFilter>* filters = nullptr;
};

}  // namespace

struct Accel::Impl {
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
    mutable std::atomic<uint64_t> rays{0};
    std::string error;
    std::vector<MeshFilter> filters;  // per mesh; stable addresses (reserved up front)
    bool streams = false;             // Embree built with ray packets (rtcOccluded1M)

    ~Impl() {
        if (scene) rtcReleaseScene(scene);
        if (device) rtcReleaseDevice(device);
    }
};

// Embree reports allocation failures and API misuse through this callback; exceptions must not
// cross its C frames, so the message is kept and thrown after the build.
static void embree_error(void* user, RTCError code, const char* message) {
    auto* first = static_cast<std::string*>(user);
    if (first->empty())
        first->assign("Embree error " + std::to_string(int(code)) + ": " +
                      (message ? message : ""));
}

// Camera rays (the context filter): rejects (valid = 0) back-face hits of one-sided materials;
// Embree then goes on traversing.
static void filter_back_faces(const RTCFilterFunctionNArguments* args) {
    const auto* context = reinterpret_cast<const CameraContext*>(args->context);
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] == 0) continue;
        const MeshFilter* f = &(*context->filters)[RTCHitN_geomID(args->hit, args->N, i)];
        const int triangle = int(RTCHitN_primID(args->hit, args->N, i));
        if (f->one_sided) {
            const uint32_t* idx = &f->mesh->indices[3 * size_t(triangle)];
            const Vec3& p0 = f->mesh->positions[idx[0]];
            const Vec3 winding =
                glm::cross(f->mesh->positions[idx[1]] - p0, f->mesh->positions[idx[2]] - p0);
            const Vec3 dir(RTCRayN_dir_x(args->ray, args->N, i),
                           RTCRayN_dir_y(args->ray, args->N, i),
                           RTCRayN_dir_z(args->ray, args->N, i));
            // As make_interaction's front_face: the ray arrives on the side ng points to.
            if (!(glm::dot(dir, winding) < 0.0f)) args->valid[i] = 0;
        }
    }
}

// Every ray (the alpha-tested meshes' geometry filter): rejects hits on cut texels.
static void filter_alpha(const RTCFilterFunctionNArguments* args) {
    const auto* f = static_cast<const MeshFilter*>(args->geometryUserPtr);
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] == 0) continue;
        const int triangle = int(RTCHitN_primID(args->hit, args->N, i));
        const Vec2 b(RTCHitN_u(args->hit, args->N, i), RTCHitN_v(args->hit, args->N, i));
        if (f->materials->cut(f->material, surface_attributes(*f->mesh, triangle, b),
                              ray_hash(args, i, triangle)))
            args->valid[i] = 0;
    }
}

Accel::Accel(const scene::Scene& scene) : m_impl(std::make_unique<Impl>()), m_materials(scene) {
    m_impl->device = rtcNewDevice(nullptr);
    if (!m_impl->device) throw std::runtime_error("cannot create an Embree device");
    rtcSetDeviceErrorFunction(m_impl->device, embree_error, &m_impl->error);
    m_impl->streams =
        rtcGetDeviceProperty(m_impl->device, RTC_DEVICE_PROPERTY_RAY_STREAM_SUPPORTED) != 0;
    m_impl->scene = rtcNewScene(m_impl->device);
    // Robust mode: watertight traversal, so that rays through shared edges do not leak light.
    rtcSetSceneFlags(m_impl->scene, RTC_SCENE_FLAG_ROBUST | RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION);
    rtcSetSceneBuildQuality(m_impl->scene, RTC_BUILD_QUALITY_HIGH);
    const scene::Bounds bounds = scene.bounds();
    if (!bounds.empty()) {
        const Vec3 far = glm::max(glm::abs(bounds.lo), glm::abs(bounds.hi));
        m_coordinate_scale = std::max({far.x, far.y, far.z});
    }
    m_impl->filters.reserve(scene.meshes.size());
    for (size_t id = 0; id < scene.meshes.size(); ++id) {
        const scene::Mesh& mesh = scene.meshes[id];
        RTCGeometry geom = rtcNewGeometry(m_impl->device, RTC_GEOMETRY_TYPE_TRIANGLE);
        auto* vertices = static_cast<float*>(
            rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                    sizeof(float) * 3, mesh.positions.size()));
        for (size_t i = 0; i < mesh.positions.size(); ++i) {
            vertices[3 * i + 0] = mesh.positions[i].x;
            vertices[3 * i + 1] = mesh.positions[i].y;
            vertices[3 * i + 2] = mesh.positions[i].z;
        }
        auto* indices = static_cast<uint32_t*>(
            rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                    sizeof(uint32_t) * 3, mesh.triangle_count()));
        std::copy(mesh.indices.begin(), mesh.indices.begin() + 3 * mesh.triangle_count(), indices);
        // Only meshes that need a filter get one: the others trace at full speed.
        MeshFilter& filter = m_impl->filters.emplace_back();
        if (mesh.material >= 0 && size_t(mesh.material) < m_materials.graphs().size()) {
            filter = {&mesh, &m_materials, mesh.material, m_materials.alpha_tested(mesh.material),
                      !m_materials.double_sided(mesh.material)};
        }
        if (filter.alpha_tested) {
            rtcSetGeometryUserData(geom, &filter);
            rtcSetGeometryIntersectFilterFunction(geom, filter_alpha);
            rtcSetGeometryOccludedFilterFunction(geom, filter_alpha);
        }
        rtcCommitGeometry(geom);
        rtcAttachGeometryByID(m_impl->scene, geom, static_cast<unsigned>(id));
        rtcReleaseGeometry(geom);
    }
    rtcCommitScene(m_impl->scene);
    if (!m_impl->error.empty()) throw std::runtime_error(m_impl->error);
}

Accel::~Accel() = default;

static RTCRay to_embree(const Ray& ray) {
    RTCRay r{};
    r.org_x = ray.origin.x;
    r.org_y = ray.origin.y;
    r.org_z = ray.origin.z;
    r.dir_x = ray.direction.x;
    r.dir_y = ray.direction.y;
    r.dir_z = ray.direction.z;
    r.tnear = 0.0f;
    r.tfar = ray.tmax;
    r.mask = 0xFFFFFFFFu;
    r.flags = 0;
    return r;
}

std::optional<Hit> Accel::intersect(const Ray& ray) const {
    return intersect(ray, false);
}

std::optional<Hit> Accel::intersect_camera(const Ray& ray) const {
    return intersect(ray, true);
}

std::optional<Hit> Accel::intersect(const Ray& ray, bool camera) const {
    m_impl->rays.fetch_add(1, std::memory_order_relaxed);
    CameraContext context;
    rtcInitIntersectContext(&context.context);
    if (camera) {
        context.context.filter = filter_back_faces;
        context.filters = &m_impl->filters;
    }
    RTCRayHit rayhit{};
    rayhit.ray = to_embree(ray);
    rayhit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rayhit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(m_impl->scene, &context.context, &rayhit);
    if (rayhit.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
    Hit hit;
    hit.t = rayhit.ray.tfar;
    hit.mesh = static_cast<int>(rayhit.hit.geomID);
    hit.triangle = static_cast<int>(rayhit.hit.primID);
    hit.barycentric = Vec2(rayhit.hit.u, rayhit.hit.v);
    return hit;
}

bool Accel::occluded(const Ray& ray) const {
    m_impl->rays.fetch_add(1, std::memory_order_relaxed);
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRay r = to_embree(ray);
    rtcOccluded1(m_impl->scene, &context, &r);
    // Embree marks an occluded ray by setting tfar to −∞.
    return r.tfar < 0.0f;
}

void Accel::occluded(std::span<const Ray> rays, std::span<uint8_t> occluded) const {
    if (!m_impl->streams) {  // an Embree built without ray packets: one ray a call
        for (size_t i = 0; i < rays.size(); ++i)
            occluded[i] = this->occluded(rays[i]) ? 1 : 0;
        return;
    }
    m_impl->rays.fetch_add(rays.size(), std::memory_order_relaxed);
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    // A ray stream, which Embree traces in packets of its SIMD width. On the reduced matrix's
    // columns (docs/results.md, "Row-column sampling") it took less CPU time than rtcOccluded1 a
    // ray, rtcOccluded8 packets or the stream with the coherent flag.
    thread_local std::vector<RTCRay> stream;
    stream.resize(rays.size());
    for (size_t i = 0; i < rays.size(); ++i) {
        // Field by field in place: a whole RTCRay built elsewhere and copied stalls on store
        // forwarding (perf: most of this loop's time).
        RTCRay& r = stream[i];
        r.org_x = rays[i].origin.x;
        r.org_y = rays[i].origin.y;
        r.org_z = rays[i].origin.z;
        r.tnear = 0.0f;
        r.dir_x = rays[i].direction.x;
        r.dir_y = rays[i].direction.y;
        r.dir_z = rays[i].direction.z;
        r.time = 0.0f;
        r.tfar = rays[i].tmax;
        r.mask = 0xFFFFFFFFu;
        r.id = 0;
        r.flags = 0;
    }
    rtcOccluded1M(m_impl->scene, &context, stream.data(), unsigned(rays.size()), sizeof(RTCRay));
    for (size_t i = 0; i < rays.size(); ++i)
        occluded[i] = stream[i].tfar < 0.0f ? 1 : 0;
}

uint64_t Accel::ray_count() const {
    return m_impl->rays.load(std::memory_order_relaxed);
}

}  // namespace mvpl::trace
