// What a printed table implies under any geometry (Chong 2003, ch. 4.1.3 against the lexel
// remapping of §3.1): the Normal row and the L1 row, angles and averages, predict the average
// at every other lexel plane angle up to one unknown, the half sweep of the visible points.
//
// Inputs: lexel plane angles in degrees (any representative mod 180°), averages in pixels per
// lexel. Output: the half sweeps (degrees) for which some set of pixels is consistent with the
// two rows, the range of the average predicted at `otherDeg` over them, and how close to the
// sweep's edge the footprint-weighted light angles must sit (1 = all at the edge). `feasible` is
// false when no half sweep fits (e.g. the L1 row is not an optimum of any pixel set). Derivation
// in table_consistency.cpp.
#pragma once

namespace lexel::flatland {

struct SweepWindow {
    bool feasible = false;
    double halfSweepLoDeg = 0.0, halfSweepHiDeg = 0.0;
    double predictedLo = 0.0, predictedHi = 0.0;  // average at otherDeg, pixels per lexel
    double edgeConcentrationLo = 0.0, edgeConcentrationHi = 0.0;  // m1 / (m0 tan h)
};

// `steps` half sweeps are tried, evenly spaced in tan h over (0, 1/|tan(l1Deg − normalDeg)|).
SweepWindow PredictAverageFromRows(double normalDeg, double normalAverage, double l1Deg,
                                   double l1Average, double otherDeg, int steps = 20000);

}  // namespace lexel::flatland
