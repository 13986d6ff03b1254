#include "engine/render/matrix_pass.h"

#include <algorithm>
#include <cstring>

#include "engine/gpu/command_list.h"
#include "engine/gpu/compute_pipeline.h"
#include "engine/gpu/context.h"
#include "engine/gpu/gpu_error.h"
#include "engine/gpu/shader_compiler.h"
#include "engine/render/gpu_vpl.h"
#include "shaders/shared/push_constants.h"

namespace mvpl::render {
namespace {

using shared::ChainRecord;
using shared::MatrixPush;
constexpr uint32_t kMatrixGroupSize = 64;  // matrix_template.glsl's local_size_x

std::unique_ptr<gpu::ComputePipeline> make_pipeline(gpu::Context& context,
                                                    const ShaderFeatures& features,
                                                    const gpu::SpirvCacheOptions& cache) {
    const StageSource source = generate_matrix_source(features);
    const gpu::ComputeLayout layout{
        {gpu::BindingType::uniform_buffer, gpu::BindingType::storage_buffer,
         gpu::BindingType::storage_image, gpu::BindingType::uniform_buffer,
         gpu::BindingType::storage_buffer},
        sizeof(MatrixPush)};
    return std::make_unique<gpu::ComputePipeline>(
        context,
        gpu::compile_glsl_cached(gpu::ShaderStage::compute, source.source, "render/" + source.name,
                                 cache),
        layout, "reduced matrix");
}

// Row r as the shadow pass draws it: a surface VPL on the row's geometric normal, so that its
// cube is the hemicube of the directions the row receives from (the contribution is 0 below it).
light::Vpl row_as_vpl(const ChainRecord& row) {
    light::Vpl v;
    v.type = light::VplType::Surface;
    v.position = Vec3(row.position[0], row.position[1], row.position[2]);
    v.normal = Vec3(row.geometric_normal[0], row.geometric_normal[1], row.geometric_normal[2]);
    v.shading_normal = v.normal;
    v.path_length = 1;  // may draw the shadow proxy, as surface VPLs do
    return v;
}

ShadowPassOptions without_kept_maps(ShadowPassOptions o) {
    o.kept_bytes = 0;
    return o;
}

}  // namespace

MatrixPass::MatrixPass(gpu::Context& context, const SceneGeometry& geometry,
                       const ShadowClusters& clusters, const ShaderFeatures& features,
                       const ShadowPassOptions& shadow, const gpu::SpirvCacheOptions& cache)
    : m_context(&context),
      m_shadow(context, geometry, clusters, without_kept_maps(shadow)),
      m_pipeline(make_pipeline(context, features, cache)),
      m_rows(context, shared::kMaxMatrixRows * sizeof(ChainRecord), gpu::BufferUsage::uniform,
             gpu::MemoryLocation::upload, "matrix rows"),
      m_hash(context, shared::kMaxMatrixRows * 4 * sizeof(uint32_t), gpu::BufferUsage::uniform,
             gpu::MemoryLocation::upload, "sketch hash") {}

MatrixPass::~MatrixPass() = default;

void MatrixPass::reserve(gpu::Buffer& buffer, uint64_t bytes, gpu::MemoryLocation location,
                         const char* name) {
    bytes = std::max<uint64_t>(bytes, 16);
    if (buffer.size() >= bytes) return;
    // Exactly what is asked (a pool keeps its size), so that no buffer exceeds the device's
    // storage buffer range where the pool does not (evaluate() cuts a pool to fit).
    buffer = gpu::Buffer(*m_context, bytes, gpu::BufferUsage::storage, location, name);
}

void MatrixPass::evaluate(const MatrixInput& in, const scene::Bounds& bounds,
                          std::vector<float>& out) {
    if (in.dims == 0 || in.dims > shared::kMaxSketchDims || in.hash.size() != 3 * in.rows.size())
        throw gpu::GpuError("reduced matrix: a sketch of 1 … 64 dimensions, one hash a row entry");
    const uint32_t stride = 1 + in.dims;
    // A pool whose VPLs or sketches exceed a storage buffer's range on this device is evaluated
    // in parts, each drawing the rows' cubes again (2^20 VPLs fill lavapipe's 128 MiB).
    const uint64_t range = m_context->device_info().limits.max_storage_buffer_range;
    const size_t fits = size_t(range / std::max<uint64_t>(sizeof(GpuVpl), stride * sizeof(float)));
    if (in.vpls.size() > fits) {
        out.clear();
        std::vector<float> part_out;
        for (size_t first = 0; first < in.vpls.size(); first += fits) {
            MatrixInput part = in;
            part.vpls = in.vpls.subspan(first, std::min(fits, in.vpls.size() - first));
            evaluate(part, bounds, part_out);
            out.insert(out.end(), part_out.begin(), part_out.end());
        }
        return;
    }
    out.assign(in.vpls.size() * stride, 0.0f);
    if (in.vpls.empty() || in.rows.empty()) return;
    const std::vector<GpuVpl> vpls = to_gpu_vpls(in.vpls, bounds);
    reserve(m_vpls, vpls.size() * sizeof(GpuVpl), gpu::MemoryLocation::upload, "matrix columns");
    reserve(m_columns, out.size() * sizeof(float), gpu::MemoryLocation::readback,
            "column sketches");
    std::memcpy(m_vpls.mapped(), vpls.data(), vpls.size() * sizeof(GpuVpl));
    std::memset(m_columns.mapped(), 0, out.size() * sizeof(float));

    MatrixPush push{};
    push.d_min2 = in.d_min * in.d_min;
    push.vsl_r2 = in.vsl_radius * in.vsl_radius;
    push.texel_angle = 2.0f / float(m_shadow.resolution());
    push.flags = in.shadows ? shared::kShadows : 0u;
    push.column_count = uint32_t(in.vpls.size());
    push.dims = in.dims;
    const uint32_t groups = (push.column_count + kMatrixGroupSize - 1) / kMatrixGroupSize;
    const size_t batch = std::min<size_t>(m_shadow.max_batch(), shared::kMaxMatrixRows);
    std::vector<light::Vpl> row_vpls;
    auto* hash = reinterpret_cast<uint32_t*>(m_hash.mapped());
    for (size_t first = 0; first < in.rows.size(); first += batch) {
        const size_t count = std::min(batch, in.rows.size() - first);
        row_vpls.clear();
        for (size_t r = first; r < first + count; ++r)
            row_vpls.push_back(row_as_vpl(in.rows[r]));
        // The batch's rows and hashes; the previous batch has finished (submit_and_wait).
        std::memcpy(m_rows.mapped(), &in.rows[first], count * sizeof(ChainRecord));
        for (size_t b = 0; b < count; ++b)
            std::copy_n(&in.hash[3 * (first + b)], 3, &hash[4 * b]);
        push.row_count = uint32_t(count);
        m_context->submit_and_wait([&](gpu::CommandList& cmd) {
            if (in.shadows) {
                m_shadow.record(cmd, row_vpls);
                cmd.barrier();
            }
            cmd.dispatch(*m_pipeline, {&m_rows, &m_vpls, &m_shadow.cubes(), &m_hash, &m_columns},
                         gpu::push_bytes(push), groups, 1, 1);
        });
    }
    std::memcpy(out.data(), m_columns.mapped(), out.size() * sizeof(float));
}

}  // namespace mvpl::render
