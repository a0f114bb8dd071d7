#include "lexel/cases/studies/thesis/lowres_report.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "lexel/cases/report/text_table.h"

namespace lexel::cases {

namespace {
TextTable LowresTable(const std::vector<LowresRow>& rows) {
    TextTable table(
        {"decision pixels K", "L1 extra (average) %", "L2 extra (mean+σ) %", "L∞ extra (worst) %"});
    for (const auto& row : rows) {
        std::vector<std::string> cells = {std::to_string(row.decisionPixels)};
        for (double v : row.extraPercent) cells.push_back(std::isnan(v) ? "n/a" : Fixed(v, 3));
        table.AddRow(cells);
    }
    return table;
}
}  // namespace

std::vector<LowresCurve> LowresCurves(const std::vector<LowresRow>& rows) {
    std::vector<LowresCurve> curves = {
        {"L1 (average)", {}, {}}, {"L2 (mean+sigma)", {}, {}}, {"Linf (worst)", {}, {}}};
    for (const auto& row : rows)
        for (int m = 0; m < 3; ++m)
            if (!std::isnan(row.extraPercent[m])) {
                curves[m].pixels.push_back(row.decisionPixels);
                curves[m].extraPercent.push_back(std::max(0.0, row.extraPercent[m]));
            }
    return curves;
}

std::string LowresText(const std::string& caseName, const std::vector<LowresRow>& rows) {
    return "Low-resolution decision: " + caseName + "\n" + LowresTable(rows).Render();
}

std::string LowresMarkdown(const std::string& caseName, const std::vector<LowresRow>& rows) {
    return "### Low-resolution decision: " + caseName + "\n\n" +
           LowresTable(rows).RenderMarkdown() + "\n![lowres " + caseName + "](" +
           MarkdownLinkTarget("lowres_" + caseName + ".png") + ")\n\n";
}

std::string LowresCsv(const std::vector<std::pair<std::string, std::vector<LowresRow>>>& studies) {
    std::ostringstream out;
    out << "case,decision_pixels,l1_extra_percent,l2_extra_percent,linf_extra_percent\n";
    for (const auto& [name, rows] : studies)
        for (const auto& row : rows)
            out << CsvText(name) << ',' << row.decisionPixels << ','
                << CsvNumber(row.extraPercent[0]) << ',' << CsvNumber(row.extraPercent[1]) << ','
                << CsvNumber(row.extraPercent[2]) << '\n';
    return out.str();
}

}  // namespace lexel::cases
