#include "engine/gpu/shader_compiler.h"

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>
#include <glslang/build_info.h>

#include <memory>
#include <regex>
#include <sstream>
#include <string>

#include "engine/gpu/embedded_shaders.h"
#include "engine/gpu/gpu_error.h"

namespace mvpl::gpu {
namespace {

// glslang needs one InitializeProcess before any compile and FinalizeProcess at the very end; a
// function-local static gives both, once, race-free.
void ensure_glslang_initialized() {
    struct Process {
        Process() { glslang::InitializeProcess(); }
        ~Process() { glslang::FinalizeProcess(); }
    };
    static const Process process;
}

EShLanguage to_glslang(ShaderStage stage) {
    switch (stage) {
        case ShaderStage::vertex:
            return EShLangVertex;
        case ShaderStage::fragment:
            return EShLangFragment;
        case ShaderStage::geometry:
            return EShLangGeometry;
        case ShaderStage::compute:
        default:
            return EShLangCompute;
    }
}

// `#include` from the embedded shaders: "x.glsl" next to the includer, then from shaders/.
class EmbeddedIncluder : public glslang::TShader::Includer {
public:
    IncludeResult* includeLocal(const char* header, const char* includer, size_t) override {
        const std::string from(includer ? includer : "");
        const size_t slash = from.rfind('/');
        if (slash == std::string::npos) return includeSystem(header, includer, 0);
        return lookup(from.substr(0, slash + 1) + header);
    }
    IncludeResult* includeSystem(const char* header, const char*, size_t) override {
        return lookup(header);
    }
    void releaseInclude(IncludeResult* result) override { delete result; }

private:
    static IncludeResult* lookup(const std::string& name) {
        const std::optional<std::string_view> source = find_embedded_shader(name);
        if (!source) return nullptr;
        return new IncludeResult(name, source->data(), source->size(), nullptr);
    }
};

// glslang's log ("ERROR: name:12: 'x' : undeclared identifier", summary lines, warnings) → one
// "name:12: error: 'x' : undeclared identifier" line per error.
std::string format_errors(const std::string& log, std::string_view name) {
    static const std::regex located(R"(^(.*?):(\d+): (.*)$)");
    std::istringstream in(log);
    std::string out;
    std::string line;
    while (std::getline(in, line)) {
        while (!line.empty() && (line.back() == '\r' || line.back() == ' '))
            line.pop_back();
        if (!line.starts_with("ERROR: ")) continue;
        line.erase(0, 7);
        // "N compilation errors.  No code generated." and the cascade marker say nothing new.
        if (line.find("compilation errors") != std::string::npos ||
            line.find("compilation terminated") != std::string::npos) {
            continue;
        }
        std::smatch m;
        std::string entry;
        if (std::regex_match(line, m, located)) {
            // String number 0 is the unnamed main source.
            const std::string where = m[1] == "0" ? std::string(name) : m[1].str();
            entry = where + ":" + m[2].str() + ": error: " + m[3].str();
        } else {
            entry = std::string(name) + ": error: " + line;
        }
        out += (out.empty() ? "" : "\n") + entry;
    }
    if (out.empty()) out = std::string(name) + ": error: glslang failed without a message";
    return out;
}

}  // namespace

std::vector<uint32_t> compile_glsl(ShaderStage stage, std::string_view source,
                                   std::string_view name) {
    ensure_glslang_initialized();
    const EShLanguage language = to_glslang(stage);
    const std::string name_string(name);
    const char* sources[] = {source.data()};
    const int lengths[] = {int(source.size())};
    const char* names[] = {name_string.c_str()};

    glslang::TShader shader(language);
    shader.setStringsWithLengthsAndNames(sources, lengths, names, 1);
    shader.setEnvInput(glslang::EShSourceGlsl, language, glslang::EShClientVulkan, 100);
    // Vulkan 1.3 implementations must accept SPIR-V 1.6; lavapipe 22.3 does.
    shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_3);
    shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_6);
    const auto messages = EShMessages(EShMsgSpvRules | EShMsgVulkanRules);
    EmbeddedIncluder includer;
    // 460 core only if the source forgets its #version line.
    if (!shader.parse(GetDefaultResources(), 460, ECoreProfile, false, false, messages, includer)) {
        throw ShaderCompileError(format_errors(shader.getInfoLog(), name));
    }
    glslang::TProgram program;
    program.addShader(&shader);
    if (!program.link(messages)) {
        throw ShaderCompileError(format_errors(program.getInfoLog(), name));
    }

    std::vector<uint32_t> spirv;
    spv::SpvBuildLogger logger;
    glslang::SpvOptions options;
    options.generateDebugInfo = false;
    options.disableOptimizer = true;  // the drivers optimise; glslang's pass adds start-up time
    glslang::GlslangToSpv(*program.getIntermediate(language), spirv, &logger, &options);
    const std::string spv_messages = logger.getAllMessages();
    if (spirv.empty() || spv_messages.find("error") != std::string::npos) {
        throw ShaderCompileError(name_string +
                                 ": error: SPIR-V generation failed: " + spv_messages);
    }
    return spirv;
}

ShaderStage stage_from_name(std::string_view name) {
    if (name.ends_with(".vert")) return ShaderStage::vertex;
    if (name.ends_with(".frag")) return ShaderStage::fragment;
    if (name.ends_with(".comp")) return ShaderStage::compute;
    if (name.ends_with(".geom")) return ShaderStage::geometry;
    throw GpuError("shader '" + std::string(name) +
                   "': no stage for its extension (use .vert, .frag, .comp or .geom)");
}

std::string glslang_identity() {
    return "glslang " + std::to_string(GLSLANG_VERSION_MAJOR) + "." +
           std::to_string(GLSLANG_VERSION_MINOR) + "." + std::to_string(GLSLANG_VERSION_PATCH) +
           GLSLANG_VERSION_FLAVOR + " vulkan1.3 spv1.6 no-optimizer no-debug-info";
}

std::vector<uint32_t> compile_embedded_shader(std::string_view name) {
    return compile_glsl(stage_from_name(name), embedded_shader(name), name);
}

}  // namespace mvpl::gpu
