#pragma once
// The scene model every subsystem reads: world-space triangle meshes, glTF metallic-roughness
// materials, punctual lights and one camera. Emissive triangles are the area lights; they are
// found from the materials (Material::emission), not listed separately.
#include <cstdint>
#include <string>
#include <vector>

#include "engine/core/color.h"
#include "engine/core/math.h"
#include "engine/scene/bounds.h"
#include "engine/scene/environment.h"
#include "engine/scene/texture.h"

namespace mvpl::scene {

// glTF alphaMode: Mask cuts geometry whose base alpha is below alpha_cutoff for every ray and
// pass; Blend is stochastic (hashed) transparency where the renderers support it.
enum class AlphaMode { Opaque, Mask, Blend };

// Which glTF shading model a material uses: the core metallic-roughness, the specular-glossiness
// of KHR_materials_pbrSpecularGlossiness (its diffuse in base_color, base_alpha and
// base_color_texture, which mean the same there), or KHR_materials_unlit (the base colour is the
// radiance the surface shows; material/node_graph.h says what light transport does with it).
enum class ShadingModel { MetalRough, SpecGloss, Unlit };

// glTF 2.0 material.alphaCutoff's default.
inline constexpr float kDefaultAlphaCutoff = 0.5f;

struct Material {
    std::string name;
    // glTF pbrMetallicRoughness; the texture channels are multiplied into the factors.
    Rgb base_color{1.0f};
    float base_alpha = 1.0f;  // baseColorFactor[3]; times the texture's A and COLOR_0's A
    TextureRef base_color_texture;
    float metallic = 1.0f;
    float roughness = 1.0f;
    TextureRef metallic_roughness_texture;  // G = roughness, B = metallic
    TextureRef normal_texture;
    float normal_scale = 1.0f;
    // A height map (Mitsuba's bumpmap; glTF has none): its R channel, bump_scale height units per
    // uv unit, bends the shading normal where there is no normal texture.
    TextureRef bump_texture;
    float bump_scale = 1.0f;
    // An opacity map (Mitsuba's mask; glTF has none): where set, the alpha is base_alpha times its
    // A channel, and the base colour texture's A is not read (Mitsuba's reflectance has none).
    TextureRef opacity_texture;
    // Emitted radiance = emissive · emissive_strength (KHR_materials_emissive_strength) · texture.
    Rgb emissive{0.0f};
    float emissive_strength = 1.0f;
    TextureRef emissive_texture;
    // KHR_materials_specular: specular = 0 removes the dielectric layer (pure Lambertian).
    float specular = 1.0f;
    TextureRef specular_texture;  // A channel
    Rgb specular_color{1.0f};
    TextureRef specular_color_texture;  // RGB, sRGB-decoded
    // KHR_materials_ior.
    float ior = 1.5f;
    // KHR_materials_transmission (factor · texture R): the share t of the dielectric base that is
    // the specular BTDF (tinted by the base colour) instead of the diffuse lobe.
    float transmission = 0.0f;
    TextureRef transmission_texture;
    // KHR_materials_volume thicknessFactor: 0 is thin-walled (the transmitted ray keeps its
    // direction), > 0 a solid that refracts at each interface (its value is not used further).
    float thickness = 0.0f;
    bool double_sided = false;
    AlphaMode alpha_mode = AlphaMode::Opaque;
    float alpha_cutoff = kDefaultAlphaCutoff;  // Mask only
    ShadingModel shading = ShadingModel::MetalRough;
    // KHR_materials_pbrSpecularGlossiness: F0 colour (specularFactor times the texture's sRGB RGB)
    // and glossiness (glossinessFactor times the texture's linear A).
    Rgb spec_gloss_specular{1.0f};
    float glossiness = 1.0f;
    TextureRef specular_glossiness_texture;

