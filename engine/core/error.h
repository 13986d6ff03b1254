#pragma once
// Errors that reach the user. InputError and UsageError end the program with exit code 2 and one
// line `mvpl: error: …`; anything else is an internal failure (exit code 1).
#include <stdexcept>
#include <string>

namespace mvpl {

// Bad input file: the message names the file and what is wrong with it.
class InputError : public std::runtime_error {
public:
    InputError(const std::string& file, const std::string& what)
        : std::runtime_error(file + ": " + what) {}
};

// Bad command line.
class UsageError : public std::runtime_error {
public:
    explicit UsageError(const std::string& what) : std::runtime_error(what) {}
};

}  // namespace mvpl
