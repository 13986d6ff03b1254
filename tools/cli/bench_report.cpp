#include "tools/cli/bench_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>

namespace mvpl::cli {

namespace {

double ratio(double numerator, double denominator) {
    return denominator > 0.0 ? numerator / denominator : 0.0;
}

using Json = nlohmann::ordered_json;  // keys in the order written, as people read them

// Seventeen significant digits round-trip a double (nlohmann writes the shortest that does), so
// a reader recomputes rates exactly; NaN and infinities are written as null.

std::string chain_bound(float roughness) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "≤ %.2f", double(roughness));
    return buf;
}

std::string vsl_radius(float radius) {
    if (!(radius > 0.0f)) return "0 (point VPLs)";
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3g", double(radius));
    return buf;
}

Json render_json(const RenderResult& r) {
    const BenchConfig& c = r.config;
    Json j = {{"width", c.width},
              {"height", c.height},
              {"shadow_resolution", c.shadow_resolution},
              {"batch", c.batch},
              {"shadow_culling", c.shadow_culling},
              {"shadow_proxy", c.shadow_proxy},
              {"shadow_lod", c.shadow_lod},
              {"backface_culling", c.backface_culling},
              {"interleave", c.interleave},
              {"batches_per_position", c.batches_per_position},
              {"devices", c.devices},
              {"hemicube", c.hemicube},
              {"vpl_culling", c.vpl_culling},
              {"chains", c.chain_roughness >= 0.0f}};
    if (c.chain_roughness >= 0.0f) j["chain_roughness"] = c.chain_roughness;
    const Json measured = {{"chain_ms", r.median.chain_ms},
                           {"chain_rays", r.median.chain_rays},
                           {"culled_vpls", r.median.culled_vpls},
                           {"shadow_texels_per_vpl", r.shadow_texels_per_vpl},
                           {"shadow_triangles_per_vpl", r.shadow_triangles_per_vpl},
                           {"shadow_front_only_share", r.shadow_front_only_share},
                           {"jitter", c.jitter},
                           {"batches", r.median.batches},
                           {"g_buffers", r.median.g_buffers},
                           {"g_buffer_ms", r.median.g_buffer_ms},
                           {"shadow_ms", r.median.shadow_ms},
                           {"shadow_ms_per_vpl", r.shadow_ms_per_vpl},
                           {"shading_ms", r.median.shading_ms},
                           {"shading_ms_per_vpl", r.shading_ms_per_vpl},
                           {"shading_pixel_vpls_per_s", r.shading_pixel_vpls_per_s},
                           {"render_wall_s", r.median.wall_s},
                           {"end_to_end_s", r.end_to_end_s},
                           {"end_to_end_vpls_per_s", r.end_to_end_vpls_per_s},
                           {"effective_vpls_per_s", r.effective_vpls_per_s}};
    j.update(measured);
    if (c.many_lights.enabled()) {
        j["row_column"] = {{"pool", c.many_lights.pool},
                           {"rows", c.many_lights.rows},
                           {"clusters", c.many_lights.clusters_per_pool()},
                           {"representatives", r.median.shaded},
                           {"matrix_s", r.median.matrix_s},
                           {"cluster_s", r.median.cluster_s},
                           {"matrix", r.median.gpu_matrix ? "gpu" : "cpu"}};
    }
    return j;
}

}  // namespace

std::string bench_levers(const BenchConfig& c) {
    return std::string("culling ") + (c.shadow_culling ? "on" : "off") + ", proxy " +
           (c.shadow_proxy ? "on" : "off") + ", levels of detail " + (c.shadow_lod ? "on" : "off") +
           ", back faces of solids " + (c.backface_culling ? "culled" : "drawn") + ", hemicube " +
           (c.hemicube ? "on" : "off") + ", VPL culling " + (c.vpl_culling ? "on" : "off") +
           ", interleave " + std::to_string(c.interleave) +
           (c.jitter ? ", sub-pixel position every " + std::to_string(c.batches_per_position) +
                           (c.batches_per_position == 1 ? " batch" : " batches")
                     : ", pixel centres") +
           ", chains " + (c.chain_roughness >= 0.0f ? chain_bound(c.chain_roughness) : "off") +
           ", VSL radius " + vsl_radius(c.vsl_radius) + ", " + std::to_string(c.devices) +
           (c.devices == 1 ? " device" : " devices") + ", row-column " +
           (c.many_lights.enabled()
                ? "pool " + std::to_string(c.many_lights.pool) + ", " +
                      std::to_string(c.many_lights.rows) + " rows, " +
                      std::to_string(c.many_lights.clusters_per_pool()) + " clusters"
                : std::string("off"));
}

