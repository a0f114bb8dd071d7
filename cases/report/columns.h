// One column table per kind of result row (a method's outcome on a light, a method's summary over
// a sweep, a light of a sweep, a cascade): each column's key, unit and getter, written
// once, from which the JSON objects, the CSV header and rows and the text and Markdown tables are
// made. Adding a metric to every machine format is one line in the row's table
// (CONTRIBUTING.md, "Add a result column").
#pragma once

#include <cstdint>
#include <functional>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include "lexel/cases/report/text_table.h"

namespace lexel::cases {

// A cell: nothing (an empty CSV field, JSON null), a count, a number or a name.
using CellValue = std::variant<std::monostate, std::int64_t, double, std::string>;

// The formats a column appears in (a bit set). Text and Markdown tables pick their columns by key
// (TextColumnOf): the terminal's 120 columns hold fewer than a CSV row.
enum ColumnFormat : unsigned { kJsonColumn = 1u, kCsvColumn = 2u, kMachineColumns = 3u };

// What a JSON object does with a column whose cell is nothing.
enum class JsonNull { kWrite, kOmit };

template <class Row>
struct Column {
    std::string key;   // the JSON key and the CSV header
    std::string unit;  // of its numbers ("pixels", "ms", "texels/pixel", ...); "" for names
    std::function<CellValue(const Row&)> get;
    unsigned formats = kMachineColumns;
    JsonNull null = JsonNull::kWrite;
};

template <class Row>
using ColumnTable = std::vector<Column<Row>>;

// A CSV field: empty for nothing, CsvNumber for a number (shortest round trip, "inf"), CsvText
// for a name.
std::string CsvCell(const CellValue& value);
// A JSON value: null for nothing and for a NaN or infinite number (FiniteOrNull).
nlohmann::json JsonCell(const CellValue& value);
// The terminal's default rendering: a count in full, a number to 4 significant digits, "" for
// nothing.
std::string TextCell(const CellValue& value);

// The CSV header of `table`'s CSV columns, in table order, comma-separated, no line end.
template <class Row>
std::string CsvHeader(const ColumnTable<Row>& table) {
    std::string line;
    for (const Column<Row>& c : table)
        if (c.formats & kCsvColumn) line += (line.empty() ? "" : ",") + c.key;
    return line;
}

// `row`'s CSV fields in the header's order, no line end.
template <class Row>
std::string CsvRow(const ColumnTable<Row>& table, const Row& row) {
    std::string line;
    bool first = true;
    for (const Column<Row>& c : table) {
        if (!(c.formats & kCsvColumn)) continue;
        line += (first ? "" : ",") + CsvCell(c.get(row));
        first = false;
    }
    return line;
}

// Sets `row`'s JSON columns in `object` (a key whose cell is nothing: null, or left out).
template <class Row>
void AddJsonColumns(const ColumnTable<Row>& table, const Row& row, nlohmann::json& object) {
    for (const Column<Row>& c : table) {
        if (!(c.formats & kJsonColumn)) continue;
        const CellValue value = c.get(row);
        if (c.null == JsonNull::kOmit && std::holds_alternative<std::monostate>(value)) continue;
        object[c.key] = JsonCell(value);
    }
}

// A column of a text or Markdown table: its header (a '\n' stacks it, TextTable) and its cell.
template <class Row>
struct TextColumn {
    std::string header;
    std::function<std::string(const Row&)> cell;
};

// The text column showing `table`'s column `key` through `format` (TextCell by default). Throws
// std::invalid_argument when the table has no such key (a programming error; the report tests
// build every text table).
template <class Row>
TextColumn<Row> TextColumnOf(const ColumnTable<Row>& table, std::string_view key,
                             std::string header,
                             std::function<std::string(const CellValue&)> format = TextCell) {
    for (const Column<Row>& c : table)
        if (c.key == key)
            return {std::move(header), [get = c.get, format = std::move(format)](const Row& row) {
                        return format(get(row));
                    }};
    throw std::invalid_argument("TextColumnOf: no column '" + std::string(key) + "'");
}

// A text table of `rows` through `columns`.
template <class Row>
TextTable TextTableOf(const std::vector<TextColumn<Row>>& columns, const std::vector<Row>& rows) {
    std::vector<std::string> header;
    for (const TextColumn<Row>& c : columns) header.push_back(c.header);
    TextTable table(std::move(header));
    for (const Row& row : rows) {
        std::vector<std::string> cells;
        for (const TextColumn<Row>& c : columns) cells.push_back(c.cell(row));
        table.AddRow(std::move(cells));
    }
    return table;
}

// Text formats for TextColumnOf: a number to `digits` significant digits or decimals (a count
// in full, nothing as "").
std::function<std::string(const CellValue&)> SignificantText(int digits);
std::function<std::string(const CellValue&)> FixedText(int digits);

// The columns' reference as a Markdown table (key, unit or "–" for a name, formats): what
// cases/README.md lists and a test keeps in step with the code.
template <class Row>
std::string ColumnReference(const ColumnTable<Row>& table) {
    std::string out = "| column | unit | in |\n| --- | --- | --- |\n";
    for (const Column<Row>& c : table) {
        const std::string in = c.formats == kMachineColumns ? "JSON, CSV"
                               : c.formats & kJsonColumn    ? "JSON"
                                                            : "CSV";
        out += "| `" + c.key + "` | " + (c.unit.empty() ? "–" : c.unit) + " | " + in + " |\n";
    }
    return out;
}

}  // namespace lexel::cases
