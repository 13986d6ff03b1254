#include "engine/render/batch_plan.h"

#include <algorithm>

namespace mvpl::render {

uint32_t default_batches_per_position(size_t triangles) {
    const size_t per = (triangles + kTrianglesPerPosition - 1) / kTrianglesPerPosition;
    return uint32_t(std::clamp<size_t>(per, kMinBatchesPerPosition, kMaxBatchesPerPosition));
}

std::vector<Slice> plan_batches(size_t count, uint64_t shaded, const RenderOptions& options,
                                std::span<const uint64_t> index) {
    const SubpixelSchedule schedule = subpixel_schedule(options);
    std::vector<Slice> slices;
    if (!index.empty()) {
        for (size_t first = 0; first < count;) {
            const uint64_t position = schedule.position_of(index[first]);
            size_t end = first + 1;
            // Interleaved, a VPL's index picks its pixel class from the batch's first index
            // (ShadingBatch::vpl_offset), so a batch holds consecutive indices only.
            while (end < count && end - first < options.batch &&
                   schedule.position_of(index[end]) == position &&
                   (options.interleave <= 1 || index[end] == index[end - 1] + 1))
                ++end;
            slices.push_back({first, end - first, position});
            first = end;
        }
        return slices;
    }
    for (size_t first = 0; first < count;) {
        const uint64_t position = schedule.position_of(shaded + first);
        size_t end = std::min(count, first + options.batch);
        if (schedule.jitter) {
            end = size_t(
                std::min<uint64_t>(end, (position + 1) * schedule.vpls_per_position - shaded));
        }
        slices.push_back({first, end - first, position});
        first = end;
    }
    return slices;
}

}  // namespace mvpl::render
