#include "python/keyword_args.h"

#include <algorithm>

namespace py = pybind11;

namespace mvpl::python {

namespace {

std::string text_of(const py::handle& value) {
    // Python's own spelling: repr of a float is the shortest string that reads back to it.
    if (py::isinstance<py::str>(value)) return value.cast<std::string>();
    return py::repr(value).cast<std::string>();
}

}  // namespace

std::vector<std::string> keyword_tokens(const py::kwargs& keywords) {
    std::vector<std::string> tokens;
    for (const auto& [key, value] : keywords) {
        const std::string name = key.cast<std::string>();
        // Appended, not "--" + name: GCC 12 warns falsely (-Wrestrict) about operator+ of a
        // literal and a temporary string.
        std::string option = "--";
        option.append(name);
        std::replace(option.begin(), option.end(), '_', '-');
        if (value.is_none()) continue;
        if (py::isinstance<py::bool_>(value)) {
            if (value.cast<bool>()) tokens.push_back(option);
            continue;
        }
        tokens.push_back(option);
        if (py::isinstance<py::tuple>(value) || py::isinstance<py::list>(value)) {
            const char* separator = name == "res" ? "x" : ",";
            std::string joined;
            for (const py::handle item : value) {
                if (!joined.empty()) joined.append(separator);
                joined.append(text_of(item));
            }
            tokens.push_back(joined);
        } else {
            tokens.push_back(text_of(value));
        }
    }
    return tokens;
}

}  // namespace mvpl::python
