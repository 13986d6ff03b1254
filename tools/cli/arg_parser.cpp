#include "tools/cli/arg_parser.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

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

constexpr size_t kWidth = 80;

// Columns, not bytes: help text holds ×, ², ≤.
size_t columns(const std::string& word) {
    return size_t(std::count_if(word.begin(), word.end(), [](char c) {
        return (static_cast<unsigned char>(c) & 0xC0) != 0x80;
    }));
}

// `text` after `indent` spaces, broken at spaces into lines of at most kWidth columns (a longer
// word keeps a line of its own): some options' help is a paragraph.
void write_wrapped(std::ostream& out, const std::string& text, size_t indent) {
    std::istringstream words(text);
    std::string word;
    size_t column = 0;
    while (words >> word) {
        if (column > 0 && column + 1 + columns(word) > kWidth) {
            out << '\n';
            column = 0;
        }
        if (column == 0) {
            out << std::string(indent, ' ');
            column = indent;
        } else {
            out << ' ';
            ++column;
        }
        out << word;
        column += columns(word);
    }
    out << '\n';
}

// An example's command line, continued with " \\" where it is too long (so that it still pastes
// into a shell as one command), each option on the line of its value.
void write_command_line(std::ostream& out, const std::string& line) {
    std::istringstream words(line);
    std::vector<std::string> units;
    for (std::string word; words >> word;) {
        if (units.empty() || word[0] == '-')
            units.push_back(word);
        else
            units.back() += " " + word;
    }
    out << "  ";
    size_t column = 2;
    for (size_t i = 0; i < units.size(); ++i) {
        if (i > 0 && column + 1 + columns(units[i]) + 2 > kWidth) {
            out << " \\\n    ";
            column = 4;
        } else if (i > 0) {
            out << ' ';
            ++column;
        }
        out << units[i];
        column += columns(units[i]);
    }
    out << '\n';
}

std::function<void(const ArgParser&)>& listener() {
    static std::function<void(const ArgParser&)> f;
    return f;
}

}  // namespace

void ArgParser::set_listener(std::function<void(const ArgParser&)> f) {
    listener() = std::move(f);
}

std::vector<ArgParser::OptionInfo> ArgParser::options() const {
    std::vector<OptionInfo> out;
    for (const Option& o : m_options)
        out.push_back({o.name, o.aliases, o.takes_value ? o.value_name : ""});
    return out;
}

ArgParser::ArgParser(std::string command, std::string summary)
    : m_command(std::move(command)), m_summary(std::move(summary)) {
    std::string heading = m_command + " options";
    heading[0] = char(std::toupper(static_cast<unsigned char>(heading[0])));
    m_groups.push_back(heading);
}

void ArgParser::begin_group(const std::string& heading) {
    const auto it = std::find(m_groups.begin(), m_groups.end(), heading);
    m_group = size_t(it - m_groups.begin());
    if (it == m_groups.end()) m_groups.push_back(heading);
}

void ArgParser::add_option(const std::string& name, const std::string& help,
                           const std::string& value_name,
                           std::function<void(const std::string&)> apply, bool repeatable) {
    Option o;
    o.name = name;
    o.help = help;
    o.takes_value = !value_name.empty();
    o.apply = std::move(apply);
    o.repeatable = repeatable;
    o.value_name = value_name;
    o.group = m_group;
    m_options.push_back(std::move(o));
}

void ArgParser::add_flag(const std::string& name, bool* target, const std::string& help) {
    add_option(name, help, "", [target](const std::string&) { *target = true; });
}

void ArgParser::add_int(const std::string& name, int* target, const std::string& help,
                        const std::string& value_name) {
    add_option(name, help + " (default " + std::to_string(*target) + ")", value_name,
               [name, target](const std::string& v) { *target = parse_number<int>(name, v); });
}

void ArgParser::add_uint64(const std::string& name, uint64_t* target, const std::string& help,
                           const std::string& value_name) {
    add_option(name, help + " (default " + std::to_string(*target) + ")", value_name,
               [name, target](const std::string& v) { *target = parse_number<uint64_t>(name, v); });
}

void ArgParser::add_float(const std::string& name, float* target, const std::string& help,
                          const std::string& value_name) {
    std::ostringstream def;
    def << *target;
    add_option(name, help + " (default " + def.str() + ")", value_name,
               [name, target](const std::string& v) { *target = parse_number<float>(name, v); });
}

void ArgParser::add_string(const std::string& name, std::string* target, const std::string& help,
                           const std::string& value_name) {
    add_option(name, help, value_name, [target](const std::string& v) { *target = v; });
}

