// The translation unit that builds the tests' precompiled GoogleTest header (tests/CMakeLists.txt);
// it holds no test.
#include <gtest/gtest.h>
