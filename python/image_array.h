#pragma once
// Images as numpy arrays: float32, height × width × 3 (R, G, B), row 0 at the top, as the EXR
// files mvpl writes and OpenImageIO and imageio read them.
#include <pybind11/numpy.h>

#include "engine/core/exr_file.h"
#include "engine/core/image.h"

namespace mvpl::python {

pybind11::array_t<float> to_array(const Image& image);
// An AOV as height × width × its channels (albedo, normal, position: 3; depth: 1).
pybind11::array_t<float> to_array(const ChannelImage& layer);
// An H×W×3 array (any real dtype, converted to float32) or the path of an EXR file; throws
// UsageError naming `what` for another shape, InputError for a file that cannot be read.
Image to_image(const pybind11::object& source, const char* what);

}  // namespace mvpl::python
