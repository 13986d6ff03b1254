#pragma once
// The guard that keeps a non-finite value from ever being written silently: a NaN or an infinity
// in an image is a bug upstream (a zero pdf, an overflowing power), and an output that looks
// plausible except for a few black or white pixels hides it. Renders are checked before they are
// returned; a failure names how many pixels and where the first one is.
#include <cstddef>
#include <stdexcept>
#include <string>

#include "engine/core/image.h"

namespace mvpl {

struct NonFiniteReport {
    size_t pixels = 0;  // pixels with at least one non-finite channel
    int first_x = -1;   // the first of them in row-major order (row 0 at the top)
    int first_y = -1;
};

NonFiniteReport find_non_finite(const Image& image);

// An internal failure (exit code 1), not bad input.
class NonFiniteError : public std::runtime_error {
public:
    explicit NonFiniteError(const std::string& what) : std::runtime_error(what) {}
};

// Throws NonFiniteError "<what>: N non-finite pixel(s), the first at (x, y) = (r, g, b)" when the
// image has any.
void require_finite(const Image& image, const std::string& what);

// read_exr for an image measured against another (compare, convergence --ref): an error of NaN
// tells nothing, so a file holding non-finite pixels is bad input, InputError "PATH: holds N
// non-finite pixel(s), the first at …".
Image read_finite_exr(const std::string& path);

}  // namespace mvpl
