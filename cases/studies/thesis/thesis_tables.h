// `lexel tables`: the thesis's experiments (Chong 2003, ch. 4.1.3) rerun on its four flatland
// cases (the shipped reconstructions, or the fitted scenes where they match better), each beside
// its published table.
#pragma once

#include <cmath>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "lexel/cases/load/published.h"
#include "lexel/flatland/methods.h"

namespace lexel::cases {

// The rows `lexel tables` prints for every case, in order: (label, method).
const std::vector<std::pair<std::string, std::string>>& TableRows();

struct TableResult {
    ThesisTable thesis;
    flatland::FlatScene scene;  // as loaded from the case file
    flatland::CaseReport report;
    std::string caseFile;              // the file used, relative to the cases directory
    bool fitted = false;               // true when fitted/<file> (lexel fit-thesis) replaced <file>
    double worstAngleErrorDeg = NAN;   // against the published table, max |ours − published|
    double worstFootprintError = NAN;  // max |ours / published − 1|
    const flatland::MethodReport& Method(const std::string& name) const;
};

// Runs TableRows' methods (metric L1) on each table's case, found in `casesDir`; fitted/<file>
// there replaces <file> when it exists and matches the published numbers better
// (ChooseThesisScene). Throws InputError naming the case file for a case that cannot be read or
// run.
std::vector<TableResult> RunThesisTables(const std::vector<ThesisTable>& tables,
                                         const std::filesystem::path& casesDir);

}  // namespace lexel::cases
