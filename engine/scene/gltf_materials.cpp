#include "engine/scene/gltf_materials.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "engine/scene/gltf_value.h"
#include "engine/scene/scene_range.h"

namespace mvpl::scene::gltf {
namespace {

class MaterialReader {
public:
    MaterialReader(const Document& doc, TextureCache& textures, int index)
        : m_doc(doc),
          m_textures(textures),
          m_material(doc.model.materials[size_t(index)]),
          m_name(indexed("materials", size_t(index))) {}

    Material read() const;

private:
    // Reflectance-like factors above 1 would let a surface reflect more than it receives; the
    // spec bounds them at 1, so they are clamped. Negative values and values beyond kMaxFactor
    // (scene_range.h: a float shader could not carry them) are errors.
    float fraction(double value, const std::string& where) const {
        return float(std::min(check_non_negative(m_doc, value, kMaxFactor, where), 1.0));
    }
    float factor(double value, const std::string& where) const {
        return float(check_non_negative(m_doc, value, kMaxFactor, where));
    }
    Rgb colour(const std::vector<double>& values, const std::string& where, bool clamp) const {
        if (values.size() < 3) m_doc.fail(where + " has fewer than 3 components");
        Rgb c;
        for (int i = 0; i < 3; ++i) {
            const std::string element = indexed(where, size_t(i));
            c[i] =
                clamp ? fraction(values[size_t(i)], element) : factor(values[size_t(i)], element);
        }
        return c;
    }

    TextureRef texture(int index, int tex_coord, const tinygltf::Value* transform, ColorSpace space,
                       const std::string& slot) const;
    TextureRef texture(const tinygltf::TextureInfo& info, ColorSpace space,
                       const std::string& slot) const {
        if (info.index == -1) return {};
        const tinygltf::Value* transform =
            find_extension(m_doc, info.extensions, "KHR_texture_transform", m_name + "." + slot);
        return texture(info.index, info.texCoord, transform, space, slot);
    }
    TextureRef texture(const tinygltf::Value* info, ColorSpace space,
                       const std::string& slot) const;

    void read_extensions(Material& out) const;
    void read_spec_gloss(const tinygltf::Value& ext, Material& out) const;
    void read_alpha(Material& out) const;

