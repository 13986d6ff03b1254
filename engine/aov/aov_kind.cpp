#include "engine/aov/aov_kind.h"

#include <algorithm>

#include "engine/core/error.h"

namespace mvpl::aov {

namespace {

struct KindName {
    Aov kind;
    std::string_view name;
};
constexpr KindName kKinds[] = {{Aov::Albedo, "albedo"},
                               {Aov::Normal, "normal"},
                               {Aov::Depth, "depth"},
                               {Aov::Position, "position"}};

std::vector<std::string> suffixed(const std::string& layer, const char* suffixes) {
    std::vector<std::string> out;
    for (const char* s = suffixes; *s; ++s)
        out.push_back(layer + "." + *s);
    return out;
}

// mvpl's channels for --aov (aov_kind.h says whose conventions they follow).
std::vector<std::string> own_channels(Aov kind) {
    switch (kind) {
        case Aov::Albedo:
            return suffixed("albedo", "RGB");
        case Aov::Normal:
            return suffixed("N", "XYZ");
        case Aov::Depth:
            return {"Z"};
        case Aov::Position:
            return suffixed("P", "XYZ");
    }
    return {};
}

// Mitsuba 3's aov integrator's channels for an AOV it calls `name`.
std::vector<std::string> mitsuba_channels(Aov kind, const std::string& name) {
    switch (kind) {
        case Aov::Albedo:
            return suffixed(name, "RGB");
        case Aov::Depth:
            return {name + ".T"};
        case Aov::Normal:
        case Aov::Position:
            return suffixed(name, "XYZ");
    }
    return {};
}

const KindName* find_kind(std::string_view name) {
    for (const KindName& k : kKinds) {
        if (k.name == name) return &k;
    }
    return nullptr;
}

std::string name_list() {
    std::string list;
    for (const KindName& k : kKinds)
        list += (list.empty() ? "" : ", ") + std::string(k.name);
    return list;
}

}  // namespace

std::vector<std::string_view> aov_names() {
    std::vector<std::string_view> names;
    for (const KindName& k : kKinds)
        names.push_back(k.name);
    return names;
}

std::vector<AovRequest> parse_aov_list(std::string_view text, const std::string& option) {
    std::vector<AovRequest> out;
    size_t start = 0;
    while (start <= text.size()) {
        const size_t comma = std::min(text.find(',', start), text.size());
        const std::string_view item = text.substr(start, comma - start);
        const KindName* k = find_kind(item);
        if (!k) {
            throw UsageError(option + ": unknown AOV '" + std::string(item) + "' (" + name_list() +
                             ")");
        }
        if (std::any_of(out.begin(), out.end(),
                        [&](const AovRequest& r) { return r.kind == k->kind; }))
            throw UsageError(option + ": AOV '" + std::string(item) + "' given twice");
        out.push_back(AovRequest{k->kind, std::string(k->name), own_channels(k->kind)});
        start = comma + 1;
    }
    return out;
}

std::vector<AovRequest> file_aovs(const scene::Scene& scene) {
    std::vector<AovRequest> out;
    for (const scene::FileAov& a : scene.aovs) {
        if (const KindName* k = find_kind(a.kind))
            out.push_back(AovRequest{k->kind, a.name, mitsuba_channels(k->kind, a.name)});
    }
    return out;
}

int components(Aov kind) {
    return kind == Aov::Depth ? 1 : 3;
}

}  // namespace mvpl::aov
