#include "engine/integrator/gpu_columns.h"

#include <cmath>

#include "engine/render/chain_layer.h"

namespace mvpl::integrator {

bool gpu_matrix(const manylights::RowColumnOptions& options, const gpu::DeviceInfo& device) {
    using manylights::MatrixDevice;
    if (options.matrix != MatrixDevice::automatic) return options.matrix == MatrixDevice::gpu;
    return device.type != gpu::DeviceType::cpu ||
           options.pool >= manylights::kGpuMatrixPoolOnCpuDevice;
}

manylights::ColumnSketches GpuColumns::sketch(const manylights::MatrixContext& context,
                                              std::span<const light::Vpl> vpls, uint32_t dims,
                                              uint64_t seed) {
    manylights::ColumnSketches s;
    s.dims = std::max<uint32_t>(dims, 1);
    std::vector<shared::ChainRecord> rows;
    rows.reserve(context.rows.size());
    for (const manylights::Row& row : context.rows)
        rows.push_back(render::receiver_record(row.receiver, row.throughput, row.max_vpl_length));
    const std::vector<uint32_t> hash = manylights::sketch_hash(3 * rows.size(), s.dims, seed);
    std::vector<float> columns;
    m_renderer->reduced_matrix(rows, vpls, hash, s.dims, m_resolution, columns);
    const size_t stride = 1 + s.dims;
    s.norms.resize(vpls.size());
    s.sketch.resize(vpls.size() * s.dims);
    for (size_t j = 0; j < vpls.size(); ++j) {
        s.norms[j] = std::sqrt(std::max(columns[j * stride], 0.0f));
        std::copy_n(&columns[j * stride + 1], s.dims, &s.sketch[j * s.dims]);
    }
    return s;
}

}  // namespace mvpl::integrator
