// The column tables (cases/report/columns.h): one table of key, unit and getter per kind of result
// row writes the JSON objects, the CSV header and rows and the text columns; the CSV headers the
// reports write are the ones cases/README.md documents, and cases/COLUMNS.md lists every column.
#include "lexel/cases/report/columns.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

#include "lexel/cases/report/spatial_report.h"
#include "lexel/cases/report/sweep_report.h"
#include "lexel/cases/studies/storage/storage_report.h"

namespace lexel::cases {
namespace {

struct Sample {
    std::string name;
    std::int64_t count = 0;
    double value = 0.0;
};

const ColumnTable<Sample>& SampleColumns() {
    static const ColumnTable<Sample> table = {
        {"name", "", [](const Sample& s) { return CellValue(s.name); }},
        {"count", "pixels", [](const Sample& s) { return CellValue(s.count); }, kCsvColumn},
        {"value", "ms", [](const Sample& s) { return CellValue(s.value); }},
        {"json_only", "", [](const Sample& s) { return CellValue(s.value * 2.0); }, kJsonColumn},
        {"absent", "", [](const Sample&) { return CellValue{}; }, kJsonColumn, JsonNull::kOmit},
        {"empty", "", [](const Sample&) { return CellValue{}; }}};
    return table;
}

TEST(Columns, CsvKeepsTableOrderAndSkipsJsonOnlyColumns) {
    EXPECT_EQ(CsvHeader(SampleColumns()), "name,count,value,empty");
    EXPECT_EQ(CsvRow(SampleColumns(), Sample{"a,b", 12, 0.1}), "\"a,b\",12,0.1,");
    EXPECT_EQ(CsvRow(SampleColumns(), Sample{"c", -3, std::numeric_limits<double>::infinity()}),
              "c,-3,inf,");
    EXPECT_EQ(CsvRow(SampleColumns(), Sample{"d", 0, std::nan("")}), "d,0,,");
}

TEST(Columns, JsonWritesNullForNothingAndNonFiniteNumbersOrLeavesTheKeyOut) {
    nlohmann::json object;
    AddJsonColumns(SampleColumns(), Sample{"a", 7, 2.5}, object);
    EXPECT_EQ(object.dump(), R"({"empty":null,"json_only":5.0,"name":"a","value":2.5})");
    nlohmann::json infinite;
    AddJsonColumns(SampleColumns(), Sample{"b", 0, -std::numeric_limits<double>::infinity()},
                   infinite);
    EXPECT_TRUE(infinite["value"].is_null());
    EXPECT_TRUE(infinite["json_only"].is_null());
    EXPECT_FALSE(infinite.contains("absent"));
    EXPECT_FALSE(infinite.contains("count"));
}

TEST(Columns, TextColumnsFormatTheTablesValues) {
    const std::vector<TextColumn<Sample>> text = {
        TextColumnOf(SampleColumns(), "name", "name"),
        TextColumnOf(SampleColumns(), "count", "count"),
        TextColumnOf(SampleColumns(), "value", "value", FixedText(3)),
        TextColumnOf(SampleColumns(), "json_only", "twice", SignificantText(2))};
    EXPECT_EQ(text[1].cell(Sample{"a", 123456789, 0.0}), "123456789");
    EXPECT_EQ(text[2].cell(Sample{"a", 0, 1.0 / 3.0}), "0.333");
    EXPECT_EQ(text[3].cell(Sample{"a", 0, 1.0 / 3.0}), "0.67");
    EXPECT_EQ(TextColumnOf(SampleColumns(), "value", "v").cell(Sample{"a", 0, 1.0 / 3.0}),
              "0.3333");
    EXPECT_EQ(TextColumnOf(SampleColumns(), "empty", "e").cell(Sample{}), "");
    EXPECT_THROW(TextColumnOf(SampleColumns(), "no_such_key", "x"), std::invalid_argument);
    const std::string rendered =
        TextTableOf(text, {Sample{"first", 1, 2.0}, Sample{"second", 30, 4.5}}).RenderMarkdown();
    EXPECT_NE(rendered.find("| name | count | value | twice |"), std::string::npos) << rendered;
    EXPECT_NE(rendered.find("| second | 30 | 4.500 | 9 |"), std::string::npos) << rendered;
}

TEST(Columns, ReferenceListsEveryColumnWithItsUnitAndFormats) {
    const std::string reference = ColumnReference(SampleColumns());
    EXPECT_NE(reference.find("| `count` | pixels | CSV |"), std::string::npos) << reference;
    EXPECT_NE(reference.find("| `value` | ms | JSON, CSV |"), std::string::npos) << reference;
    EXPECT_NE(reference.find("| `json_only` | – | JSON |"), std::string::npos) << reference;
}

std::string ReadFile(const std::string& path) {
    std::ifstream in(path);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// The first line of a report's CSV: its header.
std::string HeaderOf(const std::string& csv) { return csv.substr(0, csv.find('\n')); }

TEST(Columns, TheCsvHeadersAreTheOnesTheReferencesDocument) {
    const std::string readme = ReadFile(LEXEL_CASES_DIR "/README.md");
    const std::string storage = ReadFile(LEXEL_CASES_DIR "/studies/storage/README.md");
    ASSERT_FALSE(readme.empty());
    ASSERT_FALSE(storage.empty());
    for (const std::string& header :
         {HeaderOf(SpatialRunCsv(SpatialRun{})), HeaderOf(SweepCsv(SweepResult{}, ReportTable1{}))})
        EXPECT_NE(readme.find("`" + header + "`"), std::string::npos)
            << "cases/README.md does not list the CSV header " << header;
    const std::string header = HeaderOf(CaseStorageCsv(CaseStorage{}));
    EXPECT_NE(storage.find("`" + header + "`"), std::string::npos)
        << "cases/studies/storage/README.md does not list the CSV header " << header;
}

// cases/COLUMNS.md holds each table's reference as the code makes it, so a column added, renamed
// or given another unit shows there.
TEST(Columns, TheCaseReferenceListsEveryResultColumn) {
    const std::string readme = ReadFile(LEXEL_CASES_DIR "/COLUMNS.md");
    ASSERT_FALSE(readme.empty());
    for (const std::string& reference :
         {SpatialRunColumnReference(), SweepColumnReference(), CaseStorageColumnReference()})
        EXPECT_NE(readme.find(reference), std::string::npos) << "cases/COLUMNS.md should hold:\n"
                                                             << reference;
}

}  // namespace
}  // namespace lexel::cases
