// The published tables lexel reproduces, read from the data files in cases/published/: the four
// tables of Chong 2003 ch. 4.1.3 (thesis_tables.json) and Table 1 of Chong & Gortler's report
// (report_table1.json). Reading is strict (json_reader.h); errors name the file and pointer.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace lexel::cases {

// One printed row of a thesis table. Angles in degrees, footprints in pixels.
struct ThesisRow {
    std::string label;                 // as printed: "Our Method (L1)", "Perspective SM", ...
    std::vector<std::string> methods;  // our methods the row stands for
    double angle = 0.0, worst = 0.0, average = 0.0, meanPlusSigma = 0.0;
    std::optional<double> twoFrustaMean;  // only "Projection Aliasing" prints it
};

struct ThesisTable {
    std::string file;   // the case file it belongs to (cases/flatland/<file>), a bare file name
    std::string title;  // the thesis's heading
    std::vector<ThesisRow> rows;
    // The row printed for `method`, or null.
    const ThesisRow* RowFor(const std::string& method) const;
};

// Every row's methods are flatland methods (flatland/methods.h).
std::vector<ThesisTable> LoadThesisTables(const std::filesystem::path& file);

// Table 1 of the report: per set of lights ("all", or a method's worst 10%), the misclassified
// pixels of each method and the percentages printed beside them.
struct ReportTable1 {
    struct Row {
        std::string set;
        std::vector<double> misclassified, percentMore;  // per method, in `methods` order
    };
    std::vector<std::string> methods;
    std::vector<Row> rows;
    const Row* Find(const std::string& set) const;  // null when the report has no such row
    // The index of `method` in `methods`, or nullopt.
    std::optional<std::size_t> Column(const std::string& method) const;
};

ReportTable1 LoadReportTable1(const std::filesystem::path& file);

// Tables 2 and 3 of the report (report_timing.json): frames per second per number of lights and
// shadow-map side (Table 2), and one frame's time profile for 4 lights (Table 3, milliseconds).
struct ReportTiming {
    struct FpsRow {
        int lights = 0, mapSide = 0;
        std::vector<double> fps;  // per method, in table2Methods order
    };
    struct StageRow {
        std::string stage;                // total, optimization, convex_hull, render_and_wait
        std::vector<double> ms, percent;  // per method, in table3Methods order
    };
    int table2Screen = 0;  // screen side, pixels
    std::vector<std::string> table2Methods;
    std::vector<FpsRow> table2;
    int table3Lights = 0, table3MapSide = 0;
    std::vector<std::string> table3Methods;
    std::vector<StageRow> table3;

    // Table 3's milliseconds of `stage` for `method`, or nullopt.
    std::optional<double> Table3Ms(const std::string& stage, const std::string& method) const;
    // Table 2's frame-time ratio optimal/focused (= fps focused / fps optimal) for `lights`
    // lights at each printed map side, as (side, ratio); empty for other light counts.
    std::vector<std::pair<int, double>> Table2Ratios(int lights) const;
};

ReportTiming LoadReportTiming(const std::filesystem::path& file);

}  // namespace lexel::cases
