#include "engine/scene/mitsuba/aov_integrator.h"

#include <algorithm>
#include <string>
#include <string_view>
#include <vector>

#include "engine/scene/mitsuba/properties.h"
#include "engine/scene/mitsuba/sensor.h"

namespace mvpl::scene::mitsuba {

namespace {

// Mitsuba's types and mvpl's kind for each ("": Mitsuba has it, mvpl does not write it).
struct TypeMap {
    std::string_view mitsuba;
    std::string_view mvpl;
};
constexpr TypeMap kTypes[] = {{"albedo", "albedo"},    {"depth", "depth"}, {"position", "position"},
                              {"sh_normal", "normal"}, {"geo_normal", ""}, {"uv", ""},
                              {"dp_du", ""},           {"dp_dv", ""},      {"duv_dx", ""},
                              {"duv_dy", ""},          {"prim_index", ""}, {"shape_index", ""},
                              {"boundary_test", ""}};

// Mitsuba's string::tokenize: pieces between commas and blanks, empty ones dropped.
std::vector<std::string> tokens(const std::string& text, std::string_view delimiters) {
    std::vector<std::string> out;
    size_t start = 0;
    while (start < text.size()) {
        const size_t end = std::min(text.find_first_of(delimiters, start), text.size());
        if (end > start) out.push_back(text.substr(start, end - start));
        start = end + 1;
    }
    return out;
}

}  // namespace

void read_aov_integrator(Context& ctx, pugi::xml_node integrator) {
    const pugi::xml_node at = ctx.property(integrator, "aovs");
    for (const std::string& token : tokens(ctx.get_string(integrator, "aovs", ""), ", ")) {
        const size_t colon = token.find(':');
        if (colon == std::string::npos || colon == 0 || colon + 1 == token.size() ||
            token.find(':', colon + 1) != std::string::npos)
            ctx.fail(at, "AOV '" + token + "' is not a name:type pair");
        const std::string name = token.substr(0, colon);
        const std::string type = token.substr(colon + 1);
        const auto map = std::find_if(std::begin(kTypes), std::end(kTypes),
                                      [&](const TypeMap& m) { return m.mitsuba == type; });
        if (map == std::end(kTypes)) ctx.fail(at, "AOV type '" + type + "' is not Mitsuba's");
        std::vector<FileAov>& aovs = ctx.scene().aovs;
        if (std::any_of(aovs.begin(), aovs.end(), [&](const FileAov& a) { return a.name == name; }))
            ctx.fail(at, "AOV name '" + name + "' given twice");
        if (map->mvpl.empty()) {
            ctx.warn(at, "AOV '" + name + "' of type '" + type +
                             "' is not written (mvpl writes albedo, depth, position, sh_normal)");
            continue;
        }
        aovs.push_back(FileAov{std::string(map->mvpl), name});
    }
    for (pugi::xml_node inner : ctx.objects(integrator, "integrator"))
        read_integrator(ctx, inner);
}

}  // namespace mvpl::scene::mitsuba
