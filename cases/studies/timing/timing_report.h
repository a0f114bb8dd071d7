// `lexel timing`: per frame the pass times of focused and optimal (frame_pipeline.h), their means
// and the frame-time ratio optimal/focused, with the report's Tables 2–3 beside ours; as terminal
// text, one JSON document and CSV (schemas in README.md here).
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "lexel/cases/load/published.h"
#include "lexel/cases/studies/timing/timing_study.h"

namespace lexel::cases {

std::string TimingText(const spatial::Scene& scene, const TimingRun& run,
                       const ReportTiming& report);
nlohmann::json TimingJson(const spatial::Scene& scene, const TimingRun& run,
                          const ReportTiming& report);
// One row per method and frame, then one mean row per method.
std::string TimingCsv(const TimingRun& run);

}  // namespace lexel::cases
