// CPU ≡ GPU for every material node and closure type: a compute shader assembled by the material
// code generator (GlslModule) evaluates each node's GLSL function at 12 000 random inputs, and the
// node's C++ evaluator (NodeKind's evaluator from nodes/*.cpp, the closures' eval functions) must
// agree.
//
// Tolerance: |gpu − cpu| ≤ 1e-4 · |cpu| + 1e-6. The relative bound is the acceptance criterion;
// the absolute 1e-6 covers values that cancel to ~0 (a BRDF term times a Schlick weight ~1e-10
// near normal incidence), where one ulp of an input is already a large relative change.
// Documented singularities, excluded from the inputs: GGX roughness below 0.05 (α < 0.0025), where
// the lobe's peak D ∝ 1/α² makes a 1-ulp difference of the half vector (CPU and GPU round
// normalize() differently) a relative change of D above 1e-4 — conditioning, not a discrepancy;
// and texture coordinates within 1e-4 texels of a texel boundary under nearest filtering or of a
// wrap boundary, where floor() of a coordinate that differs by one ulp picks the neighbour.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "engine/gpu/buffer.h"
#include "engine/gpu/command_list.h"
#include "engine/gpu/compute_pipeline.h"
#include "engine/gpu/image.h"
#include "engine/gpu/shader_compiler.h"
#include "engine/material/bsdf.h"
#include "engine/material/conductor.h"
#include "engine/material/dielectric_diffuse.h"
#include "engine/material/lambertian.h"
#include "engine/material/material_codegen.h"
#include "engine/material/node_graph.h"
#include "tests/gpu/gpu_test.h"

