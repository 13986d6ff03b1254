#include "engine/scene/mitsuba/ior_tables.h"

#include <array>
#include <string_view>

namespace mvpl::scene::mitsuba {

namespace {

struct NamedConductor {
    std::string_view name;
    ComplexIor ior;
};

// RGB values of the spectral (η, k) tables Mitsuba ships (measured data of Palik's handbook),
// as Tungsten's RGB renderer tabulates them (its ComplexIorData); metals Mitsuba names beyond
// these are refused with the list.
const std::array<NamedConductor, 6> kConductors = {{
    {"none", {Rgb(0.0f), Rgb(1.0f)}},
    {"Ag", {Rgb(0.155265f, 0.116723f, 0.138342f), Rgb(4.82835f, 3.12225f, 2.14696f)}},
    {"Al", {Rgb(1.65746f, 0.880369f, 0.521229f), Rgb(9.22387f, 6.26952f, 4.837f)}},
    {"Au", {Rgb(0.143119f, 0.374957f, 1.44248f), Rgb(3.98316f, 2.38572f, 1.60322f)}},
    {"Cr", {Rgb(4.36968f, 2.9167f, 1.6547f), Rgb(5.20643f, 4.23136f, 3.75495f)}},
    {"Cu", {Rgb(0.200438f, 0.924033f, 1.10221f), Rgb(3.91295f, 2.45285f, 2.14219f)}},
}};

struct NamedDielectric {
    std::string_view name;
    float ior;
};

// Mitsuba's documentation table (BSDF "dielectric", "Index of refraction values").
const std::array<NamedDielectric, 19> kDielectrics = {{
    {"vacuum", 1.0f},      {"helium", 1.00004f},         {"hydrogen", 1.00013f},
    {"air", 1.00028f},     {"carbon dioxide", 1.00045f}, {"water", 1.3330f},
    {"acetone", 1.36f},    {"ethanol", 1.361f},          {"carbon tetrachloride", 1.461f},
    {"glycerol", 1.4729f}, {"benzene", 1.501f},          {"silicone oil", 1.52045f},
    {"bromine", 1.661f},   {"water ice", 1.31f},         {"fused quartz", 1.458f},
    {"pyrex", 1.470f},     {"acrylic glass", 1.49f},     {"polypropylene", 1.49f},
    {"bk7", 1.5046f},
}};

const std::array<NamedDielectric, 5> kMoreDielectrics = {{
    {"sodium chloride", 1.544f},
    {"amber", 1.55f},
    {"pet", 1.5750f},
    {"diamond", 2.419f},
    {"glass", 1.5046f},
}};

}  // namespace

std::optional<ComplexIor> conductor_ior(const std::string& name) {
    for (const NamedConductor& c : kConductors) {
        if (c.name == name) return c.ior;
    }
    return std::nullopt;
}

std::string conductor_names() {
    std::string out;
    for (const NamedConductor& c : kConductors)
        out += (out.empty() ? "" : ", ") + std::string(c.name);
    return out;
}

std::optional<float> dielectric_ior(const std::string& name) {
    for (const NamedDielectric& d : kDielectrics) {
        if (d.name == name) return d.ior;
    }
    for (const NamedDielectric& d : kMoreDielectrics) {
        if (d.name == name) return d.ior;
    }
    return std::nullopt;
}

Rgb conductor_f0(const ComplexIor& ior, float outside) {
    Rgb f0;
    for (int c = 0; c < 3; ++c) {
        const float eta = ior.eta[c] / outside, k = ior.k[c] / outside;
        f0[c] = ((eta - 1.0f) * (eta - 1.0f) + k * k) / ((eta + 1.0f) * (eta + 1.0f) + k * k);
    }
    return f0;
}

}  // namespace mvpl::scene::mitsuba