double BenchReport::paths_per_s() const {
    return ratio(double(paths), sampling_s);
}

double BenchReport::sampling_vpls_per_s() const {
    return ratio(double(vpls), sampling_s);
}

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    const size_t n = values.size();
    if (n == 0) return 0.0;
    return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

RenderResult summarise(const BenchConfig& config, const std::vector<RenderSample>& samples,
                       uint64_t vpls, double sampling_s) {
    auto field = [&samples](double RenderSample::*member) {
        std::vector<double> values;
        for (const RenderSample& s : samples)
            values.push_back(s.*member);
        return median(values);
    };
    RenderResult r;
    r.config = config;
    r.median.g_buffer_ms = field(&RenderSample::g_buffer_ms);
    r.median.shadow_ms = field(&RenderSample::shadow_ms);
    r.median.shading_ms = field(&RenderSample::shading_ms);
    r.median.wall_s = field(&RenderSample::wall_s);
    r.median.chain_ms = field(&RenderSample::chain_ms);
    r.median.chain_rays = samples.empty() ? 0 : samples.front().chain_rays;
    r.median.batches = samples.empty() ? 0 : samples.front().batches;
    r.median.shadow_triangles = samples.empty() ? 0 : samples.front().shadow_triangles;
    r.median.shadow_front_only_triangles =
        samples.empty() ? 0 : samples.front().shadow_front_only_triangles;
    r.median.shadow_texels = samples.empty() ? 0 : samples.front().shadow_texels;
    r.median.culled_vpls = samples.empty() ? 0 : samples.front().culled_vpls;
    r.median.g_buffers = samples.empty() ? 0 : samples.front().g_buffers;
    r.median.shaded = samples.empty() ? 0 : samples.front().shaded;
    r.median.gpu_matrix = !samples.empty() && samples.front().gpu_matrix;
    r.median.matrix_s = field(&RenderSample::matrix_s);
    r.median.cluster_s = field(&RenderSample::cluster_s);
    // Per VPL shaded: with row-column sampling the representatives.
    const double n = config.many_lights.enabled() ? double(r.median.shaded) : double(vpls);
    r.shadow_triangles_per_vpl = ratio(double(r.median.shadow_triangles), n);
    r.shadow_front_only_share =
        ratio(double(r.median.shadow_front_only_triangles), double(r.median.shadow_triangles));
    r.shadow_texels_per_vpl = ratio(double(r.median.shadow_texels), n);
    r.shadow_ms_per_vpl = ratio(r.median.shadow_ms, n);
    r.shading_ms_per_vpl = ratio(r.median.shading_ms, n);
    r.shading_pixel_vpls_per_s =
        ratio(double(config.width) * double(config.height) * n, r.median.shading_ms * 1e-3);
    r.end_to_end_s = sampling_s + r.median.wall_s;
    r.end_to_end_vpls_per_s = ratio(n, r.end_to_end_s);
    r.effective_vpls_per_s = ratio(double(vpls), r.end_to_end_s);
    return r;
}

std::string bench_json(const BenchReport& b) {
    Json sweep = Json::array();
    for (const RenderResult& r : b.sweep)
        sweep.push_back(render_json(r));
    const Json j = {
        {"scene", b.scene},
        {"triangles", b.triangles},
        {"device", b.device},
        {"repeat", b.repeat},
        {"shadows", b.shadows},
        {"ranks", b.ranks},
        {"startup",
         {{"scene_load_s", b.scene_load_s},
          {"bvh_build_s", b.bvh_build_s},
          {"context_s", b.context_s},
          {"renderer_s", b.renderer_s},
          {"total_s", b.startup_s()}}},
        {"light_paths",
         {{"paths", b.paths},
          {"vpls", b.vpls},
          {"seconds", b.sampling_s},
          {"paths_per_s", b.paths_per_s()},
          {"vpls_per_s", b.sampling_vpls_per_s()}}},
        {"render", render_json(b.main)},
        {"sweep", sweep},
        {"memory",
         {{"peak_host_bytes", b.peak_host_bytes}, {"peak_device_bytes", b.peak_device_bytes}}}};
    // A path's bytes need not be UTF-8 on Linux: invalid sequences become U+FFFD rather than an
    // exception after the whole benchmark ran.
    return j.dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
}