namespace mvpl::gpu {
namespace {

using NodeEvalTest = testing::GpuTest;
using namespace mvpl::material;

constexpr uint32_t kInputs = 64;   // floats per record in
constexpr uint32_t kOutputs = 51;  // floats per record out
constexpr uint32_t kRecords = 12000;
constexpr int kTexWidth = 5;
constexpr int kTexHeight = 3;

// The shader: the node functions from the library, dependencies first, then a main that
// unpacks one record per invocation (layout as in make_record below).
std::string test_shader() {
    GlslModule m;
    for (const char* f :
         {"Closure", "SurfacePoint", "image_texture", "vertex_color", "multiply", "mix_node",
          "emission", "normal_map", "bump_map", "lambertian", "ggx_conductor", "dielectric_diffuse",
          "metal_rough", "rough_dielectric", "lambertian_eval", "ggx_conductor_eval",
          "dielectric_diffuse_eval", "metal_rough_eval", "metal_rough_diffuse_eval"}) {
        m.require(f);
    }
    return "#version 460\nlayout(local_size_x = 64) in;\n"
           "layout(set = 0, binding = 0) readonly buffer In { float x[]; };\n"
           "layout(set = 0, binding = 1) writeonly buffer Out { float y[]; };\n"
           "layout(set = 0, binding = 2) uniform sampler2D tex;\n"
           "layout(push_constant) uniform P { uint count; } pc;\n" +
           m.code() + R"(
vec2 in2(uint b, int i) { return vec2(x[b + i], x[b + i + 1]); }
vec3 in3(uint b, int i) { return vec3(x[b + i], x[b + i + 1], x[b + i + 2]); }
vec4 in4(uint b, int i) { return vec4(x[b + i], x[b + i + 1], x[b + i + 2], x[b + i + 3]); }
void out4(uint o, int i, vec4 v) { y[o + i] = v.x; y[o + i + 1] = v.y; y[o + i + 2] = v.z; y[o + i + 3] = v.w; }
void out3(uint o, int i, vec3 v) { y[o + i] = v.x; y[o + i + 1] = v.y; y[o + i + 2] = v.z; }
void main() {
    const uint r = gl_GlobalInvocationID.x;
    if (r >= pc.count) return;
    const uint b = r * 64u;
    const uint o = r * 51u;
    out4(o, 0, image_texture(tex, in2(b, 0), in2(b, 2), x[b + 4], in2(b, 5), int(x[b + 7]),
                             int(x[b + 8]), int(x[b + 9]), in4(b, 10)));
    out4(o, 4, vertex_color(in4(b, 10), in4(b, 14)));
    out4(o, 8, mix_node(in4(b, 18), in4(b, 22), x[b + 26]));
    out4(o, 12, emission(in4(b, 14), x[b + 27]));
    SurfacePoint s;
    s.uv0 = vec2(0.0);
    s.uv1 = vec2(0.0);
    s.color = vec4(1.0);
    s.n = in3(b, 28);
    s.t = in3(b, 57);
    s.b = in3(b, 60);
    out3(o, 16, normal_map(in3(b, 32), x[b + 31], s));
    out3(o, 19, bump_map(x[b + 35], x[b + 36], x[b + 37], x[b + 38], x[b + 39], x[b + 31], s));
    const int kind = int(x[b + 50]);
    const vec3 base = in3(b, 40);
    Closure c;
    if (kind == 0) c = lambertian(base);
    else if (kind == 1) c = ggx_conductor(base, x[b + 44]);
    else if (kind == 2) c = dielectric_diffuse(base, x[b + 44], x[b + 45], in3(b, 46), x[b + 49]);
    else if (kind == 3) c = metal_rough(base, x[b + 43], x[b + 44], x[b + 45], in3(b, 46), x[b + 49]);
    else c = rough_dielectric(x[b + 44], x[b + 45], in3(b, 46), x[b + 49]);
    y[o + 22] = float(c.type);
    out3(o, 23, c.base_color);
    y[o + 26] = c.metallic;
    out3(o, 27, c.specular_color);
    y[o + 30] = c.specular;
    y[o + 31] = c.roughness;
    y[o + 32] = c.ior;
    const vec3 wo = in3(b, 51);
    const vec3 wi = in3(b, 54);
    out3(o, 33, lambertian_eval(c, s.n, wo, wi));
    out3(o, 36, ggx_conductor_eval(c, s.n, wo, wi));
    out3(o, 39, dielectric_diffuse_eval(c, s.n, wo, wi));
    out3(o, 42, metal_rough_eval(c, s.n, wo, wi));
    out3(o, 45, multiply(in4(b, 10), in4(b, 14)).yzw);  // x is the same code
    out3(o, 48, metal_rough_diffuse_eval(c, s.n, wo, wi));
}
)";
}

struct Record {
    float in[kInputs] = {};
};

Vec3 direction(std::mt19937& rng, const Vec3& n) {
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    Vec3 w;
    do {
        w = Vec3(u(rng), u(rng), u(rng));
    } while (glm::dot(w, w) > 1.0f || glm::dot(w, w) < 1e-4f);
    w = glm::normalize(w);
    // 90 % above the surface: the interesting side.
    if (glm::dot(w, n) < 0.0f && rng() % 10 != 0) w = -w;
    return w;
}

Record make_record(std::mt19937& rng) {
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::uniform_real_distribution<float> s(-3.0f, 3.0f);
    Record r;
    float* x = r.in;
    const auto put = [&](int i, std::initializer_list<float> v) {
        for (float f : v)
            x[i++] = f;
    };
    put(0, {s(rng), s(rng), s(rng), s(rng), rng() % 2 ? s(rng) : 0.0f, s(rng), s(rng)});
    put(7, {float(rng() % 3), float(rng() % 3), float(rng() % 2)});
    put(10, {2.0f * u(rng), 2.0f * u(rng), 2.0f * u(rng), u(rng)});
    put(14, {u(rng), u(rng), u(rng), u(rng)});
    put(18, {s(rng), s(rng), s(rng), s(rng), s(rng), s(rng), s(rng), s(rng), 1.4f * u(rng) - 0.2f});
    put(27, {10.0f * u(rng)});
    const Vec3 n = direction(rng, Vec3(0.0f, 0.0f, 1.0f));
    const Frame frame(n);
    put(28, {n.x, n.y, n.z, 2.0f * u(rng), u(rng), u(rng), u(rng)});
    put(35, {u(rng), u(rng), u(rng), 0.01f + 0.1f * u(rng), 0.01f + 0.1f * u(rng)});
    const auto pick = [&](float v) {
        const uint32_t k = rng() % 5;
        return k == 0 ? 0.0f : k == 1 ? 1.0f : v;
    };
    put(40, {1.2f * u(rng), u(rng), u(rng), pick(u(rng)), 0.05f + 0.95f * u(rng), pick(u(rng)),
             2.0f * u(rng), u(rng), u(rng), 1.0f + 2.0f * u(rng), float(rng() % 5)});
    const Vec3 wo = direction(rng, n);
    const Vec3 wi = direction(rng, n);
    put(51, {wo.x, wo.y, wo.z, wi.x, wi.y, wi.z});
    put(57, {frame.s.x, frame.s.y, frame.s.z, frame.t.x, frame.t.y, frame.t.z});
    return r;
}

// A node's C++ evaluator on given input values, as the graph would have evaluated them: `inputs`
// at the point, and for bump mapping the height one step along u (`along_u`) and along v.
class GivenInputs final : public NodeContext {
public:
    GivenInputs(const Node& node, const SurfacePoint& point, std::vector<Vec4> inputs,
                const scene::Texture* texture = nullptr)
        : m_node(node), m_point(point), m_inputs(std::move(inputs)), m_texture(texture) {}
    void set_bump(const Vec2& step, const Vec4& along_u, const Vec4& along_v) {
        m_step = step;
        m_along_u = along_u;
        m_along_v = along_v;
    }