void ArgParser::add_strings(const std::string& name, std::vector<std::string>* target,
                            const std::string& help, const std::string& value_name) {
    add_option(
        name, help + " (repeatable)", value_name,
        [target](const std::string& v) { target->push_back(v); }, true);
}

void ArgParser::add_resolution(const std::string& name, int* width, int* height,
                               const std::string& help) {
    const std::string def = std::to_string(*width) + "x" + std::to_string(*height);
    add_option(name, help + " (default " + def + ")", "WxH",
               [name, width, height](const std::string& v) {
                   const size_t x = v.find('x');
                   if (x == std::string::npos) throw UsageError(name + ": '" + v + "' is not WxH");
                   const int w = parse_number<int>(name, v.substr(0, x));
                   const int h = parse_number<int>(name, v.substr(x + 1));
                   if (w < 1 || h < 1 || w > 16384 || h > 16384) {
                       throw UsageError(name + ": '" + v + "' is out of range 1..16384");
                   }
                   *width = w;
                   *height = h;
               });
}

void ArgParser::add_alias(const std::string& alias, const std::string& name) {
    const auto it = std::find_if(m_options.begin(), m_options.end(),
                                 [&name](const Option& o) { return o.name == name; });
    // Declaration mistakes, caught by any --help.
    if (it == m_options.end()) throw std::logic_error("alias of unknown option " + name);
    if (find(alias)) throw std::logic_error("alias " + alias + " names an option already");
    it->aliases.push_back(alias);
}

void ArgParser::add_positional(const std::string& name, std::string* target,
                               const std::string& help) {
    m_positionals.emplace_back(name, target);
    m_positional_help.push_back(help);
}

void ArgParser::add_check(std::function<void()> check) {
    m_checks.push_back(std::move(check));
}

void ArgParser::add_example(const std::string& command_line, const std::string& what) {
    m_examples.push_back({command_line, what});
}

const ArgParser::Option* ArgParser::find(const std::string& name) const {
    for (const Option& o : m_options) {
        if (o.name == name) return &o;
        if (std::find(o.aliases.begin(), o.aliases.end(), name) != o.aliases.end()) return &o;
    }
    return nullptr;
}

bool ArgParser::given(const std::string& name) const {
    const Option* option = find(name);
    const std::string& canonical = option ? option->name : name;
    return std::find(m_given.begin(), m_given.end(), canonical) != m_given.end();
}

bool ArgParser::parse(const std::vector<std::string>& args) {
    m_given.clear();
    if (listener()) {
        listener()(*this);
        return false;
    }
    size_t positional = 0;
    // Each option given, as it was spelled (an alias or its name).
    std::vector<std::pair<const Option*, std::string>> given;
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
            // A second value would silently replace the first: say so instead, also where one
            // of the two was an alias.
            const auto earlier = std::find_if(
                given.begin(), given.end(), [option](const auto& g) { return g.first == option; });
            if (!option->repeatable && earlier != given.end()) {
                const std::string spelled =
                    earlier->second == name ? "" : " (as " + earlier->second + " and " + name + ")";
                throw UsageError(m_command + ": " + option->name + " given twice" + spelled);
            }
            given.emplace_back(option, name);
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

void ArgParser::print_groups(std::ostream& out) const {
    for (size_t g = 0; g < m_groups.size(); ++g) {
        bool empty = true;
        for (const Option& o : m_options) {
            if (o.group != g) continue;
            if (empty) out << "\n" << m_groups[g] << ":\n";
            empty = false;
            out << "  " << o.name;
            if (o.takes_value) out << " " << o.value_name;
            for (size_t k = 0; k < o.aliases.size(); ++k)
                out << (k == 0 ? " (alias: " : ", ") << o.aliases[k];
            out << (o.aliases.empty() ? "\n" : ")\n");
            write_wrapped(out, o.help, 6);
        }
    }
}

std::string ArgParser::usage() const {
    std::ostringstream out;
    out << "usage: mvpl " << m_command;
    for (const auto& p : m_positionals)
        out << " " << p.first;
    out << " [options]\n\n" << m_summary << "\n";
    if (!m_positionals.empty()) out << "\nArguments:\n";
    for (size_t i = 0; i < m_positionals.size(); ++i) {
        out << "  " << m_positionals[i].first << "\n";
        write_wrapped(out, m_positional_help[i], 6);
    }
    print_groups(out);
    if (!m_examples.empty()) out << "\nExamples:\n";
    for (const Example& e : m_examples) {
        write_command_line(out, e.command_line);
        write_wrapped(out, e.what, 6);
    }
    return out.str();
}

}  // namespace mvpl::cli
