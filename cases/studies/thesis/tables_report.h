// The thesis tables (`lexel tables`) beside the published numbers: terminal text, Markdown with
// the figures, CSV, and the low-resolution summary sentence.
#pragma once

#include <string>
#include <vector>

#include "lexel/cases/studies/thesis/lowres.h"
#include "lexel/cases/studies/thesis/thesis_tables.h"

namespace lexel::cases {

std::string TablesText(const std::vector<TableResult>& results);
// Links `<case>.png` (WriteCaseFigure) beside each table.
std::string TablesMarkdown(const std::vector<TableResult>& results);
std::string TablesCsv(const std::vector<TableResult>& results);
// Whether K = 10 decision pixels cost under 5% for L1 and L2, as the thesis reports for most
// scenes; lowres[i] is the study of results[i]'s case.
std::string LowresSummary(const std::vector<TableResult>& results,
                          const std::vector<std::vector<LowresRow>>& lowres);

}  // namespace lexel::cases
