#pragma once
// A Mitsuba spectrum given as wavelength:value pairs ("400:0.343, 404:0.445, …") as linear
// Rec.709 RGB, for an RGB renderer.
#include <pugixml.hpp>

#include <string>

#include "engine/core/color.h"

namespace mvpl::scene::mitsuba {

class Context;

// The piecewise-linear spectrum (zero outside its wavelengths, as Mitsuba's irregular spectrum)
// projected onto CIE 1931 XYZ, then to linear Rec.709, and divided by the RGB of the constant
// spectrum 1 so that a flat spectrum keeps its value in every channel (white stays white). The
// observer is the multi-lobe Gaussian fit of Wyman, Sloan & Shirley 2013 (JCGT 2(2)), within a
// few per cent of the tabulated CIE functions: a preview-accurate colour, not Mitsuba's own
// spectral rendering. Fails at `at` on a malformed pair or a wavelength out of order.
Rgb spectrum_to_rgb(const Context& ctx, pugi::xml_node at, const std::string& text);

}  // namespace mvpl::scene::mitsuba
