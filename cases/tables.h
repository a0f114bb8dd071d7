// `lexel tables` and `lexel lowres`: the thesis's experiments (Chong 2003, ch. 4.1) rerun on the
// shipped reconstructions of its four flatland cases, with the published numbers beside ours.
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "lexel/flatland/methods.h"

namespace lexel::cases {

// One published row of the tables in ch. 4.1.3.
struct ThesisRow {
    std::string label;   // as printed: "Our Method (L1)", "Perspective SM", ...
    std::string method;  // our method name
    double angle, worst, average, meanPlusSigma;
    double twoFrustaMean = NAN;  // only "Projection Aliasing" prints it
};

struct ThesisCase {
    std::string file;   // cases/flatland/<file>
    std::string title;  // the thesis's heading
    std::vector<ThesisRow> rows;
};

const std::vector<ThesisCase>& ThesisCases();

// The rows `lexel tables` prints for every case, in order (label, method).
const std::vector<std::pair<std::string, std::string>>& TableRows();

struct TableResult {
    ThesisCase thesis;
    flatland::FlatScene scene;  // as loaded from the case file
    flatland::CaseReport report;
    const flatland::MethodReport& Method(const std::string& name) const;
};

// Runs the table rows on the four cases found in casesDir (default: the shipped ones).
std::vector<TableResult> RunThesisTables(const std::string& casesDir);

std::string TablesText(const std::vector<TableResult>& results);
std::string TablesMarkdown(const std::vector<TableResult>& results);
std::string TablesCsv(const std::vector<TableResult>& results);

// Thesis 4.1.1 / Fig. 4.1: additional error at full resolution of the angle chosen from K
// decision pixels, relative to the full-resolution optimum. Error is the thesis's: the average
// footprint for L1, mean + σ for L2; and the worst footprint for L∞.
struct LowresRow {
    int decisionPixels = 0;                    // K (the last row is the full resolution)
    double extraPercent[3] = {NAN, NAN, NAN};  // L1, L2, L∞; NaN when K pixels see nothing usable
};
std::vector<int> LowresResolutions(int fullPixels);  // 5, 10, 20, 50, 100, 200, full
std::vector<LowresRow> RunLowresStudy(const flatland::FlatScene& scene);
std::string LowresText(const std::string& caseName, const std::vector<LowresRow>& rows);
std::string LowresMarkdown(const std::string& caseName, const std::vector<LowresRow>& rows);

int RunTablesCommand(const std::string& outDir, const std::string& casesDir);
int RunLowresCommand(const std::string& casePath, const std::string& outDir);

}  // namespace lexel::cases