    const Document& m_doc;
    TextureCache& m_textures;
    const tinygltf::Material& m_material;
    std::string m_name;
};

TextureRef MaterialReader::texture(int index, int tex_coord, const tinygltf::Value* transform,
                                   ColorSpace space, const std::string& slot) const {
    const std::string usage = m_name + "." + slot;
    TextureRef ref;
    ref.texture = m_textures.get(index, space, usage);
    ref.texcoord = tex_coord;
    if (transform) {
        const std::string what = usage + ".extensions.KHR_texture_transform";
        const std::vector<double> offset =
            read_numbers(m_doc, find_member(*transform, "offset"), 2, {0.0, 0.0}, what + ".offset");
        const std::vector<double> scale =
            read_numbers(m_doc, find_member(*transform, "scale"), 2, {1.0, 1.0}, what + ".scale");
        for (size_t i = 0; i < 2; ++i) {
            check_magnitude(m_doc, offset[i], kMaxFactor, indexed(what + ".offset", i));
            check_magnitude(m_doc, scale[i], kMaxFactor, indexed(what + ".scale", i));
        }
        ref.offset = Vec2(float(offset[0]), float(offset[1]));
        ref.scale = Vec2(float(scale[0]), float(scale[1]));
        // A turn is a turn: reduced in double, so that float sin and cos (whose GPU precision is
        // specified only near [-π, π]) see a small angle whatever the file says.
        ref.rotation = float(std::remainder(
            read_number(m_doc, find_member(*transform, "rotation"), 0.0, what + ".rotation"),
            2.0 * std::numbers::pi));
        ref.texcoord =
            read_int(m_doc, find_member(*transform, "texCoord"), ref.texcoord, what + ".texCoord");
    }
    // Meshes carry TEXCOORD_0 and TEXCOORD_1 only.
    if (ref.texcoord < 0 || ref.texcoord > 1) {
        m_doc.fail(usage + " uses TEXCOORD_" + std::to_string(ref.texcoord) +
                   "; only TEXCOORD_0 and TEXCOORD_1 are supported");
    }
    return ref;
}

TextureRef MaterialReader::texture(const tinygltf::Value* info, ColorSpace space,
                                   const std::string& slot) const {
    if (info == nullptr) return {};
    const std::string usage = m_name + "." + slot;
    if (!info->IsObject()) m_doc.fail(usage + " is not a JSON object");
    const tinygltf::Value* index = find_member(*info, "index");
    if (index == nullptr) m_doc.fail(usage + " has no texture index");
    const tinygltf::Value* transform = nullptr;
    if (const tinygltf::Value* extensions = find_member(*info, "extensions")) {
        if (!extensions->IsObject()) m_doc.fail(usage + ".extensions is not a JSON object");
        transform = find_member(*extensions, "KHR_texture_transform");
        if (transform && !transform->IsObject()) {
            m_doc.fail(usage + ".extensions.KHR_texture_transform is not a JSON object");
        }
    }
    return texture(read_int(m_doc, index, -1, usage + ".index"),
                   read_int(m_doc, find_member(*info, "texCoord"), 0, usage + ".texCoord"),
                   transform, space, slot);
}

Material MaterialReader::read() const {
    const tinygltf::PbrMetallicRoughness& pbr = m_material.pbrMetallicRoughness;
    Material out;
    out.name = m_material.name.empty() ? m_name : m_material.name;
    const std::string pbr_name = "pbrMetallicRoughness.";
    out.base_color = colour(pbr.baseColorFactor, m_name + "." + pbr_name + "baseColorFactor", true);
    if (pbr.baseColorFactor.size() >= 4) {
        out.base_alpha = fraction(pbr.baseColorFactor[3],
                                  indexed(m_name + "." + pbr_name + "baseColorFactor", 3));
    }
    read_alpha(out);
    out.base_color_texture =
        texture(pbr.baseColorTexture, ColorSpace::Srgb, pbr_name + "baseColorTexture");
    out.metallic = fraction(pbr.metallicFactor, m_name + "." + pbr_name + "metallicFactor");
    out.roughness = fraction(pbr.roughnessFactor, m_name + "." + pbr_name + "roughnessFactor");
    out.metallic_roughness_texture = texture(pbr.metallicRoughnessTexture, ColorSpace::Linear,
                                             pbr_name + "metallicRoughnessTexture");

    const tinygltf::NormalTextureInfo& normal = m_material.normalTexture;
    if (normal.index != -1) {
        const tinygltf::Value* transform = find_extension(
            m_doc, normal.extensions, "KHR_texture_transform", m_name + ".normalTexture");
        out.normal_texture =
            texture(normal.index, normal.texCoord, transform, ColorSpace::Linear, "normalTexture");
        out.normal_scale = float(
            check_magnitude(m_doc, normal.scale, kMaxFactor, m_name + ".normalTexture.scale"));
    }

    out.emissive = colour(m_material.emissiveFactor, m_name + ".emissiveFactor", false);
    out.emissive_texture = texture(m_material.emissiveTexture, ColorSpace::Srgb, "emissiveTexture");
    out.double_sided = m_material.doubleSided;
    read_extensions(out);
    // The shaders multiply the two in float.
    check_non_negative(m_doc, double(max_component(out.emissive)) * out.emissive_strength,
                       kMaxFactor, m_name + " emissiveFactor x emissiveStrength");
    return out;
}

void MaterialReader::read_alpha(Material& out) const {
    const std::string& mode = m_material.alphaMode;
    if (mode == "MASK") {
        out.alpha_mode = AlphaMode::Mask;
    } else if (mode == "BLEND") {
        out.alpha_mode = AlphaMode::Blend;
    } else if (mode != "OPAQUE") {
        m_doc.fail(m_name + ".alphaMode is '" + mode + "', not OPAQUE, MASK or BLEND");
    }
    out.alpha_cutoff = float(
        check_non_negative(m_doc, m_material.alphaCutoff, kMaxFactor, m_name + ".alphaCutoff"));
}

void MaterialReader::read_extensions(Material& out) const {
    const tinygltf::ExtensionMap& extensions = m_material.extensions;
    const std::string prefix = m_name + ".extensions.";
    if (const tinygltf::Value* ext =
            find_extension(m_doc, extensions, "KHR_materials_emissive_strength", m_name)) {
        const std::string where = prefix + "KHR_materials_emissive_strength.emissiveStrength";
        out.emissive_strength =
            factor(read_number(m_doc, find_member(*ext, "emissiveStrength"), 1.0, where), where);
    }
    if (const tinygltf::Value* ext =
            find_extension(m_doc, extensions, "KHR_materials_specular", m_name)) {
        const std::string name = "KHR_materials_specular.";
        const std::string where = prefix + name + "specularFactor";
        out.specular =
            fraction(read_number(m_doc, find_member(*ext, "specularFactor"), 1.0, where), where);
        out.specular_texture = texture(find_member(*ext, "specularTexture"), ColorSpace::Linear,
                                       "extensions." + name + "specularTexture");
        // specularColorFactor may exceed 1 (the spec allows it to tint above white).
        const std::string colour_where = prefix + name + "specularColorFactor";
        out.specular_color = colour(read_numbers(m_doc, find_member(*ext, "specularColorFactor"), 3,
                                                 {1.0, 1.0, 1.0}, colour_where),
                                    colour_where, false);
        out.specular_color_texture =
            texture(find_member(*ext, "specularColorTexture"), ColorSpace::Srgb,
                    "extensions." + name + "specularColorTexture");
    }
    if (const tinygltf::Value* ext =
            find_extension(m_doc, extensions, "KHR_materials_ior", m_name)) {
        const std::string where = prefix + "KHR_materials_ior.ior";
        const double ior = read_number(m_doc, find_member(*ext, "ior"), 1.5, where);
        // 0 is allowed by the extension's schema (a limit case with total Fresnel reflection).
        if (!(ior >= 1.0 || ior == 0.0)) m_doc.fail(where + " " + number_text(ior) + " is below 1");
        out.ior = float(check_non_negative(m_doc, ior, kMaxFactor, where));
    }
    if (const tinygltf::Value* ext =
            find_extension(m_doc, extensions, "KHR_materials_transmission", m_name)) {
        const std::string name = "KHR_materials_transmission.";
        const std::string where = prefix + name + "transmissionFactor";
        out.transmission = fraction(
            read_number(m_doc, find_member(*ext, "transmissionFactor"), 0.0, where), where);
        out.transmission_texture =
            texture(find_member(*ext, "transmissionTexture"), ColorSpace::Linear,
                    "extensions." + name + "transmissionTexture");
    }
    if (const tinygltf::Value* ext =
            find_extension(m_doc, extensions, "KHR_materials_pbrSpecularGlossiness", m_name)) {
        read_spec_gloss(*ext, out);
    }
    // No properties: the base colour is what the surface shows (an unlit material that also
    // names another shading model is undefined by the spec; unlit wins here).
    if (find_extension(m_doc, extensions, "KHR_materials_unlit", m_name)) {
        out.shading = ShadingModel::Unlit;
    }
    if (const tinygltf::Value* ext =
            find_extension(m_doc, extensions, "KHR_materials_volume", m_name)) {
        // Only the thickness factor matters here (thin-walled or solid); attenuation is not
        // modelled (clear glass) and the thickness texture only scales a non-zero factor.
        const std::string where = prefix + "KHR_materials_volume.thicknessFactor";
        out.thickness = float(check_non_negative(
            m_doc, read_number(m_doc, find_member(*ext, "thicknessFactor"), 0.0, where), kMaxFactor,
            where));
    }
}

// KHR_materials_pbrSpecularGlossiness: diffuse replaces the base colour (the same meaning: sRGB
// RGB, linear A as coverage); specular and glossiness share one texture (sRGB RGB, linear A).
void MaterialReader::read_spec_gloss(const tinygltf::Value& ext, Material& out) const {
    const std::string name = "KHR_materials_pbrSpecularGlossiness.";
    const std::string where = m_name + ".extensions." + name;
    out.shading = ShadingModel::SpecGloss;
    const std::vector<double> diffuse = read_numbers(m_doc, find_member(ext, "diffuseFactor"), 4,
                                                     {1.0, 1.0, 1.0, 1.0}, where + "diffuseFactor");
    out.base_color = colour(diffuse, where + "diffuseFactor", true);
    out.base_alpha = fraction(diffuse[3], indexed(where + "diffuseFactor", 3));
    out.base_color_texture = texture(find_member(ext, "diffuseTexture"), ColorSpace::Srgb,
                                     "extensions." + name + "diffuseTexture");
    out.spec_gloss_specular = colour(read_numbers(m_doc, find_member(ext, "specularFactor"), 3,
                                                  {1.0, 1.0, 1.0}, where + "specularFactor"),
                                     where + "specularFactor", true);
    out.glossiness = fraction(
        read_number(m_doc, find_member(ext, "glossinessFactor"), 1.0, where + "glossinessFactor"),
        where + "glossinessFactor");
    out.specular_glossiness_texture =
        texture(find_member(ext, "specularGlossinessTexture"), ColorSpace::Srgb,
                "extensions." + name + "specularGlossinessTexture");
}

}  // namespace

MaterialTable::MaterialTable(const Document& doc, Scene& scene, TextureCache& textures)
    : m_doc(doc), m_scene(scene) {
    const size_t count = doc.model.materials.size();
    m_scene.materials.reserve(count + 1);
    for (size_t i = 0; i < count; ++i) {
        m_scene.materials.push_back(MaterialReader(doc, textures, int(i)).read());
    }
}

int MaterialTable::material_for(int gltf_index, const std::string& usage) {
    if (gltf_index == -1) {
        if (m_default < 0) {
            Material fallback;  // glTF's default material: white, fully metallic, fully rough
            fallback.name = "default";
            m_scene.materials.push_back(fallback);
            m_default = int(m_scene.materials.size()) - 1;
        }
        return m_default;
    }
    const size_t count = m_doc.model.materials.size();
    if (gltf_index < 0 || size_t(gltf_index) >= count) {
        m_doc.fail(usage + " refers to material " + std::to_string(gltf_index) +
                   ", but the file has " + std::to_string(count) + " materials");
    }
    return gltf_index;
}

}  // namespace mvpl::scene::gltf
