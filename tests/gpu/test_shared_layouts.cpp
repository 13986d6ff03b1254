// The layouts of shaders/shared as glslang lays them out (the Offset decorations of the SPIR-V)
// against the offsets of the same headers compiled as C++: the check that the headers'
// MVPL_STD430_MEMBER asserts (prelude.h: each member on a multiple of its std430 alignment) encode
// the rules right.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "engine/gpu/shader_compiler.h"
#include "shaders/shared/chain_record.h"
#include "shaders/shared/closure.h"
#include "shaders/shared/gpu_vpl.h"
#include "shaders/shared/present_push.h"
#include "shaders/shared/push_constants.h"

namespace mvpl::gpu {
namespace {

// Every struct in a buffer block, so that each gets its explicit layout: GpuVpl as the shading
// pass binds it (std140 uniform buffer), the push constants std430 as push constants are.
const char* const kSource = R"(#version 460
#extension GL_GOOGLE_include_directive : require
#include "shared/chain_record.h"
#include "shared/gpu_vpl.h"
#include "shared/present_push.h"
#include "shared/push_constants.h"
layout(local_size_x = 1) in;
layout(std140, binding = 0) uniform U0 { GpuVpl vpl; };
layout(std430, binding = 1) buffer B1 { GBufferPush g_buffer; };
layout(std430, binding = 2) buffer B2 { MaterialPush material; };
layout(std430, binding = 3) buffer B3 { ShadowPush shadow; };
layout(std430, binding = 4) buffer B4 { OrthoPush ortho; };
layout(std430, binding = 5) buffer B5 { ShadingPush shading; };
layout(std430, binding = 6) buffer B6 { PresentPush present; };
layout(std430, binding = 7) buffer B7 { EmissionPush emission; };
layout(std430, binding = 8) buffer B8 { ChainRecord chain; };
layout(std430, binding = 9) buffer B9 { InterleavePush interleave; };
void main() {
    shading.vpl_count = vpl.type + g_buffer.material + material.size.x + shadow.face.x +
                        uint(ortho.extents.x) + present.width + emission.layer + chain.state +
                        interleave.interleave;
}
)";

struct Member {
    const char* type;
    const char* name;
    size_t offset;
};

#define MVPL_MEMBER(S, m)              \
    Member {                           \
#S, #m, offsetof(shared::S, m) \
    }

const Member kMembers[] = {
    MVPL_MEMBER(GpuVpl, position),
    MVPL_MEMBER(GpuVpl, type),
    MVPL_MEMBER(GpuVpl, normal),
    MVPL_MEMBER(GpuVpl, cos_inner),
    MVPL_MEMBER(GpuVpl, shading_normal),
    MVPL_MEMBER(GpuVpl, cos_outer),
    MVPL_MEMBER(GpuVpl, wi),
    MVPL_MEMBER(GpuVpl, map_extent),
    MVPL_MEMBER(GpuVpl, power),
    MVPL_MEMBER(GpuVpl, map_depth),
    MVPL_MEMBER(GpuVpl, base_color),
    MVPL_MEMBER(GpuVpl, metallic),
    MVPL_MEMBER(GpuVpl, specular_color),
    MVPL_MEMBER(GpuVpl, specular),
    MVPL_MEMBER(GpuVpl, roughness),
    MVPL_MEMBER(GpuVpl, ior),
    MVPL_MEMBER(GpuVpl, closure_type),
    MVPL_MEMBER(GpuVpl, path_length),
    MVPL_MEMBER(ChainRecord, position),
    MVPL_MEMBER(ChainRecord, state),
    MVPL_MEMBER(ChainRecord, shading_normal),
    MVPL_MEMBER(ChainRecord, max_vpl_length),
    MVPL_MEMBER(ChainRecord, geometric_normal),
    MVPL_MEMBER(ChainRecord, metallic),
    MVPL_MEMBER(ChainRecord, base_color),
    MVPL_MEMBER(ChainRecord, roughness),
    MVPL_MEMBER(ChainRecord, specular_color),
    MVPL_MEMBER(ChainRecord, specular),
    MVPL_MEMBER(ChainRecord, wo),
    MVPL_MEMBER(ChainRecord, ior),
    MVPL_MEMBER(ChainRecord, throughput),
    MVPL_MEMBER(ChainRecord, closure_type),
    MVPL_MEMBER(ChainRecord, emitted),
    MVPL_MEMBER(ChainRecord, unused),
    MVPL_MEMBER(GBufferPush, view_proj),
    MVPL_MEMBER(GBufferPush, material_flags),
    MVPL_MEMBER(GBufferPush, material),
    MVPL_MEMBER(GBufferPush, seed),
    MVPL_MEMBER(MaterialPush, size),
    MVPL_MEMBER(EmissionPush, size),
    MVPL_MEMBER(EmissionPush, layer),
    MVPL_MEMBER(EmissionPush, flags),
    MVPL_MEMBER(ShadowPush, vpl_near),
    MVPL_MEMBER(ShadowPush, face),
    MVPL_MEMBER(OrthoPush, u_origin),
    MVPL_MEMBER(OrthoPush, v_origin),
    MVPL_MEMBER(OrthoPush, dir_origin),
    MVPL_MEMBER(OrthoPush, extents),
    MVPL_MEMBER(ShadingPush, camera_position),
    MVPL_MEMBER(ShadingPush, d_min2),
    MVPL_MEMBER(ShadingPush, texel_angle),
    MVPL_MEMBER(ShadingPush, vpl_count),
    MVPL_MEMBER(ShadingPush, flags),
    MVPL_MEMBER(ShadingPush, size),
    MVPL_MEMBER(ShadingPush, interleave),
    MVPL_MEMBER(ShadingPush, vpl_offset),
    MVPL_MEMBER(ShadingPush, vsl_r2),
    MVPL_MEMBER(ShadingPush, pad0),
    MVPL_MEMBER(ShadingPush, pad1),
    MVPL_MEMBER(ShadingPush, pad2),
    MVPL_MEMBER(InterleavePush, size),
    MVPL_MEMBER(InterleavePush, interleave),
    MVPL_MEMBER(InterleavePush, chains),
    MVPL_MEMBER(PresentPush, scale),
    MVPL_MEMBER(PresentPush, exposure_scale),
    MVPL_MEMBER(PresentPush, width),
    MVPL_MEMBER(PresentPush, height),
    MVPL_MEMBER(PresentPush, source_width),
    MVPL_MEMBER(PresentPush, source_height),
    MVPL_MEMBER(PresentPush, hud_x),
    MVPL_MEMBER(PresentPush, hud_y),
    MVPL_MEMBER(PresentPush, hud_width),
    MVPL_MEMBER(PresentPush, hud_height),
    MVPL_MEMBER(PresentPush, linear_target),
    MVPL_MEMBER(PresentPush, cpu_image),
};

#undef MVPL_MEMBER

// "Type.member" → Offset, from OpName, OpMemberName and OpMemberDecorate … Offset.
std::map<std::string, size_t> member_offsets(const std::vector<uint32_t>& spirv) {
    constexpr uint32_t kOpName = 5;
    constexpr uint32_t kOpMemberName = 6;
    constexpr uint32_t kOpMemberDecorate = 72;
    constexpr uint32_t kDecorationOffset = 35;
    const auto text = [&](size_t word) {
        return std::string(reinterpret_cast<const char*>(&spirv[word]));
    };
    std::map<uint32_t, std::string> names;
    std::map<std::pair<uint32_t, uint32_t>, std::string> member_names;
    std::map<std::pair<uint32_t, uint32_t>, size_t> offsets;
    for (size_t i = 5; i < spirv.size();) {
        const uint32_t count = spirv[i] >> 16;
        const uint32_t op = spirv[i] & 0xFFFFu;
        if (count == 0 || i + count > spirv.size()) break;
        if (op == kOpName) names[spirv[i + 1]] = text(i + 2);
        if (op == kOpMemberName) member_names[{spirv[i + 1], spirv[i + 2]}] = text(i + 3);
        if (op == kOpMemberDecorate && spirv[i + 3] == kDecorationOffset)
            offsets[{spirv[i + 1], spirv[i + 2]}] = spirv[i + 4];
        i += count;
    }
    std::map<std::string, size_t> out;
    for (const auto& [key, offset] : offsets)
        out[names[key.first] + "." + member_names[key]] = offset;
    return out;
}

TEST(SharedLayouts, GlslangPlacesEveryMemberWhereCxxDoes) {
    const std::map<std::string, size_t> glsl =
        member_offsets(compile_glsl(ShaderStage::compute, kSource, "test/shared_layouts.comp"));
    std::map<std::string, int> members_per_type;
    for (const Member& m : kMembers) {
        const std::string key = std::string(m.type) + "." + m.name;
        const auto it = glsl.find(key);
        ASSERT_NE(it, glsl.end()) << key << " has no Offset in the SPIR-V";
        EXPECT_EQ(it->second, m.offset) << key;
        ++members_per_type[m.type];
    }
    // Every member of the structs above is listed (a new one must be added here).
    for (const auto& entry : glsl) {
        const std::string& key = entry.first;  // a named variable: clang 14 captures no bindings
        const std::string type = key.substr(0, key.find('.'));
        if (members_per_type.contains(type)) {
            EXPECT_TRUE(std::any_of(
                std::begin(kMembers), std::end(kMembers),
                [&](const Member& m) { return key == std::string(m.type) + "." + m.name; }))
                << key << " is not checked";
        }
    }
}

// shaders/shared/closure.h is not wired in yet (engine/material keeps its own copies): its GLSL,
// included and as the text a generator emits, must compile and construct as the shaders do.
TEST(SharedLayouts, TheClosureListCompilesAsGlslBothWays) {
    const std::string body =
        "layout(local_size_x = 1) in;\n"
        "layout(std430, binding = 0) buffer B { float out_value; };\n"
        "void main() {\n"
        "    const Closure c = Closure(1u, vec3(0.5), 0.0, vec3(1.0), 1.0, 0.5, 1.5);\n"
        "    out_value = c.roughness + c.ior;\n"
        "}\n";
    EXPECT_NO_THROW(compile_glsl(ShaderStage::compute,
                                 "#version 460\n#extension GL_GOOGLE_include_directive : require\n"
                                 "#include \"shared/closure.h\"\n" +
                                     body,
                                 "test/closure_include.comp"));
    EXPECT_NO_THROW(compile_glsl(ShaderStage::compute,
                                 std::string("#version 460\n") + shared::kClosureGlsl + body,
                                 "test/closure_text.comp"));
}

}  // namespace
}  // namespace mvpl::gpu
