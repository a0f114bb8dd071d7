// Aligned text and Markdown tables and number formatting for every report.
#pragma once

#include <string>
#include <vector>

namespace lexel::cases {

// A table of cells, the first row its header.
class TextTable {
  public:
    explicit TextTable(std::vector<std::string> header) : rows_{std::move(header)} {}
    void AddRow(std::vector<std::string> row) { rows_.push_back(std::move(row)); }
    // First column left-aligned, the rest right-aligned, a rule under the header; widths count
    // UTF-8 code points, so "σ" takes one column.
    std::string Render() const;
    std::string RenderMarkdown() const;  // GitHub table

  private:
    std::vector<std::vector<std::string>> rows_;
};

// An undefined quantity (NaN) prints as an empty string in every format: an empty CSV field, an
// empty table cell (JSON writes it as null); never "nan".
std::string Fixed(double value, int digits);            // "%.{digits}f"; "inf"; never "-0.000"
std::string Significant(double value, int digits = 4);  // "%.{digits}g"; "inf"
// A CSV field for `value` as std::ostream writes it at this precision; empty for NaN.
std::string CsvNumber(double value, int precision = 6);

}  // namespace lexel::cases
