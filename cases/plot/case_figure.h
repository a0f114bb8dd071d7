// The flatland case figure (Cairo, PNG): the diagram (geometry, camera frustum, light, each
// method's lexel plane and a fan of lexel rays — every Nth lexel — hitting the geometry; split
// methods draw each frustum in its own colour) beside the footprint plot (f across the visible
// pixels for every method, log-scale y, labelled axes and a legend).
#pragma once

#include <string>

#include "lexel/flatland/methods.h"

namespace lexel::cases {

// Diagram (left) and footprint plot (right) of one case in one PNG. `report.fullPass` and each
// method's wsAxis/footprints/frusta must be filled (RunFlatlandCase with keepFootprints does;
// std::invalid_argument otherwise). Throws std::runtime_error when the file cannot be written.
void WriteCaseFigure(const std::string& pngPath, const flatland::FlatScene& scene,
                     const flatland::CaseReport& report);

}  // namespace lexel::cases
