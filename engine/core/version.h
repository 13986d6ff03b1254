#pragma once
// mvpl's version, written once: CMake's project(mvpl VERSION …) in the top CMakeLists.txt.

namespace mvpl {

const char* version();

}  // namespace mvpl
