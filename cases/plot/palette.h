// lexel's one palette: the colours every figure, report and teaching program draws with, so a
// method has the same colour wherever it appears in a run.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

namespace lexel::plot {

struct Rgb {
    double r = 0.0, g = 0.0, b = 0.0;  // each in [0, 1]
};

// Tableau-like colours, reordered so the first methods avoid the camera's blue and the light's
// yellow; twelve so that all eleven flatland methods get their own. Later ones reuse them.
inline constexpr std::array<Rgb, 12> kPalette = {{{0.84, 0.15, 0.16},
                                                  {0.17, 0.63, 0.17},
                                                  {0.58, 0.40, 0.74},
                                                  {1.00, 0.50, 0.05},
                                                  {0.09, 0.75, 0.81},
                                                  {0.89, 0.47, 0.76},
                                                  {0.55, 0.34, 0.29},
                                                  {0.74, 0.74, 0.13},
                                                  {0.12, 0.47, 0.71},
                                                  {0.50, 0.50, 0.50},
                                                  {0.00, 0.45, 0.45},
                                                  {0.55, 0.00, 0.35}}};

// The colour of the index-th method or series (repeating after twelve).
inline Rgb PaletteColour(std::size_t index) { return kPalette[index % kPalette.size()]; }

// amount < 0 darkens toward black, > 0 lightens toward white.
inline Rgb Shade(Rgb c, double amount) {
    const double target = amount < 0 ? 0.0 : 1.0, t = std::abs(amount);
    return {c.r + (target - c.r) * t, c.g + (target - c.g) * t, c.b + (target - c.b) * t};
}

// A sequential scale for t in [0, 1] (clamped; not finite: 1): dark purple → teal → yellow.
inline Rgb HeatColour(double t) {
    t = std::clamp(std::isfinite(t) ? t : 1.0, 0.0, 1.0);
    const Rgb lo{0.27, 0.00, 0.33}, mid{0.13, 0.57, 0.55}, hi{0.99, 0.91, 0.14};
    const auto mix = [](Rgb a, Rgb b, double s) {
        return Rgb{a.r + (b.r - a.r) * s, a.g + (b.g - a.g) * s, a.b + (b.b - a.b) * s};
    };
    return t < 0.5 ? mix(lo, mid, 2 * t) : mix(mid, hi, 2 * t - 1);
}

}  // namespace lexel::plot
