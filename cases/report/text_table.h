// Aligned text, Markdown and HTML tables and number formatting for every report.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace lexel::cases {

// The width every terminal table and line of text is kept within: full detail stays in
// the CSV and JSON outputs.
inline constexpr std::size_t kTerminalColumns = 120;

// A table of cells, the first row its header. A header cell may hold '\n': the terminal stacks its
// lines (bottom-aligned) so that a long name does not widen a column of short numbers; Markdown
// joins them with spaces, HTML with line breaks.
class TextTable {
  public:
    explicit TextTable(std::vector<std::string> header) : rows_{std::move(header)} {}
    // `htmlClass`: the row's class in RenderHtml (e.g. "published"); the other formats ignore it.
    void AddRow(std::vector<std::string> row, std::string htmlClass = "") {
        rows_.push_back(std::move(row));
        classes_.push_back(std::move(htmlClass));
    }
    // First column left-aligned, the rest right-aligned, a rule under the header; widths count
    // UTF-8 code points, so "σ" takes one column. A table wider than `maxColumns` is cut into
    // blocks of whole columns, one under the other, each repeating the first column, so every
    // line fits (unless the first column and one other alone are wider).
    std::string Render(std::size_t maxColumns = kTerminalColumns) const;
    std::string RenderMarkdown() const;  // GitHub table
    // <table class="..."> with a <thead>; cells escaped (HtmlText); every column but the first
    // has the class "num" (right-aligned, as in the terminal).
    std::string RenderHtml(std::string_view cssClass = "") const;

  private:
    std::string RenderColumns(const std::vector<std::size_t>& columns) const;
    std::vector<std::vector<std::string>> rows_;
    std::vector<std::string> classes_ = {""};  // per row, the header's first
};

// A table with its title, a sentence or two saying what it shows, and notes under it: one unit of
// a report, rendered for the terminal (SectionsText), Markdown and HTML alike.
struct ReportSection {
    std::string title;
    std::string explanation;  // Markdown and HTML only: the terminal keeps to title and notes
    TextTable table;
    std::vector<std::string> notes;
};
// Title, table and notes per section, wrapped to kTerminalColumns, a blank line between sections.
std::string SectionsText(const std::vector<ReportSection>& sections);
// "## title", the explanation, the table and the notes per section.
std::string SectionsMarkdown(const std::vector<ReportSection>& sections);

// `text` cut at spaces into lines of at most `columns` display columns (a longer word stays
// whole), every line after the first led by `indent` (the first keeps the text's own leading
// spaces); each line ends in '\n'. A '\n' in the text is a hard break (an empty line stays).
std::string WrapText(std::string_view text, std::size_t columns = kTerminalColumns,
                     std::string_view indent = "");

// Terminal columns of a UTF-8 string: one per code point, none for combining marks.
std::size_t DisplayWidth(std::string_view text);

// An undefined quantity (NaN) prints as an empty string in every format: an empty CSV field, an
// empty table cell (JSON writes it as null); never "nan".
std::string Fixed(double value, int digits);            // "%.{digits}f"; "inf"; never "-0.000"
std::string Significant(double value, int digits = 4);  // "%.{digits}g"; "inf"
// A CSV field for `value`: the shortest decimal that reads back as the same double
// (std::to_chars), so 0.938 prints as 0.938, never 0.93800000000000006; -0 prints as 0; empty
// for NaN. Infinity prints as inf / -inf (read back as such by spreadsheets, pandas and numpy);
// JSON has no infinity and writes it as null.
std::string CsvNumber(double value);
// A CSV field for `text` (RFC 4180): quoted, with '"' doubled, when it holds ',', '"', CR or LF.
std::string CsvText(std::string_view text);
// A Markdown link destination for a file name: every byte outside [A-Za-z0-9._~-] percent-encoded
// (a name with spaces or parentheses would end the link). Also a valid relative URL in HTML.
std::string MarkdownLinkTarget(std::string_view fileName);
// Text for HTML element content and attribute values: & < > " ' escaped.
std::string HtmlText(std::string_view text);

}  // namespace lexel::cases
