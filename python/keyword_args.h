#pragma once
// Python keywords as command-line tokens, so that the module's keywords are the command line's
// options, parsed by the same option tables (tools/cli/render_args.h): `vpls=4096` is `--vpls
// 4096`, `no_caustics=True` is `--no-caustics`, `res=(640, 480)` is `--res 640x480`.
#include <pybind11/pybind11.h>

#include <string>
#include <vector>

namespace mvpl::python {

// Each keyword `name=value` as `--name` (underscores become dashes) followed by its value: True
// alone (a flag), False and None not at all, a str, int or float as Python prints it, a tuple
// or list joined by commas (by "x" for `res`). Keywords the caller takes itself (`progress`)
// must be removed first.
std::vector<std::string> keyword_tokens(const pybind11::kwargs& keywords);

}  // namespace mvpl::python
