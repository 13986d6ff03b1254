#include "python/errors.h"

#include <exception>
#include <string>

#include "engine/cluster/cluster.h"

namespace py = pybind11;

namespace mvpl::python {

namespace {

// As tools/main.cpp prints it: one line, embedded newlines folded.
std::string error_line(std::exception_ptr error, int code) {
    std::string text = cluster::message_of(error);
    for (char& c : text)
        if (c == '\n' || c == '\r') c = ' ';
    return std::string("mvpl: ") + (code == 2 ? "error: " : "internal error: ") + text;
}

}  // namespace

void register_error_translation() {
    py::register_exception_translator([](std::exception_ptr error) {
        if (!error) return;
        try {
            std::rethrow_exception(error);
        } catch (const py::error_already_set&) {
            throw;  // Python's own (KeyboardInterrupt, the progress callback's): pybind11's
        } catch (const py::builtin_exception&) {
            throw;
        } catch (const std::exception&) {
            const int code = cluster::exit_code_of(error);
            PyErr_SetString(code == 2 ? PyExc_ValueError : PyExc_RuntimeError,
                            error_line(error, code).c_str());
        }
    });
}

}  // namespace mvpl::python
