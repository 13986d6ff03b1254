#pragma once
// A small declarative command-line parser: each command binds its options to variables, then
// parse() fills them or throws UsageError with one line naming the offending argument. Checks
// (add_check) run after every argument was read, so that an option group (option_groups.h)
// declares its options and their ranges in one place.
#include <cstdint>
#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

namespace mvpl::cli {

class ArgParser {
public:
    ArgParser(std::string command, std::string summary);

    // Options added from here on are listed in usage() under `heading` (e.g. "Camera"), until
    // the next call; a heading opened before takes more options again. Until the first call
    // they go under the command's own heading ("Render options").
    void begin_group(const std::string& heading);

    // `value_name` is what usage() shows after the option: N, X, SEC, FILE, mc|metropolis…
    void add_flag(const std::string& name, bool* target, const std::string& help);
    void add_int(const std::string& name, int* target, const std::string& help,
                 const std::string& value_name = "N");
    void add_uint64(const std::string& name, uint64_t* target, const std::string& help,
                    const std::string& value_name = "N");
    void add_float(const std::string& name, float* target, const std::string& help,
                   const std::string& value_name = "X");
    void add_string(const std::string& name, std::string* target, const std::string& help,
                    const std::string& value_name = "NAME");
    // Repeatable: each occurrence appends.
    void add_strings(const std::string& name, std::vector<std::string>* target,
                     const std::string& help, const std::string& value_name = "NAME");
    // "WxH", e.g. 512x512.
    void add_resolution(const std::string& name, int* width, int* height, const std::string& help);
    // Another name for the option `name` (added before): parsed as it, "given twice" with it,
    // and given(alias) == given(name); usage() lists it beside the option.
    void add_alias(const std::string& alias, const std::string& name);
    // Positional arguments, in order; all required.
    void add_positional(const std::string& name, std::string* target, const std::string& help);
    // Runs after a successful parse, in the order added; throws UsageError on a bad value.
    void add_check(std::function<void()> check);
    // A command line that usage() shows at its end, under "Examples:", with what it does.
    void add_example(const std::string& command_line, const std::string& what);
    // The command name, the prefix of every error message ("render: --batch must be …").
    const std::string& command() const { return m_command; }

    // Whether the last parse() saw the option (by its name or an alias) on the command line.
    bool given(const std::string& name) const;

    // Returns false when --help was given (usage already printed to stdout), or while a
    // listener is set (below).
    bool parse(const std::vector<std::string>& args);
    std::string usage() const;

    // An option as the command line spells it: its name, its aliases and what its value is
    // (value_name: N, FILE, mc|metropolis…; empty for a flag).
    struct OptionInfo {
        std::string name;
        std::vector<std::string> aliases;
        std::string value_name;
    };
    std::vector<OptionInfo> options() const;
    // While set, parse() hands its parser to `listener` and returns false, parsing nothing, as
    // it does for --help: running a command with the listener set reads its option table
    // (`mvpl completion`) without a second declaration of it. An empty function unsets it.
    static void set_listener(std::function<void(const ArgParser&)> listener);

private:
    struct Option {
        std::string name;
        std::string help;
        bool takes_value = true;
        std::function<void(const std::string&)> apply;
        bool repeatable = false;  // add_strings; any other option given twice is an error
        std::string value_name;
        std::vector<std::string> aliases;
        size_t group = 0;  // index into m_groups
    };
    struct Example {
        std::string command_line;
        std::string what;
    };
    // A flag where `value_name` is empty.
    void add_option(const std::string& name, const std::string& help, const std::string& value_name,
                    std::function<void(const std::string&)> apply, bool repeatable = false);
    const Option* find(const std::string& name) const;
    void print_groups(std::ostream& out) const;

    std::string m_command;
    std::string m_summary;
    std::vector<Option> m_options;
    std::vector<std::string> m_groups;
    size_t m_group = 0;
    std::vector<std::pair<std::string, std::string*>> m_positionals;
    std::vector<std::string> m_positional_help;
    std::vector<std::function<void()>> m_checks;
    std::vector<Example> m_examples;
    std::vector<std::string> m_given;
};

}  // namespace mvpl::cli
