// The flatland scene of the teaching programs 01–05 and 07 (Chong 2003's setting, §2): a camera
// 2 units above a floor looking 14° down, a point light up and behind it, 1000 pixels and 1000
// lexels. Not part of lexel's API.
#pragma once

#include <string>

#include "lexel/flatland/lexel_remap.h"
#include "lexel/flatland/scene.h"

namespace lexel::notebooks {

// The floor alone, or (withStep) the floor and a step with a ramp on it 6 units ahead.
flatland::FlatScene TeachingScene(bool withStep);
// The optimizer's samples of TeachingScene(true) from its full-resolution pass (1000 lexels).
flatland::LexelSamples TeachingSamples();

// One line of an angle program's initial → final: "<label> lexel plane θ°  <metric> = v  (note)".
void PrintAngle(const char* label, double wsAxis, const char* metric, double value,
                const std::string& note = "");

}  // namespace lexel::notebooks
