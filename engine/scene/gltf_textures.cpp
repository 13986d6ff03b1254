#include "engine/scene/gltf_textures.h"

#include <stb_image.h>

#include <array>
#include <climits>
#include <cstring>
#include <exception>
#include <memory>

#include "engine/core/image.h"
#include "engine/core/parallel.h"
#include "engine/scene/gltf_diagnose.h"

namespace mvpl::scene::gltf {
namespace {

// 8192² texels per image and eight such in all: Texture stores 16 bytes a texel, so this bounds
// what an image header claiming enormous dimensions can make us allocate.
constexpr uint64_t kMaxTexels = uint64_t(1) << 26;
constexpr uint64_t kMaxTotalTexels = uint64_t(1) << 29;

constexpr int kWrapRepeat = 10497;
constexpr int kWrapClampToEdge = 33071;
constexpr int kWrapMirroredRepeat = 33648;
constexpr int kFilterNearest = 9728;
constexpr int kFilterLinear = 9729;

struct StbiFree {
    void operator()(void* p) const { stbi_image_free(p); }
};

// stb_image quotes raw chunk tags from the file in some reasons.
std::string stbi_reason() {
    const char* reason = stbi_failure_reason();
    std::string text = reason ? reason : "unknown reason";
    for (char& c : text) {
        if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) > 0x7E) c = '?';
    }
    return text;
}

bool starts_with(const unsigned char* bytes, int length, const char* magic, int at = 0) {
    const int n = int(std::strlen(magic));
    return length >= at + n && std::memcmp(bytes + at, magic, size_t(n)) == 0;
}

// Why stb_image could not read `bytes`. Its own reason is specific once it has chosen a format,
// but stbi_info tries each format in turn and ends with "unknown image type" whichever one the
// data was meant to be: that is made specific from the format the first bytes announce.
std::string decode_problem(const unsigned char* bytes, int length) {
    const std::string reason = stbi_reason();
    if (reason != "unknown image type") return reason;
    const std::string stb = " (stb_image: " + reason + ")";
    if (starts_with(bytes, length, "\x89PNG\r\n\x1a\n")) return "corrupt or truncated PNG" + stb;
    if (starts_with(bytes, length, "\xff\xd8\xff")) return "corrupt or truncated JPEG" + stb;
    if (starts_with(bytes, length, "GIF8")) return "corrupt or truncated GIF" + stb;
    if (starts_with(bytes, length, "BM")) return "corrupt or truncated BMP" + stb;
    if (starts_with(bytes, length, "RIFF") && starts_with(bytes, length, "WEBP", 8)) {
        return "WebP (EXT_texture_webp), which is not supported";
    }
    if (starts_with(bytes, length, "\xabKTX 20\xbb")) {
        return "KTX2 (KHR_texture_basisu), which is not supported";
    }
    if (starts_with(bytes, length, "DDS ")) return "DDS (MSFT_texture_dds), which is not supported";
    std::string head;
    for (int i = 0; i < std::min(length, 4); ++i) {
        static const char kHex[] = "0123456789abcdef";
        head += std::string(i ? " " : "") + kHex[bytes[i] >> 4] + kHex[bytes[i] & 15];
    }
    return "neither PNG, JPEG, BMP, GIF, TGA, PSD, HDR, PIC nor PNM (the data starts with " + head +
           ")";
}

// Value of every possible 8- or 16-bit code, decoded to linear when the texture is a colour.
std::vector<float> code_table(int bits, ColorSpace space) {
    const size_t codes = size_t(1) << bits;
    const float max_code = float(codes - 1);
    std::vector<float> table(codes);
    for (size_t i = 0; i < codes; ++i) {
        const float v = float(i) / max_code;
        table[i] = space == ColorSpace::Srgb ? srgb_to_linear(v) : v;
    }
    return table;
}

