#pragma once
// Private to the glTF loader (only engine/scene/gltf_*.cpp include it): the parsed tinygltf model
// and the one way to report what is wrong with it.
#include <string>

#include <tiny_gltf.h>

#include "engine/core/error.h"

namespace mvpl::scene::gltf {

// `what` with control characters blanked and its length capped: messages quote strings from
// the file (URIs, names, types) and must stay on one line.
std::string printable(const std::string& what);

struct Document {
    std::string path;
    std::string base_dir;  // where external buffers and images are read from
    tinygltf::Model model;

    [[noreturn]] void fail(const std::string& what) const {
        throw InputError(path, printable(what));
    }
};

// Reads a .gltf or .glb (binary when the file starts with the 'glTF' magic), checks what tinygltf
// would choke on before handing it over, and rejects required extensions we do not implement.
// External buffers and images are read relative to the file. Throws InputError.
Document read_document(const std::string& path);

// Whether mvpl reads the glTF extension `name` (the others are refused when a file requires them
// and ignored with a warning when it only uses them).
bool is_supported_extension(const std::string& name);

// tinygltf's multi-line, sometimes data-URI-laden messages as one short line.
std::string one_line(const std::string& message);

}  // namespace mvpl::scene::gltf
