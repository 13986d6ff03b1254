#pragma once
// The image size every estimate starts from when none is given (`mvpl render`'s --res): one
// value for the GPU renderer, the oracle, the path tracer and the CPU estimators, whose option
// structs all begin with it.
#include <cstdint>

namespace mvpl {

inline constexpr uint32_t kDefaultImageWidth = 256;
inline constexpr uint32_t kDefaultImageHeight = 256;
// The side of the image throughput is measured and previewed at when none is given (`mvpl bench
// --res`, the preview's first window): 512², the size docs/results.md quotes VPL/s at.
inline constexpr int kThroughputImageSide = 512;

}  // namespace mvpl
