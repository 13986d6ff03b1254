#pragma once
// The command line's errors as Python exceptions: bad input (what `mvpl` reports with exit code
// 2) raises ValueError, anything else RuntimeError, each with the one line `mvpl` prints
// ("mvpl: error: render: --vpls must be in 1..2^32").
#include <pybind11/pybind11.h>

namespace mvpl::python {

void register_error_translation();

}  // namespace mvpl::python
