// Undefined quantities are never printed as "nan" (issue 16): NaN is an empty CSV field and table
// cell (JSON: null, by nlohmann::json).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "lexel/cases/report/lowres_report.h"
#include "lexel/cases/report/text_table.h"

namespace lexel::cases {
namespace {

TEST(ReportNumbers, NanIsEmptyNeverNan) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_EQ(Fixed(nan, 3), "");
    EXPECT_EQ(Significant(nan, 9), "");
    EXPECT_EQ(CsvNumber(nan), "");
    EXPECT_EQ(CsvNumber(-nan, 17), "");
    EXPECT_EQ(CsvNumber(0.1, 17), "0.10000000000000001");
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

}  // namespace
}  // namespace lexel::cases
