// load_gltf: the glTF document turned into the scene model (see scene_loader.h).
#include "engine/scene/camera.h"
#include "engine/scene/gltf_document.h"
#include "engine/scene/gltf_geometry.h"
#include "engine/scene/gltf_materials.h"
#include "engine/scene/gltf_nodes.h"
#include "engine/scene/gltf_punctual.h"
#include "engine/scene/gltf_textures.h"
#include "engine/scene/gltf_value.h"
#include "engine/scene/scene_loader.h"
#include "engine/scene/scene_range.h"

namespace mvpl::scene {

Scene load_gltf(const std::string& path) {
    const gltf::Document doc = gltf::read_document(path);
    Scene scene;
    scene.path = path;
    gltf::TextureCache textures(doc, scene.textures);
    gltf::MaterialTable materials(doc, scene, textures);
    gltf::GeometryBudget budget;
    std::vector<std::string> light_names;  // JSON paths of scene.lights, for messages

    gltf::walk_scene(doc, [&](int node, const DMat4& world) {
        const tinygltf::Node& gltf_node = doc.model.nodes[size_t(node)];
        if (gltf_node.mesh != -1) {
            const size_t mesh_count = doc.model.meshes.size();
            if (gltf_node.mesh < 0 || size_t(gltf_node.mesh) >= mesh_count) {
                doc.fail("node " + std::to_string(node) + " refers to mesh " +
                         std::to_string(gltf_node.mesh) + ", but the file has " +
                         std::to_string(mesh_count) + " meshes");
            }
            const auto& primitives = doc.model.meshes[size_t(gltf_node.mesh)].primitives;
            for (size_t p = 0; p < primitives.size(); ++p) {
                Mesh mesh;
                if (!gltf::build_primitive_mesh(doc, gltf_node.mesh, int(p), node, world, budget,
                                                mesh)) {
                    continue;
                }
                mesh.material = materials.material_for(
                    primitives[p].material,
                    "mesh " + std::to_string(gltf_node.mesh) + " primitive " + std::to_string(p));
                scene.meshes.push_back(std::move(mesh));
            }
        }
        std::string light_name;
        if (auto light = gltf::node_light(doc, node, world, &light_name)) {
            scene.lights.push_back(*light);
            light_names.push_back(light_name);
        }
        // Every camera is checked; the first perspective one in traversal order is used.
        if (auto camera = gltf::node_camera(doc, node, world)) {
            if (!scene.has_camera) scene.camera = *camera;
            scene.has_camera = true;
            scene.cameras.push_back(*camera);
        }
    });
    for (const std::string& name : doc.model.extensionsUsed) {
        if (!gltf::is_supported_extension(name))
            scene.warnings.push_back("extension " + name + " is not supported; it is ignored");
    }

    textures.decode_pending();  // the texels, before anything reads them
    if (scene.meshes.empty()) doc.fail("no triangle geometry");
    if (!scene.has_camera) scene.camera = frame_bounds(scene.bounds());
    check_emitted_power(
        scene, [&](int light) { return light_names[size_t(light)]; },
        [](int material) { return gltf::indexed("materials", size_t(material)); },
        [&](const std::string& what) { doc.fail(what); });
    return scene;
}

}  // namespace mvpl::scene
