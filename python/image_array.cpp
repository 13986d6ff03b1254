#include "python/image_array.h"

#include <algorithm>
#include <cstring>
#include <string>

#include "engine/core/error.h"
#include "engine/core/finite_check.h"

namespace py = pybind11;

namespace mvpl::python {

py::array_t<float> to_array(const Image& image) {
    py::array_t<float> array(
        {py::ssize_t(image.height()), py::ssize_t(image.width()), py::ssize_t(3)});
    static_assert(sizeof(Rgb) == 3 * sizeof(float));
    std::memcpy(array.mutable_data(), image.pixels().data(), image.pixels().size() * sizeof(Rgb));
    return array;
}

py::array_t<float> to_array(const ChannelImage& layer) {
    py::array_t<float> array(
        {py::ssize_t(layer.height), py::ssize_t(layer.width), py::ssize_t(layer.channels.size())});
    std::memcpy(array.mutable_data(), layer.values.data(), layer.values.size() * sizeof(float));
    return array;
}

Image to_image(const py::object& source, const char* what) {
    if (py::isinstance<py::str>(source)) return read_finite_exr(source.cast<std::string>());
    const auto array =
        py::array_t<float, py::array::c_style | py::array::forcecast>::ensure(source);
    if (!array || array.ndim() != 3 || array.shape(2) != 3 || array.shape(0) < 1 ||
        array.shape(1) < 1)
        throw UsageError(std::string("compare: ") + what +
                         " must be an EXR path or a height x width x 3 array");
    Image image(int(array.shape(1)), int(array.shape(0)));
    std::memcpy(image.pixels().data(), array.data(), image.pixels().size() * sizeof(Rgb));
    return image;
}

}  // namespace mvpl::python
