#pragma once
// A VplSet's VPLs with its scale folded into each power (vpl.h): the per-VPL estimate that tests
// of the samplers' powers (I/(pick·N) and the like) compare against.
#include <vector>

#include "engine/light/vpl.h"

namespace mvpl::test {

inline std::vector<light::Vpl> with_scale_applied(const light::VplSet& set) {
    std::vector<light::Vpl> vpls = set.vpls;
    for (light::Vpl& v : vpls)
        v.power *= float(set.scale);
    return vpls;
}

}  // namespace mvpl::test
