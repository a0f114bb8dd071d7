// Table 1 of Chong & Gortler's report from a sweep (`lexel sweep`): mean misclassified pixels over
// all lights and over each method's worst 10% (with at least kWorstRowsMinLights lights), as a
// percentage more than the reference method (`optimal` when it ran, else the first), with the
// report's published row beside ours (labelled: its counts are on its own scale); the methods'
// mean h and time; in text (within kTerminalColumns), Markdown, CSV, JSON (schemas in
// cases/README.md); the per-light CSV is sweep_lights_csv.h's.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "lexel/cases/load/published.h"
#include "lexel/cases/report/text_table.h"
#include "lexel/cases/run/cascade_study.h"
#include "lexel/cases/run/sweep.h"

namespace lexel::cases {

// The worst-10% rows need this many lights: below it 10% of the lights is one or two of them, and
// the rows repeat single lights.
inline constexpr std::size_t kWorstRowsMinLights = 20;

// The sweep's tables with their titles, explanations and notes, in print order: Table 1 as
// published and its summary (when report methods ran), the fair comparison, the equal-texel
// table. `terminal` leaves out the columns that do not fit kTerminalColumns.
std::vector<ReportSection> SweepSections(const SweepResult& result, const ReportTable1& report,
                                         bool terminal);

std::string SweepTable(const SweepResult& result, const ReportTable1& report);
std::string SweepMarkdown(const SweepResult& result, const ReportTable1& report);
std::string SweepCsv(const SweepResult& result, const ReportTable1& report);
// The columns of a summary row (JSON and CSV) as a Markdown table: cases/README.md's list.
std::string SweepColumnReference();
nlohmann::json SweepJson(const SweepResult& result);

// The cascade-count study: "method,k,mean_misclassified" rows (optimal's with k = 1), and its
// plot (misclassified pixels against k, optimal's single map as a dashed line).
std::string CascadeStudyCsv(const CascadeCountStudy& study);
void WriteCascadeStudyPlot(const std::string& pngPath, const CascadeCountStudy& study,
                           const SweepResult& sweep);

}  // namespace lexel::cases
