#!/usr/bin/env python3
"""Prints the rows of kConductors (engine/scene/mitsuba/ior_tables.cpp): each measured conductor
that Mitsuba names, its complex index of refraction (η, k) as linear Rec.709 RGB.

Input: the folder of Mitsuba's measured spectra, NAME.eta.spd and NAME.k.spd (data/ior in
Mitsuba 0.6's source tree, the same files as pbrt-v2's scenes/spds/metals: the Luxpop database's
Palik and CXRO/LLNL measurements), one "wavelength_nm value" pair a line, '#' comments.

Each spectrum s(λ), linear between its samples and zero outside them, is projected onto the CIE
1931 2° observer (tools/data/cie_xyz_1931_2deg.csv, linear between its 1 nm samples) over the
observer's 360–830 nm, normalised by ∫ȳ so that a flat spectrum 1 has Y = 1:

    X = ∫ s x̄ dλ / ∫ ȳ dλ   (likewise Y, Z)

then taken to linear Rec.709 RGB with the XYZ→RGB matrix of ITU-R BT.709 (D65 white, no
chromatic adaptation). This is how an RGB build of Mitsuba 0.6 turns the .spd files into RGB
(and what Tungsten's table holds); the integrals here are exact for the piecewise-linear product
(Simpson's rule on each interval between the two functions' breakpoints). A channel that comes
out negative (the matrix on a spectrum outside the RGB gamut, e.g. AlSb's η in red) is set to 0.

    python3 tools/conductor_ior_rgb.py PATH/TO/mitsuba/data/ior
"""
import glob
import os
import sys

CMF = os.path.join(os.path.dirname(os.path.abspath(__file__)), "data", "cie_xyz_1931_2deg.csv")

# ITU-R BT.709 linear RGB from CIE XYZ.
XYZ_TO_RGB = ((3.240479, -1.537150, -0.498535),
              (-0.969256, 1.875991, 0.041556),
              (0.055648, -0.204043, 1.057311))


def read_columns(path, separator=None):
    rows = []
    for line in open(path, encoding="utf-8"):
        line = line.strip()
        if not line or line.startswith("#"):
            continue
        fields = line.split(separator)
        try:
            rows.append([float(f) for f in fields])
        except ValueError:
            continue  # a header
    return rows


def lerp_at(xs, ys, x):
    """The piecewise-linear function through (xs, ys) at x; zero outside [xs[0], xs[-1]]."""
    if x < xs[0] or x > xs[-1]:
        return 0.0
    lo, hi = 0, len(xs) - 1
    while hi - lo > 1:
        mid = (lo + hi) // 2
        if xs[mid] <= x:
            lo = mid
        else:
            hi = mid
    if xs[hi] == xs[lo]:
        return ys[lo]
    t = (x - xs[lo]) / (xs[hi] - xs[lo])
    return ys[lo] + t * (ys[hi] - ys[lo])


def integral(f, a, b, breakpoints):
    """∫_a^b f for f quadratic between consecutive breakpoints (Simpson's rule is then exact)."""
    points = sorted({a, b} | {p for p in breakpoints if a < p < b})
    total = 0.0
    for u, v in zip(points, points[1:]):
        total += (v - u) / 6.0 * (f(u) + 4.0 * f(0.5 * (u + v)) + f(v))
    return total


def float_literal(v):
    text = "%.6g" % v
    return text + (".0f" if "." not in text and "e" not in text else "f")


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    cmf = read_columns(CMF, ",")
    lam = [r[0] for r in cmf]
    bars = [[r[i] for r in cmf] for i in (1, 2, 3)]
    a, b = lam[0], lam[-1]
    y_norm = integral(lambda l: lerp_at(lam, bars[1], l), a, b, lam)

    def rgb(path):
        spd = read_columns(path)
        xs, ys = [r[0] for r in spd], [r[1] for r in spd]
        xyz = [integral(lambda l, bar=bar: lerp_at(xs, ys, l) * lerp_at(lam, bar, l), a, b,
                        lam + xs) / y_norm for bar in bars]
        return [max(0.0, sum(m * c for m, c in zip(row, xyz))) for row in XYZ_TO_RGB]

    names = sorted(os.path.basename(p)[:-len(".eta.spd")]
                   for p in glob.glob(os.path.join(sys.argv[1], "*.eta.spd")))
    for name in names:
        eta = rgb(os.path.join(sys.argv[1], name + ".eta.spd"))
        k = rgb(os.path.join(sys.argv[1], name + ".k.spd"))
        row = ", ".join("Rgb(" + ", ".join(float_literal(v) for v in c) + ")" for c in (eta, k))
        print('{"%s", {%s}},' % (name, row))


if __name__ == "__main__":
    main()
