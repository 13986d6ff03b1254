#pragma once
// glTF textures decoded into Scene::textures: described on first use, their texels decoded
// together, in parallel, by decode_pending().
#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "engine/scene/gltf_document.h"
#include "engine/scene/texture.h"

namespace mvpl::scene::gltf {

enum class ColorSpace { Srgb, Linear };

// One Scene texture per (glTF texture, colour space): the same image can be a colour in one
// material slot and data in another, and the texels store the decoded values.
class TextureCache {
public:
    TextureCache(const Document& doc, std::vector<Texture>& textures)
        : m_doc(doc), m_textures(textures) {}

    // Index into Scene::textures of glTF texture `index` decoded in `space`; `usage` names the
    // referring slot in messages. The texture's sampler, size and name are set and checked here;
    // its texels are left to decode_pending().
    int get(int index, ColorSpace space, const std::string& usage);

    // Decodes the texels of every texture get() has described since, in parallel (a PNG's
    // inflate is serial, so images are the unit of work); fails with the first texture's
    // problem, in the order get() saw them, whichever thread met it first.
    void decode_pending();

private:
    struct Pending {
        int entry;  // index into m_textures
        int index;  // glTF texture
        ColorSpace space;
    };

    Texture describe(int index);
    void decode(const Pending& pending);

    const Document& m_doc;
    std::vector<Texture>& m_textures;
    std::map<std::pair<int, ColorSpace>, int> m_entries;
    std::vector<Pending> m_pending;
    uint64_t m_total_texels = 0;
};

}  // namespace mvpl::scene::gltf
