#pragma once
// Checked reads from tinygltf's generic JSON values (extension objects), so that a wrongly typed
// property is an InputError rather than an assert in tinygltf's accessors.
#include <string>
#include <vector>

#include "engine/scene/gltf_document.h"
#include "engine/scene/scene_range.h"  // number_text

namespace mvpl::scene::gltf {

// The extension object `name` in `extensions`, or null when absent; `owner` names the holder in
// messages ("material 3").
const tinygltf::Value* find_extension(const Document& doc, const tinygltf::ExtensionMap& extensions,
                                      const char* name, const std::string& owner);

// Member `key` of a JSON object, or null when absent.
const tinygltf::Value* find_member(const tinygltf::Value& object, const char* key);

// A finite number, or `fallback` when `value` is null.
double read_number(const Document& doc, const tinygltf::Value* value, double fallback,
                   const std::string& what);
// An integer, or `fallback` when `value` is null.
int read_int(const Document& doc, const tinygltf::Value* value, int fallback,
             const std::string& what);
// An array of exactly `size` finite numbers, or `fallback` when `value` is null.
std::vector<double> read_numbers(const Document& doc, const tinygltf::Value* value, size_t size,
                                 const std::vector<double>& fallback, const std::string& what);

// "path[index]": the JSON path of an array element.
std::string indexed(const std::string& path, size_t index);

// Range checks against the limits of engine/scene/scene_range.h, for values already known to be
// numbers. `where` names the value by its JSON path ("materials[2].emissiveFactor[0]"); a value
// out of range fails with "<where> is <value>, beyond the supported …" and is otherwise
// returned as it is. NaN is always out of range.
double check_magnitude(const Document& doc, double value, double limit, const std::string& where);
double check_between(const Document& doc, double value, double lo, double hi,
                     const std::string& where);
// A value that must also be non-negative: [0, limit].
double check_non_negative(const Document& doc, double value, double limit,
                          const std::string& where);

}  // namespace mvpl::scene::gltf
