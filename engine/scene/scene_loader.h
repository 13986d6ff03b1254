#pragma once
#include <string>
#include <vector>

#include "engine/scene/scene.h"

namespace mvpl::scene {

// What the command line adds to a scene file (Mitsuba's `-D name=value` and `-a PATH`).
struct LoadOptions {
    std::vector<std::pair<std::string, std::string>> defines;  // override `<default>`s
    std::vector<std::string> search_paths;                     // folders for relative files
};

// Loads a scene by its file extension (.gltf, .glb, .ply, .obj, .xml). Throws InputError naming
// the file and what is wrong; never crashes or allocates without bound on malformed input.
Scene load_scene(const std::string& path, const LoadOptions& options = {});

// Mitsuba 3 and Mitsuba 0.6 XML scenes (engine/scene/mitsuba/).
Scene load_mitsuba(const std::string& path, const LoadOptions& options = {});

// glTF 2.0 (.gltf with external or embedded buffers, .glb) via tinygltf.
Scene load_gltf(const std::string& path);

// For the bare-mesh loaders (engine/scene/ply_loader.h, obj_loader.h).
//
// Grey diffuse: reflectance 0.5 (Mitsuba's default `diffuse`), no dielectric layer.
Material default_mesh_material();
// Completes a scene read from a bare mesh file: a mesh without normals, or with a zero or
// non-finite one, gets flat normals (as glTF requires of a primitive without NORMAL); the
// camera frames the bounds (frame_bounds, as for a glTF file without a camera). Meshes must
// have valid indices and finite positions already.
Scene mesh_scene(const std::string& path, std::vector<Mesh> meshes,
                 std::vector<Material> materials);

}  // namespace mvpl::scene
