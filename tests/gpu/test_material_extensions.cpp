// CPU ≡ GPU for the two shading models beyond metallic-roughness: a KHR_materials_
// pbrSpecularGlossiness material (diffuse and specular-glossiness textures, the spec_gloss node)
// and a KHR_materials_unlit one (base colour texture times COLOR_0 as emission, a black
// closure), as generate_material_code writes them for the G-buffer, run in a compute shader at
// 4096 random surface points against evaluate_closure and evaluate_emission on the CPU.
//
// Tolerance: |gpu − cpu| ≤ 1e-5 · |cpu| + 1e-6 per value. Both sides fetch the same texels and
// filter them with the same arithmetic (image_texture); what differs is float rounding in the
// bilinear weights and the products after them, a few ulps.
#include <gtest/gtest.h>

#include <random>

#include "engine/gpu/buffer.h"
#include "engine/gpu/command_list.h"
#include "engine/gpu/compute_pipeline.h"
#include "engine/gpu/image.h"
#include "engine/gpu/shader_compiler.h"
#include "engine/material/graph_eval.h"
#include "engine/material/material_codegen.h"
#include "tests/gpu/gpu_test.h"

namespace mvpl::gpu {
namespace {

using MaterialExtensionsTest = testing::GpuTest;
using namespace mvpl::material;

constexpr uint32_t kExtensionPoints = 4096;
constexpr uint32_t kValues = 14;  // per point and material: closure (11), emission (3)

struct PointIn {
    Vec2 uv;
    Vec2 pad{0.0f};
    Vec4 color;
};

std::string shader(const MaterialCode& code) {
    return "#version 460\nlayout(local_size_x = 64) in;\n"
           "struct PointIn { vec2 uv; vec2 pad; vec4 color; };\n"
           "layout(set = 0, binding = 0) readonly buffer In { PointIn p[]; };\n"
           "layout(set = 0, binding = 1) writeonly buffer Out { float y[]; };\n" +
           code.bindings + "layout(push_constant) uniform P { uint count; } pc;\n" +
           code.functions + R"(
void main() {
    const uint i = gl_GlobalInvocationID.x;
    if (i >= pc.count) return;
    SurfacePoint s;
    s.uv0 = p[i].uv;
    s.uv1 = p[i].uv;
    s.color = p[i].color;
    s.t = vec3(1.0, 0.0, 0.0);
    s.b = vec3(0.0, 0.0, -1.0);
    s.n = vec3(0.0, 1.0, 0.0);
    for (uint m = 0u; m < 2u; ++m) {
        Closure c;
        vec3 e;
        vec3 normal;
        resolve_material(m, s, c, e, normal);
        const uint o = (2u * i + m) * 14u;
        y[o] = c.base_color.r; y[o + 1u] = c.base_color.g; y[o + 2u] = c.base_color.b;
        y[o + 3u] = c.metallic; y[o + 4u] = c.roughness; y[o + 5u] = c.specular;
        y[o + 6u] = c.specular_color.r; y[o + 7u] = c.specular_color.g;
        y[o + 8u] = c.specular_color.b; y[o + 9u] = c.ior; y[o + 10u] = float(c.type);
        y[o + 11u] = e.r; y[o + 12u] = e.g; y[o + 13u] = e.b;
    }
}
)";
}

std::array<float, kValues> cpu_values(const MaterialGraph& g,
                                      const std::vector<scene::Texture>& textures,
                                      const SurfacePoint& p) {
    const ClosureParams c = evaluate_closure(g, textures, p);
    const Rgb e = evaluate_emission(g, textures, p);
    return {c.base_color.r,
            c.base_color.g,
            c.base_color.b,
            c.metallic,
            c.roughness,
            c.specular,
            c.specular_color.r,
            c.specular_color.g,
            c.specular_color.b,
            c.ior,
            float(uint32_t(closure_type(c))),
            e.r,
            e.g,
            e.b};
}

std::vector<MaterialGraph> graphs() {
    scene::TextureRef diffuse;
    diffuse.texture = 0;
    scene::TextureRef spec_gloss = diffuse;
    spec_gloss.texture = 1;
    scene::Material sg;
    sg.shading = scene::ShadingModel::SpecGloss;
    sg.base_color = Rgb(0.9f, 0.7f, 1.0f);
    sg.base_color_texture = diffuse;
    sg.spec_gloss_specular = Rgb(0.8f, 1.0f, 0.6f);
    sg.glossiness = 0.9f;
    sg.specular_glossiness_texture = spec_gloss;
    scene::Material unlit;
    unlit.shading = scene::ShadingModel::Unlit;
    unlit.base_color = Rgb(1.0f, 0.2176f, 0.5f);
    unlit.base_color_texture = diffuse;
    return {graph_from_gltf(sg), graph_from_gltf(unlit, {.vertex_colors = true})};
}

TEST_F(MaterialExtensionsTest, SpecGlossAndUnlitAgreeWithTheCpuGraphs) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<scene::Texture> textures(2);
    for (scene::Texture& t : textures) {
        t.width = 4;
        t.height = 3;
        t.filter = scene::Filter::Linear;
        for (int i = 0; i < t.width * t.height; ++i)
            t.texels.emplace_back(u(rng), u(rng), u(rng), u(rng));
    }
    const std::vector<MaterialGraph> g = graphs();
    const MaterialCode code = generate_material_code(g, textures, 2);
    ASSERT_EQ(code.textures, (std::vector<int>{0, 1}));

