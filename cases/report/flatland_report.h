// Output formats of `lexel run` for flatland cases: an aligned terminal table, one JSON document
// (schema in cases/README.md) and CSV.
#pragma once

#include <nlohmann/json.hpp>
#include <span>
#include <string>

#include "lexel/cases/report/text_table.h"
#include "lexel/flatland/methods.h"

namespace lexel::cases {

nlohmann::json CaseReportJson(const flatland::CaseReport& report);
// One case: {"case": ..., "methods": [...]}; several: {"cases": [ ...those objects... ]}.
nlohmann::json RunJson(std::span<const flatland::CaseReport> reports);
std::string RunCsv(std::span<const flatland::CaseReport> reports);
std::string CaseTable(const flatland::CaseReport& report);
std::string CaseMarkdown(const flatland::CaseReport& report);
// The pieces of CaseTable: "<case>: N of M pixels visible, ..." and the methods' table.
std::string CaseHeader(const flatland::CaseReport& report);
TextTable CaseMethodTable(const flatland::CaseReport& report);

}  // namespace lexel::cases