// The wrap modes and filter of glTF sampler `index` (checked to exist) on `texture`.
void apply_sampler(const Document& doc, const std::string& texture_name, int index,
                   Texture& texture) {
    const tinygltf::Model& model = doc.model;
    if (index < 0 || size_t(index) >= model.samplers.size()) {
        doc.fail(texture_name + " refers to sampler " + std::to_string(index) +
                 ", but the file has " + std::to_string(model.samplers.size()) + " samplers");
    }
    const tinygltf::Sampler& sampler = model.samplers[size_t(index)];
    const std::string sampler_name = "sampler " + std::to_string(index);
    auto wrap = [&](int mode, const char* axis) {
        switch (mode) {
            case kWrapRepeat:
                return Wrap::Repeat;
            case kWrapClampToEdge:
                return Wrap::ClampToEdge;
            case kWrapMirroredRepeat:
                return Wrap::MirroredRepeat;
            default:
                doc.fail(sampler_name + " has an invalid " + axis + " " + std::to_string(mode));
        }
    };
    texture.wrap_s = wrap(sampler.wrapS, "wrapS");
    texture.wrap_t = wrap(sampler.wrapT, "wrapT");
    if (sampler.magFilter == kFilterNearest) {
        texture.filter = Filter::Nearest;
    } else if (sampler.magFilter != kFilterLinear && sampler.magFilter != -1) {
        doc.fail(sampler_name + " has an invalid magFilter " + std::to_string(sampler.magFilter));
    }
}

// The image `source` of a texture, checked to exist and to hold data (under 2 GiB).
const tinygltf::Image& source_image(const Document& doc, const std::string& texture_name,
                                    int source) {
    const tinygltf::Model& model = doc.model;
    if (source == -1) doc.fail(texture_name + " has no image source");
    if (source < 0 || size_t(source) >= model.images.size()) {
        doc.fail(texture_name + " refers to image " + std::to_string(source) +
                 ", but the file has " + std::to_string(model.images.size()) + " images");
    }
    const tinygltf::Image& image = model.images[size_t(source)];
    const std::string image_name = "image " + std::to_string(source);
    if (image.image.empty()) {
        // tinygltf keeps going (with a warning) when an external image cannot be read.
        if (!image.uri.empty()) {
            const std::string problem = external_file_problem(doc.base_dir, image.uri);
            doc.fail(image_name + " file '" + image.uri + "' " +
                     (problem.empty() ? "cannot be read" : problem));
        }
        doc.fail(image_name + " has no data");
    }
    if (image.image.size() > size_t(INT_MAX)) doc.fail(image_name + " is larger than 2 GiB");
    return image;
}

// An image's codes as stb_image decoded them: 8 or 16 bits, 1 to 4 channels.
struct Pixels {
    std::unique_ptr<void, StbiFree> data;
    int channels = 0;
    bool sixteen_bits = false;

    size_t code(size_t i) const {
        return sixteen_bits ? static_cast<const uint16_t*>(data.get())[i]
                            : static_cast<const uint8_t*>(data.get())[i];
    }
};

// The pixels of `bytes`, whose header stbi_info read as width × height.
Pixels decode_pixels(const Document& doc, const std::string& image_name, const unsigned char* bytes,
                     int length, int width, int height) {
    Pixels pixels;
    pixels.sixteen_bits = stbi_is_16_bit_from_memory(bytes, length) != 0;
    int decoded_width = 0;
    int decoded_height = 0;
    int& channels = pixels.channels;
    pixels.data.reset(pixels.sixteen_bits
                          ? static_cast<void*>(stbi_load_16_from_memory(
                                bytes, length, &decoded_width, &decoded_height, &channels, 0))
                          : static_cast<void*>(stbi_load_from_memory(
                                bytes, length, &decoded_width, &decoded_height, &channels, 0)));
    if (!pixels.data) doc.fail(image_name + " cannot be decoded: " + decode_problem(bytes, length));
    if (decoded_width != width || decoded_height != height || channels < 1 || channels > 4) {
        doc.fail(image_name + " decodes inconsistently with its header");
    }
    return pixels;
}

