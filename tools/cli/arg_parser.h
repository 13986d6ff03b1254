#pragma once
// A small declarative command-line parser: each command binds its options to variables, then
// parse() fills them or throws UsageError with one line naming the offending argument. Checks
// (add_check) run after every argument was read, so that an option group (option_groups.h)
// declares its options and their ranges in one place.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace mvpl::cli {

class ArgParser {
public:
    ArgParser(std::string command, std::string summary);

    void add_flag(const std::string& name, bool* target, const std::string& help);
    void add_int(const std::string& name, int* target, const std::string& help);
    void add_uint64(const std::string& name, uint64_t* target, const std::string& help);
    void add_float(const std::string& name, float* target, const std::string& help);
    void add_string(const std::string& name, std::string* target, const std::string& help);
    // Repeatable: each occurrence appends.
    void add_strings(const std::string& name, std::vector<std::string>* target,
                     const std::string& help);
    // "WxH", e.g. 512x512.
    void add_resolution(const std::string& name, int* width, int* height, const std::string& help);
    // Positional arguments, in order; all required.
    void add_positional(const std::string& name, std::string* target, const std::string& help);
    // Runs after a successful parse, in the order added; throws UsageError on a bad value.
    void add_check(std::function<void()> check);
    // The command name, the prefix of every error message ("render: --batch must be …").
    const std::string& command() const { return m_command; }

    // Whether the last parse() saw the option on the command line.
    bool given(const std::string& name) const;

    // Returns false when --help was given (usage already printed to stdout).
    bool parse(const std::vector<std::string>& args);
    std::string usage() const;

private:
    struct Option {
        std::string name;
        std::string help;
        bool takes_value = true;
        std::function<void(const std::string&)> apply;
        bool repeatable = false;  // add_strings; any other option given twice is an error
    };
    const Option* find(const std::string& name) const;

    std::string m_command;
    std::string m_summary;
    std::vector<Option> m_options;
    std::vector<std::pair<std::string, std::string*>> m_positionals;
    std::vector<std::string> m_positional_help;
    std::vector<std::function<void()>> m_checks;
    std::vector<std::string> m_given;
};

}  // namespace mvpl::cli
