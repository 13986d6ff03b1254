#include "tools/cli/arg_parser.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "engine/core/error.h"

namespace mvpl::cli {

namespace {

template <typename T>
T parse_number(const std::string& option, const std::string& text) {
    T value{};
    const char* begin = text.data();
    const char* end = begin + text.size();
    const auto [ptr, ec] = std::from_chars(begin, end, value);
    if (ec != std::errc() || ptr != end || text.empty()) {
        throw UsageError(option + ": '" + text + "' is not a valid number");
    }
    if constexpr (std::is_floating_point_v<T>) {
        if (!std::isfinite(value)) throw UsageError(option + ": '" + text + "' is not finite");
    }
    return value;
}

}  // namespace

ArgParser::ArgParser(std::string command, std::string summary)
    : m_command(std::move(command)), m_summary(std::move(summary)) {}

void ArgParser::add_flag(const std::string& name, bool* target, const std::string& help) {
    m_options.push_back({name, help, false, [target](const std::string&) { *target = true; }});
}

void ArgParser::add_int(const std::string& name, int* target, const std::string& help) {
    m_options.push_back(
        {name, help + " (default " + std::to_string(*target) + ")", true,
         [name, target](const std::string& v) { *target = parse_number<int>(name, v); }});
}

void ArgParser::add_uint64(const std::string& name, uint64_t* target, const std::string& help) {
    m_options.push_back(
        {name, help + " (default " + std::to_string(*target) + ")", true,
         [name, target](const std::string& v) { *target = parse_number<uint64_t>(name, v); }});
}

void ArgParser::add_float(const std::string& name, float* target, const std::string& help) {
    std::ostringstream def;
    def << *target;
    m_options.push_back(
        {name, help + " (default " + def.str() + ")", true,
         [name, target](const std::string& v) { *target = parse_number<float>(name, v); }});
}

void ArgParser::add_string(const std::string& name, std::string* target, const std::string& help) {
    m_options.push_back({name, help, true, [target](const std::string& v) { *target = v; }});
}

void ArgParser::add_strings(const std::string& name, std::vector<std::string>* target,
                            const std::string& help) {
    m_options.push_back({name, help + " (repeatable)", true,
                         [target](const std::string& v) { target->push_back(v); }, true});
}

void ArgParser::add_resolution(const std::string& name, int* width, int* height,
                               const std::string& help) {
    const std::string def = std::to_string(*width) + "x" + std::to_string(*height);
    m_options.push_back(
        {name, help + " (default " + def + ")", true, [name, width, height](const std::string& v) {
             const size_t x = v.find('x');
             if (x == std::string::npos) throw UsageError(name + ": '" + v + "' is not WxH");
             const int w = parse_number<int>(name, v.substr(0, x));
             const int h = parse_number<int>(name, v.substr(x + 1));
             if (w < 1 || h < 1 || w > 16384 || h > 16384) {
                 throw UsageError(name + ": '" + v + "' is out of range 1..16384");
             }
             *width = w;
             *height = h;
         }});
}

void ArgParser::add_positional(const std::string& name, std::string* target,
                               const std::string& help) {
    m_positionals.emplace_back(name, target);
    m_positional_help.push_back(help);
}

void ArgParser::add_check(std::function<void()> check) {
    m_checks.push_back(std::move(check));
}

const ArgParser::Option* ArgParser::find(const std::string& name) const {
    for (const Option& o : m_options) {
        if (o.name == name) return &o;
    }
    return nullptr;
}

bool ArgParser::given(const std::string& name) const {
    return std::find(m_given.begin(), m_given.end(), name) != m_given.end();
}

bool ArgParser::parse(const std::vector<std::string>& args) {
    m_given.clear();
    size_t positional = 0;
    std::vector<const Option*> given;
    for (size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        if (a == "--help" || a == "-h") {
            std::fputs(usage().c_str(), stdout);
            return false;
        }
        if (a.size() > 1 && a[0] == '-' &&
            !(a.size() > 1 && (std::isdigit(static_cast<unsigned char>(a[1])) || a[1] == '.'))) {
            std::string name = a;
            std::string value;
            bool has_inline = false;
            if (const size_t eq = a.find('='); eq != std::string::npos && a.rfind("--", 0) == 0) {
                name = a.substr(0, eq);
                value = a.substr(eq + 1);
                has_inline = true;
            } else if (a.size() > 2 && a[1] != '-' && find(a.substr(0, 2))) {
                // A short option with its value attached, as Mitsuba's -Dname=value.
                name = a.substr(0, 2);
                value = a.substr(2);
                has_inline = true;
            }
            const Option* option = find(name);
            if (!option)
                throw UsageError(m_command + ": unknown option '" + name + "' (see mvpl " +
                                 m_command + " --help)");
            if (option->takes_value) {
                if (!has_inline) {
                    if (i + 1 >= args.size())
                        throw UsageError(m_command + ": " + name + " needs a value");
                    value = args[++i];
                }
            } else if (has_inline) {
                throw UsageError(m_command + ": " + name + " takes no value");
            }
            // A second value would silently replace the first: say so instead.
            if (!option->repeatable && std::find(given.begin(), given.end(), option) != given.end())
                throw UsageError(m_command + ": " + name + " given twice");
            given.push_back(option);
            m_given.push_back(option->name);
            option->apply(value);
            continue;
        }
        if (positional >= m_positionals.size())
            throw UsageError(m_command + ": unexpected argument '" + a + "'");
        *m_positionals[positional++].second = a;
    }
    if (positional < m_positionals.size()) {
        throw UsageError(m_command + ": missing " + m_positionals[positional].first +
                         " (see mvpl " + m_command + " --help)");
    }
    for (const auto& check : m_checks)
        check();
    return true;
}

std::string ArgParser::usage() const {
    std::ostringstream out;
    out << "usage: mvpl " << m_command;
    for (const auto& p : m_positionals)
        out << " " << p.first;
    out << " [options]\n\n" << m_summary << "\n\n";
    for (size_t i = 0; i < m_positionals.size(); ++i) {
        out << "  " << m_positionals[i].first << "\n      " << m_positional_help[i] << "\n";
    }
    for (const Option& o : m_options) {
        out << "  " << o.name << (o.takes_value ? " VALUE" : "") << "\n      " << o.help << "\n";
    }
    return out.str();
}

}  // namespace mvpl::cli