// texture.texels (width × height of them) from the pixels' codes, colour decoded from `space`.
void fill_texels(const Pixels& pixels, ColorSpace space, Texture& texture) {
    const int bits = pixels.sixteen_bits ? 16 : 8;
    const int channels = pixels.channels;
    const std::vector<float> colour = code_table(bits, space);
    const std::vector<float> linear =
        space == ColorSpace::Linear ? colour : code_table(bits, ColorSpace::Linear);
    texture.texels.resize(size_t(texture.width) * size_t(texture.height));
    for (size_t t = 0; t < texture.texels.size(); ++t) {
        const size_t base = t * size_t(channels);
        Vec4& out = texture.texels[t];
        // Grey fills R, G and B; a missing alpha is opaque. Alpha is never sRGB-encoded.
        if (channels <= 2) {
            out = Vec4(Vec3(colour[pixels.code(base)]),
                       channels == 2 ? linear[pixels.code(base + 1)] : 1.0f);
        } else {
            out = Vec4(colour[pixels.code(base)], colour[pixels.code(base + 1)],
                       colour[pixels.code(base + 2)],
                       channels == 4 ? linear[pixels.code(base + 3)] : 1.0f);
        }
    }
}

}  // namespace

int TextureCache::get(int index, ColorSpace space, const std::string& usage) {
    const size_t count = m_doc.model.textures.size();
    if (index < 0 || size_t(index) >= count) {
        m_doc.fail(usage + " refers to texture " + std::to_string(index) + ", but the file has " +
                   std::to_string(count) + " textures");
    }
    const auto key = std::make_pair(index, space);
    const auto it = m_entries.find(key);
    if (it != m_entries.end()) return it->second;
    m_textures.push_back(describe(index));
    const int entry = int(m_textures.size()) - 1;
    m_entries.emplace(key, entry);
    m_pending.push_back({entry, index, space});
    return entry;
}

Texture TextureCache::describe(int index) {
    const tinygltf::Texture& gltf_texture = m_doc.model.textures[size_t(index)];
    const std::string texture_name = "texture " + std::to_string(index);
    Texture texture;
    if (gltf_texture.sampler != -1)
        apply_sampler(m_doc, texture_name, gltf_texture.sampler, texture);
    const tinygltf::Image& image = source_image(m_doc, texture_name, gltf_texture.source);
    const std::string image_name = "image " + std::to_string(gltf_texture.source);
    const unsigned char* bytes = image.image.data();
    const int length = int(image.image.size());

    int width = 0;
    int height = 0;
    int channels = 0;
    if (!stbi_info_from_memory(bytes, length, &width, &height, &channels)) {
        m_doc.fail(image_name + " cannot be decoded: " + decode_problem(bytes, length));
    }
    const uint64_t texels = uint64_t(std::max(width, 0)) * uint64_t(std::max(height, 0));
    if (width <= 0 || height <= 0 || texels > kMaxTexels) {
        m_doc.fail(image_name + " is " + std::to_string(width) + "x" + std::to_string(height) +
                   " texels; at most " + std::to_string(kMaxTexels) + " are allowed");
    }
    if (m_total_texels + texels > kMaxTotalTexels) {
        m_doc.fail("the textures exceed " + std::to_string(kMaxTotalTexels) + " texels in all");
    }
    m_total_texels += texels;

    texture.name = !image.name.empty()                                      ? image.name
                   : !image.uri.empty() && image.uri.rfind("data:", 0) != 0 ? image.uri
                                                                            : texture_name;
    texture.width = width;
    texture.height = height;
    return texture;
}

void TextureCache::decode(const Pending& pending) {
    const int source = m_doc.model.textures[size_t(pending.index)].source;
    const tinygltf::Image& image = m_doc.model.images[size_t(source)];
    Texture& texture = m_textures[size_t(pending.entry)];
    const Pixels pixels =
        decode_pixels(m_doc, "image " + std::to_string(source), image.image.data(),
                      int(image.image.size()), texture.width, texture.height);
    fill_texels(pixels, pending.space, texture);
}

void TextureCache::decode_pending() {
    std::vector<std::exception_ptr> errors(m_pending.size());
    parallel_for(int64_t(m_pending.size()), 1, [&](int64_t begin, int64_t end) {
        for (int64_t i = begin; i < end; ++i) {
            try {
                decode(m_pending[size_t(i)]);
            } catch (...) {
                errors[size_t(i)] = std::current_exception();
            }
        }
    });
    m_pending.clear();
    for (const std::exception_ptr& error : errors)
        if (error) std::rethrow_exception(error);
}

}  // namespace mvpl::scene::gltf
