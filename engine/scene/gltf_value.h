#pragma once
// Checked reads from tinygltf's generic JSON values (extension objects), so that a wrongly typed
// property is an InputError rather than an assert in tinygltf's accessors.
#include <string>
#include <vector>

#include "engine/scene/gltf_document.h"

namespace mvpl::scene::gltf {

// A double as a person would write it ("0.5", "1e+30"), for messages.
std::string number_text(double value);

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

}  // namespace mvpl::scene::gltf
