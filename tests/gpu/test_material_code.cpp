// CPU ≡ GPU for a whole generated material, not just its node functions: the GLSL that
// generate_material_code writes for a bump-mapped graph (image texture → bump_map, whose
// generated code evaluates the height at three points through a generated helper) runs in a
// compute shader at 4096 random surface points, against evaluate_normal on the CPU.
//
// Tolerance: |n_gpu − n_cpu| ≤ 1e-4. Both sides fetch the same texels and filter with the same
// arithmetic; what differs is float rounding in the bilinear weights (~1e-7 of a height), which
// the forward difference over one texel (÷ du = 1/4) and the bump scale (0.5) amplify to ~1e-6.
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

using MaterialCodeTest = testing::GpuTest;
using namespace mvpl::material;

constexpr uint32_t kPoints = 4096;

MaterialGraph bump_graph() {
    MaterialGraph g;
    Node lambert;
    lambert.kind = &node_kind("lambertian");
    Node base;
    base.kind = &node_kind("constant");
    base.value = Vec4(0.5f);
    lambert.inputs[0] = {g.add(base), kAllChannels};
    g.closure = g.add(lambert);
    Node height;
    height.kind = &node_kind("image_texture");
    height.texture.texture = 0;
    Node bump;
    bump.kind = &node_kind("bump_map");
    bump.value = Vec4(0.5f);
    bump.inputs[0] = {g.add(height), 1};
    g.normal = g.add(bump);
    return g;
}

std::string shader(const MaterialCode& code) {
    return "#version 460\nlayout(local_size_x = 64) in;\n"
           "layout(set = 0, binding = 0) readonly buffer In { vec2 uv[]; };\n"
           "layout(set = 0, binding = 1) writeonly buffer Out { float n[]; };\n" +
           code.bindings + "layout(push_constant) uniform P { uint count; } pc;\n" +
           code.functions + R"(
void main() {
    const uint i = gl_GlobalInvocationID.x;
    if (i >= pc.count) return;
    SurfacePoint s;
    s.uv0 = uv[i];
    s.uv1 = uv[i];
    s.color = vec4(1.0);
    s.t = vec3(1.0, 0.0, 0.0);
    s.b = vec3(0.0, 0.0, -1.0);
    s.n = vec3(0.0, 1.0, 0.0);
    Closure c;
    vec3 e;
    vec3 normal;
    resolve_material(0u, s, c, e, normal);
    n[3u * i] = normal.x;
    n[3u * i + 1u] = normal.y;
    n[3u * i + 2u] = normal.z;
}
)";
}

TEST_F(MaterialCodeTest, BumpMappedMaterialAgreesWithTheCpuGraph) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    scene::Texture tex;
    tex.width = 4;
    tex.height = 3;
    tex.filter = scene::Filter::Linear;
    for (int i = 0; i < tex.width * tex.height; ++i)
        tex.texels.emplace_back(u(rng), u(rng), u(rng), 1.0f);
    const std::vector<scene::Texture> textures{tex};
    const MaterialGraph graph = bump_graph();
    const MaterialCode code = generate_material_code({graph}, textures, 2);
    ASSERT_EQ(code.textures, std::vector<int>{0});

    std::vector<Vec2> uvs;
    for (uint32_t i = 0; i < kPoints; ++i)
        uvs.emplace_back(3.0f * u(rng) - 1.0f, 3.0f * u(rng) - 1.0f);
    Buffer in(context(), uvs.size() * sizeof(Vec2), BufferUsage::storage, MemoryLocation::device,
              "surface points");
    in.upload(uvs);
    Buffer out(context(), uvs.size() * 3 * sizeof(float), BufferUsage::storage,
               MemoryLocation::device, "normals");
    Image image(context(), {4, 3, 1, Format::rgba32_float, ImageUsage::sampled, false}, "height");
    image.upload(tex.texels);
    const ComputePipeline pipeline(
        context(), compile_glsl(ShaderStage::compute, shader(code), "test_material_code.comp"),
        {{BindingType::storage_buffer, BindingType::storage_buffer, BindingType::sampled_image},
         sizeof(uint32_t)},
        "material code");
    context().submit_and_wait([&](CommandList& cmd) {
        cmd.dispatch(pipeline, {&in, &out, &image}, push_bytes(kPoints), (kPoints + 63) / 64);
    });
    const std::vector<float> gpu = out.download<float>(size_t(kPoints) * 3);

    int failures = 0;
    int tilted = 0;
    for (uint32_t i = 0; i < kPoints; ++i) {
        SurfacePoint p;
        p.uv0 = p.uv1 = uvs[i];
        p.frame = Frame(Vec3(1, 0, 0), Vec3(0, 0, -1), Vec3(0, 1, 0));
        const Vec3 cpu = evaluate_normal(graph, textures, p);
        const Vec3 g(gpu[3 * i], gpu[3 * i + 1], gpu[3 * i + 2]);
        if (cpu.y < 0.999f) ++tilted;
        if (!(glm::length(g - cpu) <= 1e-4f) && failures++ < 10) {
            ADD_FAILURE() << "point " << i << " uv (" << uvs[i].x << ", " << uvs[i].y
                          << "): GPU (" << g.x << ", " << g.y << ", " << g.z << "), CPU ("
                          << cpu.x << ", " << cpu.y << ", " << cpu.z << ")";
        }
    }
    EXPECT_EQ(failures, 0);
    // The height field does tilt the normals (the test is not comparing two flat answers).
    EXPECT_GT(tilted, int(kPoints) / 2);
}

}  // namespace
}  // namespace mvpl::gpu
