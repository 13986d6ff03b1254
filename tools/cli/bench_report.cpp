#include "tools/cli/bench_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace mvpl::cli {

namespace {

double ratio(double numerator, double denominator) {
    return denominator > 0.0 ? numerator / denominator : 0.0;
}

// JSON-escapes a string (paths and device names: quotes, backslashes, control characters).
std::string quoted(const std::string& text) {
    std::string out = "\"";
    for (const char c : text) {
        if (c == '"' || c == '\\') {
            out += '\\';
            out += c;
        } else if (static_cast<unsigned char>(c) < 0x20) {
            char buf[8];
            std::snprintf(buf, sizeof buf, "\\u%04x", unsigned(static_cast<unsigned char>(c)));
            out += buf;
        } else {
            out += c;
        }
    }
    return out + "\"";
}

// Seventeen significant digits round-trip a double, so a reader recomputes rates exactly.
std::string number(double value) {
    if (!std::isfinite(value)) return "null";
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.17g", value);
    return buf;
}

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

std::string render_json(const RenderResult& r, const std::string& indent) {
    const std::string i = indent + "  ";
    std::string s = "{\n";
    s += i + "\"width\": " + std::to_string(r.config.width) + ",\n";
    s += i + "\"height\": " + std::to_string(r.config.height) + ",\n";
    s += i + "\"shadow_resolution\": " + std::to_string(r.config.shadow_resolution) + ",\n";
    s += i + "\"batch\": " + std::to_string(r.config.batch) + ",\n";
    s += i + "\"shadow_culling\": " + (r.config.shadow_culling ? "true" : "false") + ",\n";
    s += i + "\"shadow_proxy\": " + (r.config.shadow_proxy ? "true" : "false") + ",\n";
    s += i + "\"shadow_lod\": " + (r.config.shadow_lod ? "true" : "false") + ",\n";
    s += i + "\"backface_culling\": " + (r.config.backface_culling ? "true" : "false") + ",\n";
    s += i + "\"interleave\": " + std::to_string(r.config.interleave) + ",\n";
    s += i + "\"batches_per_position\": " + std::to_string(r.config.batches_per_position) + ",\n";
    s += i + "\"devices\": " + std::to_string(r.config.devices) + ",\n";
    s += i + "\"hemicube\": " + (r.config.hemicube ? "true" : "false") + ",\n";
    s += i + "\"vpl_culling\": " + (r.config.vpl_culling ? "true" : "false") + ",\n";
    const bool chains = r.config.chain_roughness >= 0.0f;
    s += i + "\"chains\": " + (chains ? "true" : "false") + ",\n";
    if (chains) s += i + "\"chain_roughness\": " + number(r.config.chain_roughness) + ",\n";
    s += i + "\"chain_ms\": " + number(r.median.chain_ms) + ",\n";
    s += i + "\"chain_rays\": " + std::to_string(r.median.chain_rays) + ",\n";
    s += i + "\"culled_vpls\": " + std::to_string(r.median.culled_vpls) + ",\n";
    s += i + "\"shadow_texels_per_vpl\": " + number(r.shadow_texels_per_vpl) + ",\n";
    s += i + "\"shadow_triangles_per_vpl\": " + number(r.shadow_triangles_per_vpl) + ",\n";
    s += i + "\"shadow_front_only_share\": " + number(r.shadow_front_only_share) + ",\n";
    s += i + "\"jitter\": " + (r.config.jitter ? "true" : "false") + ",\n";
    s += i + "\"batches\": " + std::to_string(r.median.batches) + ",\n";
    s += i + "\"g_buffers\": " + std::to_string(r.median.g_buffers) + ",\n";
    s += i + "\"g_buffer_ms\": " + number(r.median.g_buffer_ms) + ",\n";
    s += i + "\"shadow_ms\": " + number(r.median.shadow_ms) + ",\n";
    s += i + "\"shadow_ms_per_vpl\": " + number(r.shadow_ms_per_vpl) + ",\n";
    s += i + "\"shading_ms\": " + number(r.median.shading_ms) + ",\n";
    s += i + "\"shading_ms_per_vpl\": " + number(r.shading_ms_per_vpl) + ",\n";
    s += i + "\"shading_pixel_vpls_per_s\": " + number(r.shading_pixel_vpls_per_s) + ",\n";
    s += i + "\"render_wall_s\": " + number(r.median.wall_s) + ",\n";
    s += i + "\"end_to_end_s\": " + number(r.end_to_end_s) + ",\n";
    s += i + "\"end_to_end_vpls_per_s\": " + number(r.end_to_end_vpls_per_s) + "\n";
    return s + indent + "}";
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
           (c.devices == 1 ? " device" : " devices");
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
    const double n = double(vpls);
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
    return r;
}

std::string bench_json(const BenchReport& b) {
    std::string s = "{\n";
    s += "  \"scene\": " + quoted(b.scene) + ",\n";
    s += "  \"triangles\": " + std::to_string(b.triangles) + ",\n";
    s += "  \"device\": " + quoted(b.device) + ",\n";
    s += "  \"repeat\": " + std::to_string(b.repeat) + ",\n";
    s += std::string("  \"shadows\": ") + (b.shadows ? "true" : "false") + ",\n";
    s += "  \"ranks\": " + std::to_string(b.ranks) + ",\n";
    s += "  \"startup\": {\n";
    s += "    \"scene_load_s\": " + number(b.scene_load_s) + ",\n";
    s += "    \"bvh_build_s\": " + number(b.bvh_build_s) + ",\n";
    s += "    \"context_s\": " + number(b.context_s) + ",\n";
    s += "    \"renderer_s\": " + number(b.renderer_s) + ",\n";
    s += "    \"total_s\": " + number(b.startup_s()) + "\n";
    s += "  },\n";
    s += "  \"light_paths\": {\n";
    s += "    \"paths\": " + std::to_string(b.paths) + ",\n";
    s += "    \"vpls\": " + std::to_string(b.vpls) + ",\n";
    s += "    \"seconds\": " + number(b.sampling_s) + ",\n";
    s += "    \"paths_per_s\": " + number(b.paths_per_s()) + ",\n";
    s += "    \"vpls_per_s\": " + number(b.sampling_vpls_per_s()) + "\n";
    s += "  },\n";
    s += "  \"render\": " + render_json(b.main, "  ") + ",\n";
    s += "  \"sweep\": [";
    for (size_t i = 0; i < b.sweep.size(); ++i) {
        s += (i ? ", " : "\n    ") + render_json(b.sweep[i], "    ");
    }
    s += b.sweep.empty() ? "],\n" : "\n  ],\n";
    s += "  \"memory\": {\n";
    s += "    \"peak_host_bytes\": " + std::to_string(b.peak_host_bytes) + ",\n";
    s += "    \"peak_device_bytes\": " + std::to_string(b.peak_device_bytes) + "\n";
    s += "  }\n";
    return s + "}\n";
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
