// Output formats of `lexel run` for flatland cases: an aligned terminal table, one JSON document
// (schema in cases/README.md) and CSV.
#pragma once

#include <nlohmann/json.hpp>
#include <span>
#include <string>

#include "lexel/flatland/methods.h"

namespace lexel::cases {

nlohmann::json CaseReportJson(const flatland::CaseReport& report);
// One case: {"case": ..., "methods": [...]}; several: {"cases": [ ...those objects... ]}.
nlohmann::json RunJson(std::span<const flatland::CaseReport> reports);
std::string RunCsv(std::span<const flatland::CaseReport> reports);
std::string CaseTable(const flatland::CaseReport& report);
std::string CaseMarkdown(const flatland::CaseReport& report);

// Writes `content` to `path` through a temporary file and a rename, so a failed run never
// leaves a partial file. Throws std::runtime_error on I/O failure.
void WriteFileAtomically(const std::string& path, const std::string& content);

// A small aligned-text table used by every terminal report.
class TextTable {
  public:
    explicit TextTable(std::vector<std::string> header) : rows_{std::move(header)} {}
    void AddRow(std::vector<std::string> row) { rows_.push_back(std::move(row)); }
    std::string Render() const;          // first column left-aligned, the rest right-aligned
    std::string RenderMarkdown() const;  // GitHub table
  private:
    std::vector<std::vector<std::string>> rows_;
};

std::string Fixed(double value, int digits);  // "%.{digits}f", or "inf"
std::string Significant(double value, int digits = 4);

}  // namespace lexel::cases
