#pragma once
// glTF textures decoded into Scene::textures on first use.
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
    // referring slot in messages.
    int get(int index, ColorSpace space, const std::string& usage);

private:
    Texture decode(int index, ColorSpace space);

    const Document& m_doc;
    std::vector<Texture>& m_textures;
    std::map<std::pair<int, ColorSpace>, int> m_entries;
    uint64_t m_total_texels = 0;
};

}  // namespace mvpl::scene::gltf
