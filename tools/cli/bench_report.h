#pragma once
// `mvpl bench` results: what one measured run holds, the medians over repeats, and the two ways
// of printing them (a JSON document for machines, a table for people).
#include <cstdint>
#include <string>
#include <vector>

#include "engine/core/image_size.h"
#include "engine/manylights/row_column_options.h"

namespace mvpl::cli {

// One render configuration of the benchmark.
struct BenchConfig {
    int width = kThroughputImageSide;
    int height = kThroughputImageSide;
    int shadow_resolution = 0;  // the renderer's --shadow-res and --batch (bench's configure())
    int batch = 0;
    bool shadow_culling = true;    // render::RenderOptions::shadow_culling
    bool shadow_proxy = true;      // render::RenderOptions::shadow_proxy
    bool shadow_lod = true;        // render::RenderOptions::shadow_lod
    bool backface_culling = true;  // render::RenderOptions::backface_culling
    bool jitter =
        true;  // a G-buffer per sub-pixel position (false with --no-jitter: one per render)
    int batches_per_position = 0;  // render::RenderOptions's; 0: the scene's default
    int interleave = 1;            // render::RenderOptions::interleave
    bool hemicube = true;          // render::RenderOptions::hemicube
    bool vpl_culling = true;       // render::RenderOptions::vpl_culling
    // render::RenderOptions::chains: the roughness bound (negative: no specular chains) and the
    // light paths' --max-depth, which bounds them.
    float chain_roughness = -1.0f;
    int max_depth = -1;
    float vsl_radius = 0.0f;  // render::RenderOptions::vsl_radius (0: point VPLs)
    int devices = 1;          // render::VplRenderer::devices
    // Row-column sampling (--pool, --rows, --clusters): off without a pool.
    manylights::RowColumnOptions many_lights;
};

// The levers of issue 14 a configuration uses, for people: "culling on, proxy on, interleave 1".
std::string bench_levers(const BenchConfig& config);

// One measured render of the VPLs with one configuration. Times in seconds unless named _ms.
struct RenderSample {
    double g_buffer_ms = 0.0;  // GPU time per pass (timestamp queries), summed over batches
    double shadow_ms = 0.0;
    double shading_ms = 0.0;
    double wall_s = 0.0;  // host time of begin + accumulate + resolve (uploads, read-back)
    uint32_t batches = 0;
    uint64_t shadow_triangles = 0;             // drawn into cube faces and orthographic maps
    uint64_t shadow_front_only_triangles = 0;  // of those, solids' with back faces culled
    uint64_t shadow_texels = 0;                // cube-face texels cleared and drawn
    uint64_t culled_vpls = 0;                  // VPLs that could not reach the view
    uint32_t g_buffers = 0;                    // one per sub-pixel position
    double chain_ms = 0.0;  // host time tracing specular chains (summed over devices)
    uint64_t chain_rays = 0;
    // With row-column sampling: the representatives shaded, and the host seconds of the reduced
    // matrix and of the clustering (in wall_s).
    uint64_t shaded = 0;
    double matrix_s = 0.0;
    double cluster_s = 0.0;
    bool gpu_matrix = false;  // the reduced matrix on the GPU renderer (--matrix)
};

// The medians over the repeats of one configuration, and the rates derived from those medians
// (not medians of per-repeat rates), so that `vpls / end_to_end_s == end_to_end_vpls_per_s`.
struct RenderResult {
    BenchConfig config;
    RenderSample median;
    double shadow_ms_per_vpl = 0.0;
    double shadow_triangles_per_vpl = 0.0;
    double shadow_front_only_share = 0.0;  // shadow_front_only_triangles / shadow_triangles
    double shadow_texels_per_vpl = 0.0;
    double shading_ms_per_vpl = 0.0;
    double shading_pixel_vpls_per_s = 0.0;  // width · height · VPLs / shading GPU seconds
    double end_to_end_s = 0.0;              // light-path generation + render wall time
    double end_to_end_vpls_per_s = 0.0;     // VPLs shaded (representatives with a pool)
    // The VPLs the image estimates (every pool's, with row-column sampling) per end-to-end second.
    double effective_vpls_per_s = 0.0;
};

struct BenchReport {
    std::string scene;
    uint64_t triangles = 0;
    std::string device;
    int repeat = 1;
    bool shadows = true;  // false with --no-shadows: no shadow pass, every VPL unshadowed
    int ranks = 1;        // under mpirun: the job's ranks (engine/cluster)
    // Start-up, medians: scene file → Scene, Embree BVH, Vulkan context, renderer (geometry
    // upload) and its first begin() (pipeline creation and shader compilation).
    double scene_load_s = 0.0;
    double bvh_build_s = 0.0;
    double context_s = 0.0;
    double renderer_s = 0.0;
    // Light-path generation (Monte Carlo, the CPU with Embree), median seconds.
    uint64_t paths = 0;
    uint64_t vpls = 0;
    double sampling_s = 0.0;
    RenderResult main;
    std::vector<RenderResult> sweep;  // empty without --sweep
    uint64_t peak_host_bytes = 0;     // getrusage ru_maxrss
    uint64_t peak_device_bytes = 0;   // high-water mark of mvpl's device allocations

    double startup_s() const { return scene_load_s + bvh_build_s + context_s + renderer_s; }
    double paths_per_s() const;
    double sampling_vpls_per_s() const;
};

// Median of a non-empty list (the mean of the middle two for an even count).
double median(std::vector<double> values);
// Medians of each field of the samples, and the derived rates for `vpls` VPLs after
// `sampling_s` seconds of light-path generation (per VPL: per representative shaded, with a
// pool).
RenderResult summarise(const BenchConfig& config, const std::vector<RenderSample>& samples,
                       uint64_t vpls, double sampling_s);

std::string bench_json(const BenchReport& report);
std::string bench_table(const BenchReport& report);

}  // namespace mvpl::cli
