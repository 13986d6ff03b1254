#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <thread>

#include "engine/gpu/embedded_shaders.h"
#include "engine/gpu/gpu_error.h"
#include "engine/gpu/shader_compiler.h"

namespace mvpl::gpu {
namespace {

constexpr uint32_t kSpirvMagic = 0x07230203;

std::string compile_error(std::string_view source, std::string_view name) {
    try {
        compile_glsl(ShaderStage::compute, source, name);
    } catch (const ShaderCompileError& e) {
        return e.what();
    }
    ADD_FAILURE() << name << " compiled, but it should not";
    return "";
}

TEST(ShaderCompiler, CompilesAnEmbeddedComputeShaderToSpirv16) {
    const std::vector<uint32_t> spirv = compile_embedded_shader("test/saxpy.comp");
    ASSERT_GT(spirv.size(), 5u);
    EXPECT_EQ(spirv[0], kSpirvMagic);
    EXPECT_EQ(spirv[1], 0x00010600u) << "SPIR-V version word";
}

TEST(ShaderCompiler, SyntaxErrorNamesTheShaderAndTheLine) {
    const std::string source =
        "#version 460\n"
        "layout(local_size_x = 1) in;\n"
        "void main() {\n"
        "    float x = 1.0\n"  // missing ';' is reported on the next line
        "    x += 2.0;\n"
        "}\n";
    const std::string message = compile_error(source, "test/broken.comp");
    EXPECT_NE(message.find("test/broken.comp:5: error: "), std::string::npos) << message;
    EXPECT_EQ(message.find("ERROR:"), std::string::npos) << "raw glslang log leaked: " << message;
}

TEST(ShaderCompiler, EveryLineNamesTheShaderAndGlslangNoiseIsDropped) {
    // glslang stops at the first error (no cascading), so one line here; the summary
    // ("1 compilation errors. No code generated.") and the cascade marker are not errors.
    const std::string source =
        "#version 460\n"
        "layout(local_size_x = 1) in;\n"
        "layout(std430, binding = 0) buffer B { float v[]; };\n"
        "void main() {\n"
        "    v[0] = undeclared_a;\n"
        "}\n";
    const std::string message = compile_error(source, "one_error.comp");
    EXPECT_EQ(message, "one_error.comp:5: error: 'undeclared_a' : undeclared identifier");
}

TEST(ShaderCompiler, ResolvesIncludesFromTheEmbeddedShaders) {
    const std::string source =
        "#version 460\n"
        "#extension GL_GOOGLE_include_directive : require\n"
        "#include \"constants.glsl\"\n"  // next to the includer: test/constants.glsl
        "layout(local_size_x = 1) in;\n"
        "layout(std430, binding = 0) buffer B { float v[]; };\n"
        "void main() { v[0] = kIncludedValue; }\n";
    EXPECT_FALSE(compile_glsl(ShaderStage::compute, source, "test/uses_include.comp").empty());
    // The same file from the top of shaders/.
    std::string from_root = source;
    from_root.replace(from_root.find("constants.glsl"), 14, "test/constants.glsl");
    EXPECT_FALSE(compile_glsl(ShaderStage::compute, from_root, "other.comp").empty());

    std::string missing = source;
    missing.replace(missing.find("constants.glsl"), 14, "nowhere.glsl");
    const std::string message = compile_error(missing, "test/uses_include.comp");
    EXPECT_NE(message.find("test/uses_include.comp:3: error: "), std::string::npos) << message;
    EXPECT_NE(message.find("nowhere.glsl"), std::string::npos) << message;
}

TEST(ShaderCompiler, LinkErrorsAreReportedToo) {
    // Parses, but a stage without main() does not link.
    const std::string message = compile_error(
        "#version 460\nlayout(local_size_x = 1) in;\nvoid not_main() {}\n", "no_main.comp");
    EXPECT_EQ(message.rfind("no_main.comp: error: ", 0), 0u) << message;
    EXPECT_NE(message.find("Missing entry point"), std::string::npos) << message;
}

TEST(ShaderCompiler, StageFollowsTheExtension) {
    EXPECT_EQ(stage_from_name("a/b.vert"), ShaderStage::vertex);
    EXPECT_EQ(stage_from_name("b.frag"), ShaderStage::fragment);
    EXPECT_EQ(stage_from_name("b.comp"), ShaderStage::compute);
    EXPECT_EQ(stage_from_name("b.geom"), ShaderStage::geometry);
    EXPECT_THROW(stage_from_name("common.glsl"), GpuError);
}

TEST(ShaderCompiler, CompilesOnSeveralThreadsAtOnce) {
    // Start-up compiles the generated G-buffer and shading shaders in parallel.
    const std::vector<uint32_t> expected = compile_embedded_shader("test/saxpy.comp");
    std::vector<std::vector<uint32_t>> results(4);
    std::vector<std::thread> threads;
    for (size_t i = 0; i < results.size(); ++i) {
        threads.emplace_back([&results, i] {
            for (int k = 0; k < 3; ++k)
                results[i] = compile_embedded_shader("test/saxpy.comp");
        });
    }
    for (std::thread& t : threads)
        t.join();
    for (const std::vector<uint32_t>& r : results)
        EXPECT_EQ(r, expected);
}

TEST(EmbeddedShaders, ListsAndFindsTheShadersDirectory) {
    const std::vector<std::string_view> names = embedded_shader_names();
    EXPECT_NE(std::find(names.begin(), names.end(), "test/saxpy.comp"), names.end());
    const std::string_view saxpy = embedded_shader("test/saxpy.comp");
    EXPECT_TRUE(saxpy.starts_with("#version 460"));
    EXPECT_EQ(saxpy.data()[saxpy.size()], '\0');
    EXPECT_FALSE(find_embedded_shader("test/none.comp").has_value());
    try {
        embedded_shader("test/none.comp");
        ADD_FAILURE() << "no exception";
    } catch (const GpuError& e) {
        EXPECT_NE(std::string(e.what()).find("test/none.comp"), std::string::npos);
    }
}

}  // namespace
}  // namespace mvpl::gpu