    std::vector<PointIn> points;
    for (uint32_t i = 0; i < kExtensionPoints; ++i) {
        points.push_back({Vec2(3.0f * u(rng) - 1.0f, 3.0f * u(rng) - 1.0f), Vec2(0.0f),
                          Vec4(u(rng), u(rng), u(rng), 1.0f)});
    }
    Buffer in(context(), points.size() * sizeof(PointIn), BufferUsage::storage,
              MemoryLocation::device, "surface points");
    in.upload(points);
    Buffer out(context(), size_t(kExtensionPoints) * 2 * kValues * sizeof(float),
               BufferUsage::storage, MemoryLocation::device, "closures");
    std::vector<std::unique_ptr<Image>> images;
    for (const scene::Texture& t : textures) {
        images.push_back(std::make_unique<Image>(
            context(), ImageDesc{4, 3, 1, Format::rgba32_float, ImageUsage::sampled, false},
            "texture"));
        images.back()->upload(t.texels);
    }
    const ComputePipeline pipeline(
        context(),
        compile_glsl(ShaderStage::compute, shader(code), "test_material_extensions.comp"),
        {{BindingType::storage_buffer, BindingType::storage_buffer, BindingType::sampled_image,
          BindingType::sampled_image},
         sizeof(uint32_t)},
        "material extensions");
    context().submit_and_wait([&](CommandList& cmd) {
        cmd.dispatch(pipeline, {&in, &out, images[0].get(), images[1].get()},
                     push_bytes(kExtensionPoints), (kExtensionPoints + 63) / 64);
    });
    const std::vector<float> gpu = out.download<float>(size_t(kExtensionPoints) * 2 * kValues);

    int failures = 0;
    for (uint32_t i = 0; i < kExtensionPoints; ++i) {
        SurfacePoint p;
        p.uv0 = p.uv1 = points[i].uv;
        p.color = points[i].color;
        p.frame = Frame(Vec3(1, 0, 0), Vec3(0, 0, -1), Vec3(0, 1, 0));
        for (uint32_t m = 0; m < 2; ++m) {
            const std::array<float, kValues> cpu = cpu_values(g[m], textures, p);
            for (uint32_t k = 0; k < kValues; ++k) {
                const float c = cpu[k];
                const float v = gpu[(2 * i + m) * kValues + k];
                if (!(std::abs(v - c) <= 1e-5f * std::abs(c) + 1e-6f) && failures++ < 10) {
                    ADD_FAILURE() << (m == 0 ? "spec-gloss" : "unlit") << " value " << k
                                  << " point " << i << ": GPU " << v << ", CPU " << c;
                }
            }
        }
    }
    EXPECT_EQ(failures, 0);
}

}  // namespace
}  // namespace mvpl::gpu