std::string bench_table(const BenchReport& b) {
    const RenderResult& m = b.main;
    char buf[1024];
    std::string s;
    std::snprintf(buf, sizeof buf,
                  "bench: %s, %llu triangles, %s; medians of %d%s%s\n"
                  "  start-up         %8.3f s  (scene %.3f s, BVH %.3f s, Vulkan %.3f s, "
                  "renderer + shaders %.3f s)\n",
                  b.scene.c_str(), static_cast<unsigned long long>(b.triangles), b.device.c_str(),
                  b.repeat, b.shadows ? "" : "; no shadows",
                  b.ranks > 1 ? ("; " + std::to_string(b.ranks) + " MPI ranks").c_str() : "",
                  b.startup_s(), b.scene_load_s, b.bvh_build_s, b.context_s, b.renderer_s);
    s += buf;
    std::snprintf(buf, sizeof buf,
                  "  light paths      %8.3f s  %llu paths → %llu VPLs: %.0f paths/s, %.0f VPLs/s\n",
                  b.sampling_s, static_cast<unsigned long long>(b.paths),
                  static_cast<unsigned long long>(b.vpls), b.paths_per_s(),
                  b.sampling_vpls_per_s());
    s += buf;
    std::snprintf(buf, sizeof buf,
                  "  render %dx%d, shadow %d², batch %d (%u batches): wall %.3f s\n"
                  "  levers           %s; %llu VPLs culled\n"
                  "    G-buffer       %8.2f ms  %u G-buffers\n"
                  "    shadow         %8.2f ms  %.3f ms/VPL, %.0f triangles/VPL (%.0f %% front "
                  "faces only), %.0f texels/VPL\n"
                  "    shading        %8.2f ms  %.3f ms/VPL, %.1f M pixel·VPL/s\n"
                  "    chains (host)  %8.2f ms  %llu rays\n"
                  "  end to end       %8.3f s  %.1f VPL/s\n"
                  "  peak memory      host %.1f MiB, device %.1f MiB\n",
                  m.config.width, m.config.height, m.config.shadow_resolution, m.config.batch,
                  m.median.batches, m.median.wall_s, bench_levers(m.config).c_str(),
                  static_cast<unsigned long long>(m.median.culled_vpls), m.median.g_buffer_ms,
                  m.median.g_buffers, m.median.shadow_ms, m.shadow_ms_per_vpl,
                  m.shadow_triangles_per_vpl, 100.0 * m.shadow_front_only_share,
                  m.shadow_texels_per_vpl, m.median.shading_ms, m.shading_ms_per_vpl,
                  m.shading_pixel_vpls_per_s * 1e-6, m.median.chain_ms,
                  static_cast<unsigned long long>(m.median.chain_rays), m.end_to_end_s,
                  m.end_to_end_vpls_per_s, double(b.peak_host_bytes) / (1 << 20),
                  double(b.peak_device_bytes) / (1 << 20));
    s += buf;
    if (m.config.many_lights.enabled()) {
        std::snprintf(buf, sizeof buf,
                      "  row-column       %llu representatives of %llu VPLs (%s matrix %.3f s, "
                      "clusters %.3f s): %.1f VPL/s effective\n",
                      static_cast<unsigned long long>(m.median.shaded),
                      static_cast<unsigned long long>(b.vpls), m.median.gpu_matrix ? "GPU" : "CPU",
                      m.median.matrix_s, m.median.cluster_s, m.effective_vpls_per_s);
        s += buf;
    }
    if (!b.sweep.empty()) {
        s += "\n  batch  shadow  shadow ms/VPL  shading ms/VPL  M pixel·VPL/s  render s   VPL/s  "
             "levers\n";
        for (const RenderResult& r : b.sweep) {
            std::snprintf(buf, sizeof buf, "  %5d  %6d  %13.3f  %14.3f  %13.1f  %8.3f  %6.1f  %s\n",
                          r.config.batch, r.config.shadow_resolution, r.shadow_ms_per_vpl,
                          r.shading_ms_per_vpl, r.shading_pixel_vpls_per_s * 1e-6, r.median.wall_s,
                          r.end_to_end_vpls_per_s, bench_levers(r.config).c_str());
            s += buf;
        }
    }
    return s;
}

}  // namespace mvpl::cli