    const Node& node() const override { return m_node; }
    const SurfacePoint& point() const override { return m_point; }
    Vec4 input_at(int k, const SurfacePoint& p) const override {
        if (p.uv0.x > m_point.uv0.x) return m_along_u;
        if (p.uv0.y > m_point.uv0.y) return m_along_v;
        return size_t(k) < m_inputs.size() ? m_inputs[size_t(k)] : Vec4(0.0f);
    }
    Vec2 texel_step(int) const override { return m_step; }
    const scene::Texture* texture() const override { return m_texture; }

private:
    const Node& m_node;
    const SurfacePoint& m_point;
    std::vector<Vec4> m_inputs;
    const scene::Texture* m_texture;
    Vec2 m_step{0.0f};
    Vec4 m_along_u{0.0f};
    Vec4 m_along_v{0.0f};
};

Node node_of(std::string_view kind, const Vec4& value = Vec4(1.0f)) {
    Node n;
    n.kind = &node_kind(kind);
    n.value = value;
    return n;
}

Vec4 scalar(float v) {
    return Vec4(v);
}

Vec4 colour(const Vec3& v) {
    return Vec4(v, 1.0f);
}

// The closure node the record's x[50] names, on the record's inputs.
ClosureParams cpu_closure(const float* x) {
    const auto v3 = [&](int i) { return Vec3(x[i], x[i + 1], x[i + 2]); };
    const int kind = int(x[50]);
    const Vec4 base = colour(v3(40));
    const Vec4 spec = colour(v3(46));
    const SurfacePoint plain;
    const auto closure = [&](std::string_view name, std::vector<Vec4> inputs) {
        const Node n = node_of(name);
        return n.kind->closure(GivenInputs(n, plain, std::move(inputs)));
    };
    if (kind == 0) return closure("lambertian", {base});
    if (kind == 1) return closure("ggx_conductor", {base, scalar(x[44])});
    if (kind == 2)
        return closure("dielectric_diffuse",
                       {base, scalar(x[44]), scalar(x[45]), spec, scalar(x[49])});
    if (kind == 3)
        return closure("metal_rough",
                       {base, scalar(x[43]), scalar(x[44]), scalar(x[45]), spec, scalar(x[49])});
    return closure("rough_dielectric", {scalar(x[44]), scalar(x[45]), spec, scalar(x[49])});
}

// The C++ evaluators on the same record.
std::vector<float> cpu_eval(const Record& r, const scene::Texture& base_texture) {
    const float* x = r.in;
    std::vector<float> y(kOutputs, 0.0f);
    const auto v2 = [&](int i) { return Vec2(x[i], x[i + 1]); };
    const auto v3 = [&](int i) { return Vec3(x[i], x[i + 1], x[i + 2]); };
    const auto v4 = [&](int i) { return Vec4(x[i], x[i + 1], x[i + 2], x[i + 3]); };
    const auto out = [&](int i, auto v, int n) {
        for (int k = 0; k < n; ++k)
            y[size_t(i + k)] = v[k];
    };
    scene::Texture t = base_texture;
    t.wrap_s = scene::Wrap(int(x[7]));
    t.wrap_t = scene::Wrap(int(x[8]));
    // GLSL filter 0 is nearest (material_codegen.cpp).
    t.filter = int(x[9]) == 0 ? scene::Filter::Nearest : scene::Filter::Linear;
    Node texture = node_of("image_texture", v4(10));
    texture.texture.texture = 0;
    texture.texture.offset = v2(2);
    texture.texture.rotation = x[4];
    texture.texture.scale = v2(5);
    SurfacePoint at_uv;
    at_uv.uv0 = v2(0);
    out(0, texture.kind->value(GivenInputs(texture, at_uv, {}, &t)), 4);
    SurfacePoint coloured;
    coloured.color = v4(14);
    const Node vertex = node_of("vertex_color", v4(10));
    out(4, vertex.kind->value(GivenInputs(vertex, coloured, {})), 4);
    const SurfacePoint plain;
    const Node mix = node_of("mix_node");
    out(8, mix.kind->value(GivenInputs(mix, plain, {v4(18), v4(22), scalar(x[26])})), 4);
    const Node emission = node_of("emission", Vec4(x[27]));
    out(12, emission.kind->value(GivenInputs(emission, plain, {v4(14)})), 4);
    const Frame frame(v3(57), v3(60), v3(28));
    SurfacePoint framed;
    framed.frame = frame;
    const Node normal = node_of("normal_map", Vec4(x[31]));
    out(16, normal.kind->normal(GivenInputs(normal, framed, {colour(v3(32))})), 3);
    const Node bump = node_of("bump_map", Vec4(x[31]));
    GivenInputs heights(bump, framed, {scalar(x[35])});
    heights.set_bump(v2(38), scalar(x[36]), scalar(x[37]));
    out(19, bump.kind->normal(heights), 3);
    const ClosureParams c = cpu_closure(x);
    y[22] = float(uint32_t(closure_type(c)));
    out(23, c.base_color, 3);
    y[26] = c.metallic;
    out(27, c.specular_color, 3);
    y[30] = c.specular;
    y[31] = c.roughness;
    y[32] = c.ior;
    const Vec3 wo = Frame(frame.n).to_local(v3(51));
    const Vec3 wi = Frame(frame.n).to_local(v3(54));
    const float alpha = roughness_to_alpha(c.roughness);
    out(33, lambertian_eval(c.base_color, wo, wi), 3);
    out(36, conductor_eval(c.base_color, alpha, wo, wi), 3);
    out(39,
        dielectric_diffuse_eval(c.base_color, dielectric_layer(c.specular_color, c.specular, c.ior),
                                alpha, wo, wi),
        3);
    out(42, Bsdf(c).eval(wo, wi), 3);
    const Node product = node_of("multiply");
    const Vec4 m = product.kind->value(GivenInputs(product, plain, {v4(10), v4(14)}));
    out(45, Vec3(m.y, m.z, m.w), 3);
    out(48, Bsdf(c).eval_diffuse(wo, wi), 3);
    return y;
}

const char* output_name(int i) {
    if (i < 4) return "image_texture";
    if (i < 8) return "vertex_color";
    if (i < 12) return "mix_node";
    if (i < 16) return "emission";
    if (i < 19) return "normal_map";
    if (i < 22) return "bump_map";
    if (i < 33) return "closure node";
    if (i < 36) return "lambertian_eval";
    if (i < 39) return "ggx_conductor_eval";
    if (i < 42) return "dielectric_diffuse_eval";
    if (i < 45) return "metal_rough_eval";
    if (i < 48) return "multiply";
    return "metal_rough_diffuse_eval";
}

// Nearest filtering or a wrap discontinuity within 1e-4 texels of the sample point (see top).
bool near_texel_boundary(const Record& r) {
    const float* x = r.in;
    Vec2 st = Vec2(x[0], x[1]) * Vec2(x[5], x[6]);
    if (x[4] != 0.0f) {
        const float c = std::cos(x[4]);
        const float s = std::sin(x[4]);
        st = Vec2(c * st.x + s * st.y, -s * st.x + c * st.y);
    }
    st += Vec2(x[2], x[3]);
    const float px = st.x * kTexWidth;
    const float py = st.y * kTexHeight;
    const auto near = [](float v, float shift) {
        const float f = v - shift;
        return std::abs(f - std::round(f)) < 1e-3f;  // ~1e-4 texels after the ±3 ranges' rounding
    };
    // Texel edges (nearest) and texel centres (bilinear's floor) both switch neighbours.
    return near(px, 0.0f) || near(py, 0.0f) || near(px, 0.5f) || near(py, 0.5f);
}

TEST_F(NodeEvalTest, EveryNodeAndClosureTypeAgreesWithItsCppEvaluator) {
    std::mt19937 rng(2024);
    scene::Texture tex;
    tex.width = kTexWidth;
    tex.height = kTexHeight;
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (int i = 0; i < kTexWidth * kTexHeight; ++i)
        tex.texels.emplace_back(u(rng), u(rng), u(rng), u(rng));
    std::vector<Record> records;
    while (records.size() < kRecords) {
        const Record r = make_record(rng);
        if (!near_texel_boundary(r)) records.push_back(r);
    }

    Buffer in(context(), records.size() * sizeof(Record), BufferUsage::storage,
              MemoryLocation::device, "node inputs");
    in.upload(records);
    Buffer out(context(), records.size() * kOutputs * sizeof(float), BufferUsage::storage,
               MemoryLocation::device, "node outputs");
    Image image(context(),
                {kTexWidth, kTexHeight, 1, Format::rgba32_float, ImageUsage::sampled, false},
                "node texture");
    image.upload(tex.texels);
    const ComputePipeline pipeline(
        context(), compile_glsl(ShaderStage::compute, test_shader(), "test_node_eval.comp"),
        {{BindingType::storage_buffer, BindingType::storage_buffer, BindingType::sampled_image},
         sizeof(uint32_t)},
        "node eval");
    const uint32_t count = kRecords;
    context().submit_and_wait([&](CommandList& cmd) {
        cmd.dispatch(pipeline, {&in, &out, &image}, push_bytes(count), (kRecords + 63) / 64);
    });
    const std::vector<float> gpu = out.download<float>(size_t(kRecords) * kOutputs);

    int failures = 0;
    float max_relative = 0.0f;  // over values with |cpu| > 1e-3, reported for the record
    std::vector<int> closure_types(kClosureTypeCount, 0);
    for (size_t r = 0; r < records.size(); ++r) {
        const std::vector<float> cpu = cpu_eval(records[r], tex);
        closure_types[size_t(cpu[22])]++;
        for (int i = 0; i < int(kOutputs); ++i) {
            const float c = cpu[size_t(i)];
            const float g = gpu[r * kOutputs + size_t(i)];
            if (std::abs(c) > 1e-3f)
                max_relative = std::max(max_relative, std::abs(g - c) / std::abs(c));
            if (!(std::abs(g - c) <= 1e-4f * std::abs(c) + 1e-6f) && failures++ < 10) {
                ADD_FAILURE() << output_name(i) << " [" << i << "] record " << r << ": GPU " << g
                              << ", CPU " << c;
            }
        }
    }
    EXPECT_EQ(failures, 0);
    std::printf("max relative error (|cpu| > 1e-3): %.3g\n", double(max_relative));
    // Every closure type occurred often.
    for (int t = 0; t < kClosureTypeCount; ++t)
        EXPECT_GT(closure_types[size_t(t)], 500) << t;
}

}  // namespace
}  // namespace mvpl::gpu
