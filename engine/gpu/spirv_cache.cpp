#include "engine/gpu/spirv_cache.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <random>

namespace mvpl::gpu {
namespace {

constexpr char kMagic[8] = {'M', 'V', 'P', 'L', 'S', 'P', 'V', '1'};

uint64_t fnv1a(const void* data, size_t size, uint64_t h = 0xcbf29ce484222325ull) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (size_t i = 0; i < size; ++i) {
        h ^= p[i];
        h *= 0x100000001b3ull;
    }
    return h;
}

struct Header {
    char magic[8];
    uint64_t key;
    uint64_t checksum;  // FNV-1a of the words
    uint64_t words;
};

std::filesystem::path entry_path(const std::filesystem::path& dir, const std::string& key) {
    return dir / (key + ".spv");
}

bool read_entry(const std::filesystem::path& path, uint64_t key, std::vector<uint32_t>& out) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return false;
    Header h{};
    if (!in.read(reinterpret_cast<char*>(&h), sizeof h)) return false;
    if (std::memcmp(h.magic, kMagic, sizeof kMagic) != 0 || h.key != key) return false;
    // A SPIR-V module is far below 256 MiB; a larger count is corruption.
    if (h.words == 0 || h.words > (64u << 20)) return false;
    std::vector<uint32_t> words(h.words);
    if (!in.read(reinterpret_cast<char*>(words.data()), std::streamsize(h.words * 4))) return false;
    if (in.peek() != std::char_traits<char>::eof()) return false;
    if (fnv1a(words.data(), words.size() * 4) != h.checksum) return false;
    if (words[0] != 0x07230203u) return false;  // the SPIR-V magic number
    out = std::move(words);
    return true;
}

void write_entry(const std::filesystem::path& dir, const std::filesystem::path& path, uint64_t key,
                 const std::vector<uint32_t>& words) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) return;
    std::random_device rd;
    const std::filesystem::path tmp =
        path.string() + ".tmp" + std::to_string(rd()) + std::to_string(rd());
    {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        if (!out) return;
        Header h{};
        std::memcpy(h.magic, kMagic, sizeof kMagic);
        h.key = key;
        h.checksum = fnv1a(words.data(), words.size() * 4);
        h.words = words.size();
        out.write(reinterpret_cast<const char*>(&h), sizeof h);
        out.write(reinterpret_cast<const char*>(words.data()), std::streamsize(words.size() * 4));
        if (!out.flush()) {
            out.close();
            std::filesystem::remove(tmp, ec);
            return;
        }
    }
    std::filesystem::rename(tmp, path, ec);
    if (ec) std::filesystem::remove(tmp, ec);
}

uint64_t key_value(ShaderStage stage, std::string_view source) {
    const std::string compiler = glslang_identity();
    uint64_t h = fnv1a(compiler.data(), compiler.size());
    const auto s = uint32_t(stage);
    h = fnv1a(&s, sizeof s, h);
    return fnv1a(source.data(), source.size(), h);
}

}  // namespace

std::filesystem::path default_spirv_cache_directory() {
    if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) {
        return std::filesystem::path(xdg) / "mvpl";
    }
    if (const char* home = std::getenv("HOME"); home && *home) {
        return std::filesystem::path(home) / ".cache" / "mvpl";
    }
    return {};
}

std::string spirv_cache_key(ShaderStage stage, std::string_view source) {
    char buf[17];
    std::snprintf(buf, sizeof buf, "%016llx",
                  static_cast<unsigned long long>(key_value(stage, source)));
    return buf;
}

std::vector<uint32_t> compile_glsl_cached(ShaderStage stage, std::string_view source,
                                          std::string_view name, const SpirvCacheOptions& options,
                                          bool* hit) {
    if (hit) *hit = false;
    const std::filesystem::path dir =
        options.directory.empty() ? default_spirv_cache_directory() : options.directory;
    if (!options.enabled || dir.empty()) return compile_glsl(stage, source, name);
    const uint64_t key = key_value(stage, source);
    const std::filesystem::path path = entry_path(dir, spirv_cache_key(stage, source));
    std::vector<uint32_t> words;
    try {
        if (read_entry(path, key, words)) {
            if (hit) *hit = true;
            return words;
        }
    } catch (const std::exception&) {
        // An unreadable entry is a miss.
    }
    words = compile_glsl(stage, source, name);
    try {
        write_entry(dir, path, key, words);
    } catch (const std::exception&) {
        // A cache that cannot be written costs the next start-up a compile, nothing more.
    }
    return words;
}

}  // namespace mvpl::gpu
