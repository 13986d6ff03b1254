#include "engine/core/version.h"

namespace mvpl {

const char* version() {
    return MVPL_VERSION;  // engine/core/CMakeLists.txt, from PROJECT_VERSION
}

}  // namespace mvpl
