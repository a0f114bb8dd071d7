// Aligned text and Markdown tables and number formatting for every report.
#pragma once

#include <string>
#include <string_view>
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
// A CSV field for `value` as std::ostream writes it at this precision; empty for NaN. Infinity
// prints as inf / -inf (read back as such by spreadsheets, pandas and numpy); JSON has no
// infinity and writes it as null.
std::string CsvNumber(double value, int precision = 6);
// A CSV field for `text` (RFC 4180): quoted, with '"' doubled, when it holds ',', '"', CR or LF.
std::string CsvText(std::string_view text);
// A Markdown link destination for a file name: every byte outside [A-Za-z0-9._~-] percent-encoded
// (a name with spaces or parentheses would end the link).
std::string MarkdownLinkTarget(std::string_view fileName);

}  // namespace lexel::cases
