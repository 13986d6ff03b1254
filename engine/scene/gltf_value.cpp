#include "engine/scene/gltf_value.h"

#include <climits>
#include <cmath>

namespace mvpl::scene::gltf {

const tinygltf::Value* find_extension(const Document& doc, const tinygltf::ExtensionMap& extensions,
                                      const char* name, const std::string& owner) {
    const auto it = extensions.find(name);
    if (it == extensions.end()) return nullptr;
    if (!it->second.IsObject()) doc.fail(owner + " has a " + name + " that is not a JSON object");
    return &it->second;
}

const tinygltf::Value* find_member(const tinygltf::Value& object, const char* key) {
    if (!object.IsObject() || !object.Has(key)) return nullptr;
    return &object.Get(key);
}

double read_number(const Document& doc, const tinygltf::Value* value, double fallback,
                   const std::string& what) {
    if (value == nullptr) return fallback;
    if (!value->IsNumber()) doc.fail(what + " is not a number");
    const double number = value->GetNumberAsDouble();
    if (!std::isfinite(number)) doc.fail(what + " is not finite");
    return number;
}

int read_int(const Document& doc, const tinygltf::Value* value, int fallback,
             const std::string& what) {
    if (value == nullptr) return fallback;
    if (value->IsInt()) return value->GetNumberAsInt();
    // tinygltf stores integers beyond int as reals; an integral real within range is fine.
    const double number = value->IsNumber() ? value->GetNumberAsDouble() : 0.5;
    if (!(number == std::floor(number) && number >= INT_MIN && number <= INT_MAX)) {
        doc.fail(what + " is not an integer");
    }
    return int(number);
}

std::vector<double> read_numbers(const Document& doc, const tinygltf::Value* value, size_t size,
                                 const std::vector<double>& fallback, const std::string& what) {
    if (value == nullptr) return fallback;
    if (!value->IsArray() || value->ArrayLen() != size) {
        doc.fail(what + " must be an array of " + std::to_string(size) + " numbers");
    }
    std::vector<double> numbers(size);
    for (size_t i = 0; i < size; ++i) {
        numbers[i] = read_number(doc, &value->Get(int(i)), 0.0, what);
    }
    return numbers;
}

std::string indexed(const std::string& path, size_t index) {
    // Appended piece by piece: GCC 12 warns (-Wrestrict, falsely) about "[" + std::to_string(i).
    std::string out = path;
    out += '[';
    out += std::to_string(index);
    out += ']';
    return out;
}

double check_magnitude(const Document& doc, double value, double limit, const std::string& where) {
    if (!(std::abs(value) <= limit)) {
        doc.fail(where + " is " + number_text(value) + ", beyond the supported magnitude " +
                 number_text(limit));
    }
    return value;
}

double check_between(const Document& doc, double value, double lo, double hi,
                     const std::string& where) {
    if (!(value >= lo && value <= hi)) {
        doc.fail(where + " is " + number_text(value) + ", outside the supported range " +
                 number_text(lo) + " to " + number_text(hi));
    }
    return value;
}

double check_non_negative(const Document& doc, double value, double limit,
                          const std::string& where) {
    if (value < 0.0) doc.fail(where + " is " + number_text(value) + ", which is negative");
    if (!(value <= limit)) {
        doc.fail(where + " is " + number_text(value) + ", beyond the supported " +
                 number_text(limit));
    }
    return value;
}

}  // namespace mvpl::scene::gltf