    // The emitted radiance's factor and texture: KHR_materials_unlit shows its base colour as
    // emission (material/node_graph.h), every other model its emissive factor and texture.
    bool unlit() const { return shading == ShadingModel::Unlit; }
    Rgb emission() const { return unlit() ? base_color : emissive * emissive_strength; }
    const TextureRef& emission_texture() const {
        return unlit() ? base_color_texture : emissive_texture;
    }
    bool is_emissive() const { return max_component(emission()) > 0.0f; }
};

// One glTF primitive in world space (node transforms applied). Every vertex has a normal: the
// loader generates flat normals, as glTF requires, where the file has none.
struct Mesh {
    std::string name;
    std::vector<Vec3> positions;
    std::vector<Vec3> normals;
    std::vector<Vec2> uv0;          // empty when the primitive has no TEXCOORD_0
    std::vector<Vec2> uv1;          // empty when the primitive has no TEXCOORD_1
    std::vector<Vec4> tangents;     // empty unless the file has TANGENT (xyz, w = handedness)
    std::vector<Vec4> colors;       // empty unless the file has COLOR_0 (linear RGBA)
    std::vector<uint32_t> indices;  // three per triangle
    int material = 0;

    size_t triangle_count() const { return indices.size() / 3; }
};

enum class LightType { Point, Spot, Directional };

// KHR_lights_punctual, photometric values taken 1:1 as radiometric: intensity is W/sr for point
// and spot lights (colour · intensity) and W/m² of irradiance for directional lights.
struct Light {
    std::string name;
    LightType type = LightType::Point;
    Rgb intensity{0.0f};
    Vec3 position{0.0f};
    Vec3 direction{0.0f, 0.0f, -1.0f};  // unit, the way the light travels (the node's -Z)
    float inner_cone = 0.0f;            // radians, spot only
    float outer_cone = kPi / 4.0f;      // radians, spot only
};

// Perspective pinhole camera looking down its local -Z with +Y up (glTF convention).
struct Camera {
    Mat4 camera_to_world{1.0f};  // rigid: rotation and translation only
    float yfov = 0.6911f;        // radians, vertical
    float znear = 0.01f;

    Vec3 position() const { return Vec3(camera_to_world[3]); }
};

// An AOV a scene file asks for (Mitsuba's `<integrator type="aov">`): mvpl's kind (albedo,
// normal, depth, position: engine/aov/aov_kind.h) and the file's name for its channels.
struct FileAov {
    std::string kind;
    std::string name;
};

struct Scene {
    std::string path;
    std::vector<Mesh> meshes;
    std::vector<Material> materials;
    std::vector<Texture> textures;
    std::vector<Light> lights;
    Environment environment;  // black: none; camera rays that leave the scene see it
    Camera camera;
    bool has_camera = false;  // false: the camera was made to frame the scene bounds
    // The file's perspective cameras in node traversal order (camera is the first); what
    // `--camera N` picks from.
    std::vector<Camera> cameras;
    // What the loader read past without refusing the file, one line each (e.g. an extension it
    // ignores); the command line prints them as warnings.
    std::vector<std::string> warnings;
    // What the file asks of the renderer where it says (Mitsuba's integrator and film); the
    // commands take them as defaults for --max-depth and --res. 0: the file says nothing.
    int max_depth = 0;  // Mitsuba's max_depth (−1 unlimited)
    int film_width = 0;
    int film_height = 0;
    // Mitsuba 0.6's `vpl` integrator: its shadowMapResolution, the default --shadow-res (0: no
    // such integrator), and its clamping, relative to each VPL's nearest and farthest geometry,
    // which the command line turns into the default --clamp (sampler/mitsuba_clamping.h;
    // negative: no such integrator).
    int shadow_resolution = 0;
    float vpl_clamping = -1.0f;
    // The AOVs the file asks for, written by render and reference unless --aov is given.
    std::vector<FileAov> aovs;

    Bounds bounds() const;
    size_t triangle_count() const;
    // Per material: whether a mesh with triangles uses it (an index out of range counts as
    // material 0, as the renderer draws it). Code is generated, and chains considered, for these.
    std::vector<bool> drawn_materials() const;
};

}  // namespace mvpl::scene
