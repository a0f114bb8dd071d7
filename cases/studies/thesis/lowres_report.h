// The low-resolution decision study (`lexel lowres`, thesis §4.1.1): text, Markdown, CSV and the
// curves of its plot (cases/plot/curve_plot.h).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "lexel/cases/plot/curve_plot.h"
#include "lexel/cases/studies/thesis/lowres.h"

namespace lexel::cases {

std::string LowresText(const std::string& caseName, const std::vector<LowresRow>& rows);
// Links lowres_<case>.png.
std::string LowresMarkdown(const std::string& caseName, const std::vector<LowresRow>& rows);
// One CSV of several studies: (case name, rows).
std::string LowresCsv(const std::vector<std::pair<std::string, std::vector<LowresRow>>>& studies);
// The plot's curves: extra error (clamped at 0 for the log plot) against K, n/a rows left out.
std::vector<LowresCurve> LowresCurves(const std::vector<LowresRow>& rows);

}  // namespace lexel::cases
