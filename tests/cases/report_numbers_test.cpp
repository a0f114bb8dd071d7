// Undefined quantities are never printed as "nan": NaN is an empty CSV field and table
// cell (JSON: null, by nlohmann::json).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "lexel/cases/report/json_number.h"
#include "lexel/cases/report/text_table.h"
#include "lexel/cases/studies/thesis/lowres_report.h"

namespace lexel::cases {
namespace {

TEST(ReportNumbers, NanIsEmptyNeverNan) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_EQ(Fixed(nan, 3), "");
    EXPECT_EQ(Significant(nan, 9), "");
    EXPECT_EQ(CsvNumber(nan), "");
    EXPECT_EQ(CsvNumber(-nan), "");
    EXPECT_EQ(CsvNumber(0.1), "0.1");
    EXPECT_EQ(CsvNumber(2.5), "2.5");
    EXPECT_EQ(CsvNumber(std::numeric_limits<double>::infinity()), "inf");
    EXPECT_EQ(Fixed(1.23456, 3), "1.235");
}

TEST(ReportNumbers, LowresCsvLeavesAnUndecidableResolutionEmpty) {
    LowresRow undecidable;  // K pixels that see no geometry: no extra error defined
    undecidable.decisionPixels = 5;
    LowresRow measured;
    measured.decisionPixels = 10;
    measured.extraPercent[0] = 1.5;
    measured.extraPercent[1] = 2.5;
    measured.extraPercent[2] = 0.25;
    const std::string csv = LowresCsv({{"c", {undecidable, measured}}});
    EXPECT_EQ(csv,
              "case,decision_pixels,l1_extra_percent,l2_extra_percent,linf_extra_percent\n"
              "c,5,,,\n"
              "c,10,1.5,2.5,0.25\n");
}

// A case name is a file stem, so it may hold ',' and '"': CSV quotes such fields
// (RFC 4180) and Markdown links percent-encode the file name.
TEST(ReportNumbers, CsvQuotesNamesWithCommasAndQuotes) {
    EXPECT_EQ(CsvText("plain name"), "plain name");
    EXPECT_EQ(CsvText("a,b"), "\"a,b\"");
    EXPECT_EQ(CsvText("say \"hi\""), "\"say \"\"hi\"\"\"");
    EXPECT_EQ(CsvText(""), "");
    LowresRow row;
    row.decisionPixels = 4;
    row.extraPercent[0] = 1.0;
    row.extraPercent[1] = 2.0;
    row.extraPercent[2] = 3.0;
    EXPECT_EQ(LowresCsv({{"x,\"y\"", {row}}}),
              "case,decision_pixels,l1_extra_percent,l2_extra_percent,linf_extra_percent\n"
              "\"x,\"\"y\"\"\",4,1,2,3\n");
}

TEST(ReportNumbers, MarkdownLinksEncodeFileNames) {
    EXPECT_EQ(MarkdownLinkTarget("lowres_single_plane.png"), "lowres_single_plane.png");
    EXPECT_EQ(MarkdownLinkTarget("lowres_a b(1).png"), "lowres_a%20b%281%29.png");
    EXPECT_EQ(MarkdownLinkTarget("σ.png"), "%CF%83.png");
    const std::string markdown = LowresMarkdown("a b", {});
    EXPECT_NE(markdown.find("](lowres_a%20b.png)"), std::string::npos) << markdown;
}

}  // namespace
}  // namespace lexel::cases

TEST(JsonNumber, FiniteNumbersStayAndTheRestAreNull) {
    using lexel::cases::FiniteOrNull;
    EXPECT_EQ(FiniteOrNull(0.938).dump(), "0.938");
    EXPECT_EQ(FiniteOrNull(-0.0).dump(), "-0.0");
    EXPECT_EQ(FiniteOrNull(1e308).get<double>(), 1e308);
    EXPECT_TRUE(FiniteOrNull(std::numeric_limits<double>::infinity()).is_null());
    EXPECT_TRUE(FiniteOrNull(-std::numeric_limits<double>::infinity()).is_null());
    EXPECT_TRUE(FiniteOrNull(std::nan("")).is_null());
}
