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
