#pragma once
// Row-column sampling's reduced matrix on the GPU renderer: the rows as receiver records, the
// pool's columns' norms and sketches from VplRenderer::reduced_matrix (engine/render/
// matrix_pass.h), the same as manylights::sketch_columns up to visibility (the rows' cubes in
// place of Embree's rays).
#include "engine/gpu/device_info.h"
#include "engine/manylights/reduced_matrix.h"
#include "engine/manylights/row_column_options.h"
#include "engine/render/vpl_renderer.h"

namespace mvpl::integrator {

// Whether `options` put the reduced matrix on a renderer on `device` (RowColumnOptions::matrix).
bool gpu_matrix(const manylights::RowColumnOptions& options, const gpu::DeviceInfo& device);

class GpuColumns : public manylights::ColumnEvaluator {
public:
    // resolution: the side of a row cube's face.
    GpuColumns(render::VplRenderer& renderer, uint32_t resolution)
        : m_renderer(&renderer), m_resolution(resolution) {}

    manylights::ColumnSketches sketch(const manylights::MatrixContext& context,
                                      std::span<const light::Vpl> vpls, uint32_t dims,
                                      uint64_t seed) override;

private:
    render::VplRenderer* m_renderer;
    uint32_t m_resolution;
};

}  // namespace mvpl::integrator
