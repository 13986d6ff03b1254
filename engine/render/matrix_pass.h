#pragma once
// The reduced matrix of row-column sampling on the GPU (Hašan, Pellacini, Bala 2007: rows
// computed with shadow maps). Per batch of rows, their distance cubes by the shadow pass (a row
// drawn as a surface VPL on its geometric normal: a hemicube), then one compute dispatch over the
// pool's columns (shaders/render/matrix_template.glsl) that adds the batch's entries — the shading
// pass's contribution code, visibility from the row's cube — to each column's squared norm and
// count sketch. The pool's VPLs draw no cube: the cost of the maps grows with the rows, not with
// the pool. Vulkan-free to include.
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "engine/gpu/buffer.h"
#include "engine/gpu/spirv_cache.h"
#include "engine/light/vpl.h"
#include "engine/render/shader_program.h"
#include "engine/render/shadow_pass.h"
#include "engine/scene/bounds.h"
#include "shaders/shared/chain_record.h"

namespace mvpl::gpu {
class ComputePipeline;
class Context;
}  // namespace mvpl::gpu

namespace mvpl::render {

// One pool's matrix: the rows as receivers (chain_record(); state unread), the columns, the
// count sketch's hash of the 3R entries (manylights::sketch_hash: bucket, bit 31 the sign).
struct MatrixInput {
    std::span<const shared::ChainRecord> rows;
    std::span<const light::Vpl> vpls;
    std::span<const uint32_t> hash;
    uint32_t dims = 16;
    float d_min = 0.0f;       // the shading pass's clamp (world units)
    float vsl_radius = 0.0f;  // the shading pass's sphere radius (world units)
    bool shadows = true;      // false: every entry unshadowed
};

class MatrixPass {
public:
    // shadow: the rows' cubes' options (their resolution; no kept maps).
    MatrixPass(gpu::Context& context, const SceneGeometry& geometry, const ShadowClusters& clusters,
               const ShaderFeatures& features, const ShadowPassOptions& shadow,
               const gpu::SpirvCacheOptions& cache = {});
    ~MatrixPass();
    MatrixPass(const MatrixPass&) = delete;
    MatrixPass& operator=(const MatrixPass&) = delete;

    // Column j's squared norm at out[j · (1 + dims)], its sketch after it; submits and waits.
    // bounds: the scene's (directional VPLs' records).
    void evaluate(const MatrixInput& in, const scene::Bounds& bounds, std::vector<float>& out);

    uint32_t resolution() const { return m_shadow.resolution(); }

private:
    // Grows `buffer` to hold at least `bytes`.
    void reserve(gpu::Buffer& buffer, uint64_t bytes, gpu::MemoryLocation location,
                 const char* name);

    gpu::Context* m_context;
    ShadowPass m_shadow;
    std::unique_ptr<gpu::ComputePipeline> m_pipeline;
    gpu::Buffer m_rows, m_vpls, m_hash, m_columns;  // rows and hash: a batch's, uniform
};

}  // namespace mvpl::render
