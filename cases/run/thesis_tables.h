// `lexel tables`: the thesis's experiments (Chong 2003, ch. 4.1.3) rerun on the shipped
// reconstructions of its four flatland cases, each beside its published table.
#pragma once

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
    const flatland::MethodReport& Method(const std::string& name) const;
};

// Runs TableRows' methods (metric L1) on each table's case, found in `casesDir`. Throws
// InputError naming the case file for a case that cannot be read or run.
std::vector<TableResult> RunThesisTables(const std::vector<ThesisTable>& tables,
                                         const std::filesystem::path& casesDir);

}  // namespace lexel::cases
