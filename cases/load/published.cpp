#include "lexel/cases/load/published.h"

#include <algorithm>

#include "lexel/cases/load/json_reader.h"
#include "lexel/flatland/methods.h"
#include "lexel/solvers/errors.h"

namespace lexel::cases {

const ThesisRow* ThesisTable::RowFor(const std::string& method) const {
    for (const ThesisRow& row : rows)
        if (std::find(row.methods.begin(), row.methods.end(), method) != row.methods.end())
            return &row;
    return nullptr;
}

namespace {

ThesisRow ReadThesisRow(const JsonField& row) {
    row.ExpectObject({"label", "methods", "angle", "worst", "average", "mean_plus_sigma"},
                     {"two_frusta_mean"});
    ThesisRow out;
    out.label = row["label"].String();
    for (const JsonField& m : row["methods"].Array(1)) {
        out.methods.push_back(m.String());
        if (!flatland::IsFlatlandMethod(out.methods.back()))
            m.Fail("unknown method '" + out.methods.back() + "'");
    }
    out.angle = row["angle"].Number();
    out.worst = row["worst"].Positive();
    out.average = row["average"].Positive();
    out.meanPlusSigma = row["mean_plus_sigma"].Positive();
    if (row.Has("two_frusta_mean")) out.twoFrustaMean = row["two_frusta_mean"].Positive();
    return out;
}

std::vector<ThesisTable> ThesisTablesFromJson(const nlohmann::json& document) {
    const JsonField root(document, "");
    root.ExpectObject({"tables"}, {"source"});
    std::vector<ThesisTable> tables;
    for (const JsonField& table : root["tables"].Array(1)) {
        table.ExpectObject({"file", "title", "rows"});
        ThesisTable t{table["file"].String(), table["title"].String(), {}};
        // A name in the cases directory (fitted/<file> may stand in for it: `lexel tables`).
        if (t.file.empty() || t.file.find('/') != std::string::npos)
            table["file"].Fail("must be a file name in the cases directory, got '" + t.file + "'");
        for (const JsonField& row : table["rows"].Array(1)) t.rows.push_back(ReadThesisRow(row));
        tables.push_back(std::move(t));
    }
    return tables;
}

ReportTable1 ReportTable1FromJson(const nlohmann::json& document) {
    const JsonField root(document, "");
    root.ExpectObject({"methods", "rows"}, {"source"});
    ReportTable1 out;
    for (const JsonField& m : root["methods"].Array(1)) out.methods.push_back(m.String());
    for (const JsonField& row : root["rows"].Array(1)) {
        row.ExpectObject({"set", "misclassified", "percent_more"});
        ReportTable1::Row r{row["set"].String(), {}, {}};
        for (const JsonField& v : row["misclassified"].Array())
            r.misclassified.push_back(v.Number());
        for (const JsonField& v : row["percent_more"].Array()) r.percentMore.push_back(v.Number());
        if (r.misclassified.size() != out.methods.size())
            row["misclassified"].Fail("must have one value per method (" +
                                      std::to_string(out.methods.size()) + ")");
        if (r.percentMore.size() != out.methods.size())
            row["percent_more"].Fail("must have one value per method (" +
                                     std::to_string(out.methods.size()) + ")");
        out.rows.push_back(std::move(r));
    }
    return out;
}

// One row of methods' values: as many as there are methods.
std::vector<double> ValuesPerMethod(const JsonField& array, std::size_t methods) {
    std::vector<double> out;
    for (const JsonField& v : array.Array()) out.push_back(v.Number());
    if (out.size() != methods)
        array.Fail("must have one value per method (" + std::to_string(methods) + ")");
    return out;
}

ReportTiming ReportTimingFromJson(const nlohmann::json& document) {
    const JsonField root(document, "");
    root.ExpectObject({"table2", "table3"}, {"source"});
    ReportTiming out;
    const JsonField t2 = root["table2"];
    t2.ExpectObject({"screen", "methods", "rows"});
    out.table2Screen = static_cast<int>(t2["screen"].Integer(1, 1 << 20));
    for (const JsonField& m : t2["methods"].Array(1)) out.table2Methods.push_back(m.String());
    for (const JsonField& row : t2["rows"].Array(1)) {
        row.ExpectObject({"lights", "map", "fps"});
        out.table2.push_back({static_cast<int>(row["lights"].Integer(1, 1000)),
                              static_cast<int>(row["map"].Integer(1, 1 << 20)),
                              ValuesPerMethod(row["fps"], out.table2Methods.size())});
    }
    const JsonField t3 = root["table3"];
    t3.ExpectObject({"lights", "map", "methods", "rows"});
    out.table3Lights = static_cast<int>(t3["lights"].Integer(1, 1000));
    out.table3MapSide = static_cast<int>(t3["map"].Integer(1, 1 << 20));
    for (const JsonField& m : t3["methods"].Array(1)) out.table3Methods.push_back(m.String());
    for (const JsonField& row : t3["rows"].Array(1)) {
        row.ExpectObject({"stage", "ms", "percent"});
        out.table3.push_back({row["stage"].String(),
                              ValuesPerMethod(row["ms"], out.table3Methods.size()),
                              ValuesPerMethod(row["percent"], out.table3Methods.size())});
    }
    return out;
}

template <class Result>
Result ReadPublished(const std::filesystem::path& file, Result (*fromJson)(const nlohmann::json&)) {
    const nlohmann::json document = ParseJsonFile(file);
    try {
        return fromJson(document);
    } catch (const InputError& e) {
        throw InputError(file.string() + ": " + e.what());
    }
}

}  // namespace

std::vector<ThesisTable> LoadThesisTables(const std::filesystem::path& file) {
    return ReadPublished(file, &ThesisTablesFromJson);
}

const ReportTable1::Row* ReportTable1::Find(const std::string& set) const {
    for (const Row& row : rows)
        if (row.set == set) return &row;
    return nullptr;
}

std::optional<std::size_t> ReportTable1::Column(const std::string& method) const {
    const auto it = std::find(methods.begin(), methods.end(), method);
    if (it == methods.end()) return std::nullopt;
    return static_cast<std::size_t>(it - methods.begin());
}

ReportTable1 LoadReportTable1(const std::filesystem::path& file) {
    return ReadPublished(file, &ReportTable1FromJson);
}

}  // namespace lexel::cases

namespace lexel::cases {

std::optional<double> ReportTiming::Table3Ms(const std::string& stage,
                                             const std::string& method) const {
    const auto column = std::find(table3Methods.begin(), table3Methods.end(), method);
    if (column == table3Methods.end()) return std::nullopt;
    for (const StageRow& row : table3)
        if (row.stage == stage)
            return row.ms[static_cast<std::size_t>(column - table3Methods.begin())];
    return std::nullopt;
}

std::vector<std::pair<int, double>> ReportTiming::Table2Ratios(int lights) const {
    const auto optimal = std::find(table2Methods.begin(), table2Methods.end(), "optimal");
    const auto focused = std::find(table2Methods.begin(), table2Methods.end(), "focused");
    std::vector<std::pair<int, double>> out;
    if (optimal == table2Methods.end() || focused == table2Methods.end()) return out;
    for (const FpsRow& row : table2)
        if (row.lights == lights)
            out.emplace_back(
                row.mapSide,
                row.fps[static_cast<std::size_t>(focused - table2Methods.begin())] /
                    row.fps[static_cast<std::size_t>(optimal - table2Methods.begin())]);
    return out;
}

ReportTiming LoadReportTiming(const std::filesystem::path& file) {
    return ReadPublished(file, &ReportTimingFromJson);
}

}  // namespace lexel::cases
