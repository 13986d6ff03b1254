#pragma once
// What the preview can show (V, the script's `view NAME`, the panel): the picture; the AOVs
// `render --aov` writes; the picture with its VPLs drawn over it; each pixel's relative standard
// error estimated from the variance between frames (frame_variance.h).
#include <algorithm>
#include <array>
#include <string>

namespace mvpl::preview {

inline constexpr std::array<const char*, 6> kViewNames{"image", "albedo", "normal",
                                                       "depth", "vpls",   "error"};

inline bool is_view_name(const std::string& name) {
    return std::find(kViewNames.begin(), kViewNames.end(), name) != kViewNames.end();
}

}  // namespace mvpl::preview
