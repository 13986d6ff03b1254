#pragma once
// Image files as Mitsuba's `bitmap` texture and `envmap` read them: PNG, JPEG, BMP, TGA and
// Radiance HDR through stb_image, OpenEXR through engine/core/image.h. 8- and 16-bit images are
// sRGB-encoded unless `raw` (Mitsuba's default for colour bitmaps); HDR and EXR are linear.
#include <string>
#include <vector>

#include "engine/core/math.h"

namespace mvpl::scene::mitsuba {

struct Bitmap {
    int width = 0;
    int height = 0;
    std::vector<Vec4> texels;  // linear, row 0 at the top
};

// Throws InputError naming the file when it cannot be read or decoded, or holds more than 2^26
// texels or a non-finite texel.
Bitmap read_bitmap(const std::string& path, bool raw);

}  // namespace mvpl::scene::mitsuba
