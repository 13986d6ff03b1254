#include "tools/cli/exr_outputs.h"

#include <algorithm>

#include "engine/core/error.h"
#include "engine/core/file_extension.h"
#include "engine/core/version.h"

namespace mvpl::cli {

namespace {

bool has_exr(const std::vector<std::string>& outputs) {
    return std::any_of(outputs.begin(), outputs.end(),
                       [](const std::string& p) { return lower_extension(p) == ".exr"; });
}

std::string shell_quoted(const std::string& word) {
    const bool plain = !word.empty() && std::all_of(word.begin(), word.end(), [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) ||
               std::string_view("-_./,:=+@%").find(c) != std::string_view::npos;
    });
    if (plain) return word;
    std::string out = "'";
    for (const char c : word) {
        if (c == '\'')
            out += "'\\''";
        else
            out += c;
    }
    out += '\'';
    return out;
}

}  // namespace

void add_aov_option(ArgParser& parser, std::string* list, const std::vector<std::string>* outputs) {
    std::string names;
    for (const std::string_view n : aov::aov_names()) {
        if (!names.empty()) names += ',';
        names.append(n);
    }
    parser.add_string("--aov", list,
                      "extra EXR channels, averaged over the image's sub-pixel positions: "
                      "albedo (albedo.R/G/B), normal (N.X/Y/Z), depth (Z), position (P.X/Y/Z)",
                      names);
    parser.add_check([&parser, list, outputs] {
        if (!parser.given("--aov")) return;
        aov::parse_aov_list(*list, parser.command() + ": --aov");
        // No -o: the command's default output, an .exr.
        if (!outputs->empty() && !has_exr(*outputs))
            throw UsageError(parser.command() + ": --aov writes EXR channels: give -o FILE.exr");
    });
}

std::vector<aov::AovRequest> aov_requests(const ArgParser& parser, const std::string& list,
                                          const scene::Scene& scene,
                                          const std::vector<std::string>& outputs) {
    if (!has_exr(outputs)) return {};
    if (parser.given("--aov")) return aov::parse_aov_list(list, parser.command() + ": --aov");
    return aov::file_aovs(scene);
}

std::string command_line(const std::string& command, const Args& args) {
    std::string line = "mvpl ";
    line += command;
    for (const std::string& a : args) {
        line += ' ';
        line += shell_quoted(a);
    }
    return line;
}

std::vector<ExrAttribute> run_attributes(const RunFacts& facts) {
    std::vector<ExrAttribute> out;
    out.push_back({"mvpl/version", std::string(version())});
    out.push_back(
        {"mvpl/commandLine", command_line(facts.command, facts.args ? *facts.args : Args{})});
    out.push_back({"mvpl/seed", std::to_string(facts.seed)});
    if (facts.vpls) out.push_back({"mvpl/vpls", std::to_string(*facts.vpls)});
    if (facts.spp) out.push_back({"mvpl/spp", *facts.spp});
    out.push_back({"mvpl/wallSeconds", facts.wall_seconds});
    return out;
}

}  // namespace mvpl::cli
