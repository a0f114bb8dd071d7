// What a reader sees on a terminal: tables within 120 columns (cut into blocks of whole
// columns when wider, headers stacked over lines), wrapped captions, no worst-10% rows for a
// handful of lights, the report's published counts labelled as such, a progress line with an
// estimate, one line of --help per method, and CSV numbers in the shortest form that reads back
// as the same double.
#include <gtest/gtest.h>

#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <nlohmann/json.hpp>
#include <random>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "lexel/cases/report/progress_text.h"
#include "lexel/cases/report/sweep_report.h"
#include "lexel/cases/report/text_table.h"
#include "lexel/flatland/methods.h"
#include "lexel/spatial/harness/methods.h"

namespace lexel::cases {
namespace {

std::vector<std::string> LinesOf(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

// The widest line of `text` in display columns, and that line.
std::pair<std::size_t, std::string> Widest(const std::string& text) {
    std::pair<std::size_t, std::string> widest{0, ""};
    for (const std::string& line : LinesOf(text))
        if (DisplayWidth(line) > widest.first) widest = {DisplayWidth(line), line};
    return widest;
}

TEST(TextTable, StacksHeaderLinesBottomAligned) {
    TextTable table({"method", "mean\nmisclassified", "ms"});
    table.AddRow({"optimal", "12.5", "0.3"});
    EXPECT_EQ(table.Render(),
              "                  mean\n"
              "method   misclassified   ms\n"
              "---------------------------\n"
              "optimal           12.5  0.3\n");
    EXPECT_EQ(table.RenderMarkdown(),
              "| method | mean misclassified | ms |\n| --- | ---: | ---: |\n"
              "| optimal | 12.5 | 0.3 |\n");
}

TEST(TextTable, CutsAWideTableIntoBlocksOfWholeColumnsThatFit) {
    // 12 columns of 14: 12·14 + 11·2 = 190 columns on one line.
    std::vector<std::string> header = {"method"};
    for (int c = 1; c < 12; ++c) header.push_back("column " + std::to_string(c) + " (wide)");
    TextTable table(header);
    std::vector<std::string> row = {"optimal-refined"};
    const auto cellOf = [](int c) {
        return "value-" + std::string(c < 10 ? "0" : "") + std::to_string(c);
    };
    for (int c = 1; c < 12; ++c) row.push_back(cellOf(c));
    table.AddRow(row);
    const std::string text = table.Render(120);
    const auto [width, line] = Widest(text);
    EXPECT_LE(width, 120u) << line;
    EXPECT_GT(width, 60u) << text;  // two blocks, not one column each
    // Two blocks, each led by the method column, every cell printed once.
    std::size_t rows = 0;
    for (const std::string& l : LinesOf(text)) rows += l.starts_with("optimal-refined");
    EXPECT_EQ(rows, 2u) << text;
    for (int c = 1; c < 12; ++c) {
        const std::string cell = cellOf(c);
        const std::size_t at = text.find(" " + cell);
        EXPECT_NE(at, std::string::npos) << cell << "\n" << text;
        EXPECT_EQ(text.find(" " + cell, at + 1), std::string::npos) << cell << "\n" << text;
    }
    // A table that fits is one block.
    EXPECT_EQ(LinesOf(table.Render(1000)).size(), 3u);
}

TEST(TextTable, RendersEscapedHtml) {
    TextTable table({"method", "a < b\n& c"});
    table.AddRow({"<script>", "\"1\""});
    const std::string html = table.RenderHtml("summary");
    EXPECT_EQ(html,
              "<table class=\"summary\">\n<thead><tr><th>method</th><th class=\"num\">a &lt; "
              "b<br>&amp; c</th></tr></thead>\n<tbody>\n<tr><td>&lt;script&gt;</td><td "
              "class=\"num\">&quot;1&quot;</td></tr>\n</tbody>\n</table>\n");
}

TEST(TextTable, WrapsTextAtSpacesWithinTheWidth) {
    EXPECT_EQ(WrapText("one two three four", 9, "  "), "one two\n  three\n  four\n");
    EXPECT_EQ(WrapText("σσσσ σσσσ", 9), "σσσσ σσσσ\n");  // code points, not bytes
    EXPECT_EQ(WrapText("averyveryverylongword x", 5), "averyveryverylongword\nx\n");
    EXPECT_EQ(WrapText(""), "");
    EXPECT_EQ(WrapText("  indented text here", 12, "    "), "  indented\n    text\n    here\n");
    EXPECT_EQ(WrapText("one two\nthree four\n", 9), "one two\nthree\nfour\n");
    EXPECT_EQ(WrapText("a\n\nb", 9), "a\n\nb\n");
}

// ---- CSV and JSON numbers ----

// Before: `lexel run --format csv` printed 0.93800000000000128 (17 significant digits).
TEST(ReportNumbers, CsvNumbersAreTheShortestThatReadBack) {
    EXPECT_EQ(CsvNumber(0.938), "0.938");
    EXPECT_EQ(CsvNumber(0.93800000000000128), "0.9380000000000013");
    EXPECT_EQ(CsvNumber(0.1 + 0.2), "0.30000000000000004");
    EXPECT_EQ(CsvNumber(1247.0), "1247");
    EXPECT_EQ(CsvNumber(-0.0), "0");
    EXPECT_EQ(CsvNumber(1e300), "1e+300");
    EXPECT_EQ(CsvNumber(-std::numeric_limits<double>::infinity()), "-inf");
    // Seeded random doubles over many magnitudes: each reads back exactly, and no shorter
    // %.{p}g does.
    std::mt19937_64 random(24);
    std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
    std::uniform_int_distribution<int> exponent(-30, 30);
    for (int i = 0; i < 20000; ++i) {
        const double value = mantissa(random) * std::pow(10.0, exponent(random));
        const std::string text = CsvNumber(value);
        double back = 0.0;
        const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), back);
        ASSERT_TRUE(error == std::errc() && end == text.data() + text.size()) << text;
        ASSERT_EQ(back, value) << text << " (seed 24, draw " << i << ")";
        // No %.{p}g that reads back is shorter.
        for (int p = 1; p <= 17; ++p) {
            char shorter[64];
            std::snprintf(shorter, sizeof shorter, "%.*g", p, value);
            if (std::strtod(shorter, nullptr) != value) continue;
            ASSERT_LE(text.size(), std::string(shorter).size()) << text << " " << shorter;
            break;
        }
    }
}

TEST(ReportNumbers, JsonNumbersReadBackAsTheSameDouble) {
    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> value(-1e6, 1e6);
    nlohmann::json doc = nlohmann::json::array();
    std::vector<double> values;
    for (int i = 0; i < 5000; ++i) {
        values.push_back(value(random) / 3.0);
        doc.push_back(values.back());
    }
    const nlohmann::json back = nlohmann::json::parse(doc.dump(2));
    for (std::size_t i = 0; i < values.size(); ++i)
        ASSERT_EQ(back[i].get<double>(), values[i]) << "seed 7, draw " << i;
}

// ---- progress ----

TEST(Progress, LineSaysElapsedAndAnEstimateOfWhatIsLeft) {
    EXPECT_EQ(DurationText(0.4), "0 s");
    EXPECT_EQ(DurationText(59.9), "59 s");
    EXPECT_EQ(DurationText(245), "4 min 05 s");
    EXPECT_EQ(DurationText(3 * 3600 + 7 * 60 + 59), "3 h 07 min");
    EXPECT_EQ(DurationText(2 * 86400 + 5 * 3600 + 1), "2 d 05 h");
    EXPECT_EQ(DurationText(-3), "0 s");
    EXPECT_EQ(ProgressText("sweep", 0, 100000, "lights", 0.0),
              "sweep [..............................] 0/100000 lights, 0 s elapsed, estimating "
              "the time left");
    // 25 of 100000 lights in 45 s: 1.8 s a light, 99975 left: 179955 s = 2 d 01 h.
    EXPECT_EQ(ProgressText("sweep", 25, 100000, "lights", 45.0),
              "sweep [..............................] 25/100000 lights, 45 s elapsed, about 2 d "
              "01 h left");
    EXPECT_EQ(ProgressText("timing", 5, 10, "frames", 10.0),
              "timing [###############...............] 5/10 frames, 10 s elapsed, about 10 s left");
    EXPECT_EQ(ProgressText("run walkthrough", 39, 39, "steps", 75.0),
              "run walkthrough [##############################] 39/39 steps, 1 min 15 s elapsed");
}

// ---- --help ----

TEST(MethodHelp, EveryMethodHasOneLineOfDescription) {
    std::set<std::string_view> seen;
    for (const std::string& m : spatial::SpatialMethodNames()) {
        const std::string_view d = spatial::SpatialMethodDescription(m);
        EXPECT_FALSE(d.empty()) << m;
        EXPECT_LE(m.size() + 4 + DisplayWidth(d), 100u) << m << ": " << d;
        EXPECT_EQ(d.find('\n'), std::string_view::npos) << m;
        EXPECT_TRUE(seen.insert(d).second) << m << " repeats " << d;
    }
    for (const std::string& m : flatland::FlatlandMethodNames()) {
        const std::string_view d = flatland::FlatlandMethodDescription(m);
        EXPECT_FALSE(d.empty()) << m;
        EXPECT_LE(m.size() + 4 + DisplayWidth(d), 100u) << m << ": " << d;
    }
    EXPECT_TRUE(spatial::SpatialMethodDescription("nope").empty());
    EXPECT_TRUE(flatland::FlatlandMethodDescription("nope").empty());
}

// ---- lexel sweep's tables ----

// A sweep of every method over `lights` point lights with large, distinct counts (the widest
// cells the tables print).
SweepResult WideSweep(std::size_t lights) {
    SweepResult r;
    r.caseName = "walkthrough";
    r.methods = spatial::SpatialMethodNames();
    for (std::size_t l = 0; l < lights; ++l) {
        spatial::Light light;
        light.type = spatial::Light::Type::kPoint;
        light.position = {1.0 * l, 50.0, -3.0};
        r.lights.push_back(light);
        r.receiverPixels.push_back(500000);
        std::vector<SweepCell> cells;
        for (std::size_t m = 0; m < r.methods.size(); ++m) {
            SweepCell c;
            c.misclassified = static_cast<std::int64_t>(100000 + 7919 * ((l * 31 + m * 17) % 97));
            c.misclassifiedMean = static_cast<double>(c.misclassified);
            c.h = 123456.789 * (m + 1);
            c.ms = 1234.5678;
            c.footprintMean = 12.3456;
            c.footprintMax = 12345.678;
            c.uncovered = 123456;
            c.cascades = spatial::IsPartitionedMethod(r.methods[m]) ? 16
                         : spatial::IsVirtualMethod(r.methods[m])   ? 156
                                                                    : 1;
            if (spatial::IsVirtualMethod(r.methods[m])) {
                c.pagesRequested = 123456;
                c.pagesResident = 156;
                c.pagesDropped = 123300;
                c.lodBias = 12.345;
            }
            c.emptyPartitions = c.cascades > 1 ? 3 : 0;
            c.storageFactor = 98765.4321;
            cells.push_back(c);
        }
        r.cells.push_back(cells);
    }
    return r;
}

ReportTable1 PublishedTable1() {
    return LoadReportTable1(std::string(LEXEL_CASES_DIR) + "/published/report_table1.json");
}

TEST(SweepTable, FitsTheTerminal) {
    for (std::size_t lights : {3u, 20u, 500u}) {
        const std::string text = SweepTable(WideSweep(lights), PublishedTable1());
        const auto [width, line] = Widest(text);
        EXPECT_LE(width, kTerminalColumns) << lights << " lights: " << line;
        EXPECT_NE(text.find("Equal texels"), std::string::npos);
    }
}

// Before: `--lights 10` printed "worst 10%" rows that each repeat one light.
TEST(SweepTable, HasWorstTenPercentRowsFromTwentyLights) {
    const ReportTable1 report = PublishedTable1();
    for (std::size_t lights : {1u, 10u, 19u}) {
        const SweepResult r = WideSweep(lights);
        EXPECT_EQ(SweepTable(r, report).find("worst 10%"), std::string::npos) << lights;
        EXPECT_NE(SweepTable(r, report).find("No worst-10% rows: they need at least 20 lights"),
                  std::string::npos)
            << lights;
        EXPECT_EQ(SweepCsv(r, report).find(",optimal-report,optimal-report,"), std::string::npos);
        EXPECT_TRUE(SweepJson(r)["report_table"]["worst_10_percent"].empty()) << lights;
    }
    const SweepResult r = WideSweep(20);
    const std::string text = SweepTable(r, report);
    // One row per report method, and under each the report's own row.
    std::size_t worst = 0;
    for (const std::string& line : LinesOf(text)) worst += line.starts_with("worst 10% by ");
    // The report's methods, then tsm-report (fitted to the view frustum as they are).
    const std::size_t reportColumns = spatial::ReportMethodNames().size() + 1;
    EXPECT_EQ(worst, 2u * reportColumns) << text;  // two column blocks
    EXPECT_EQ(SweepJson(r)["report_table"]["worst_10_percent"].size(), reportColumns);
    EXPECT_EQ(text.find("No worst-10% rows"), std::string::npos);
}

// Table 1's published counts (1,886,057) sat beside ours (1,247) unlabelled.
TEST(SweepTable, LabelsThePublishedCountsAsTheReportsOwnScale) {
    const SweepResult r = WideSweep(20);
    for (const std::string& text :
         {SweepTable(r, PublishedTable1()), SweepMarkdown(r, PublishedTable1())}) {
        EXPECT_NE(text.find("published (report)"), std::string::npos) << text;
        EXPECT_NE(text.find("1886057 (0)"), std::string::npos) << text;
        EXPECT_NE(text.find("summed over its 500 lights"), std::string::npos) << text;
        EXPECT_NE(text.find("the percentages do."), std::string::npos) << text;
        EXPECT_EQ(text.find("report (Table 1)"), std::string::npos) << text;
    }
    // Without optimal-report there is no published row, and no note about it.
    SweepResult fair = r;
    fair.methods = {"optimal", "focused"};
    for (auto& cells : fair.cells) cells.resize(2);
    const std::string text = SweepTable(fair, PublishedTable1());
    EXPECT_EQ(text.find("published (report)"), std::string::npos) << text;
    EXPECT_EQ(text.find("summed over"), std::string::npos) << text;
}

TEST(SweepTable, MarkdownSaysWhatEachTableMeans) {
    const std::string markdown = SweepMarkdown(WideSweep(20), PublishedTable1());
    std::size_t headings = 0, explained = 0;
    const std::vector<std::string> lines = LinesOf(markdown);
    for (std::size_t i = 0; i + 2 < lines.size(); ++i)
        if (lines[i].starts_with("## ")) {
            ++headings;
            explained += !lines[i + 2].empty() && lines[i + 2][0] != '|';
        }
    // Table 1, its summary, fair, equal texels, the virtual shadow maps' pages.
    EXPECT_EQ(headings, 5u) << markdown;
    EXPECT_NE(markdown.find("Virtual shadow maps' pages"), std::string::npos);
    EXPECT_NE(markdown.find("| vsm-dynamic | 123456.0 | 156.0 | 123300.0 | 12.345 |"),
              std::string::npos)
        << markdown;
    EXPECT_EQ(explained, headings) << markdown;
    EXPECT_NE(markdown.find("| max σ1(J⁻¹) |"), std::string::npos);  // terminal-only cut
}

// A two-method fair sweep (optimal, lispsm-tight) from per-light (misclassified mean, standard
// error, h, grazing part of h) for each method.
struct CellSpec {
    double mean, error, h, hGrazing;
};
SweepResult FairSweep(const std::vector<std::array<CellSpec, 2>>& lights, int phases) {
    SweepResult r;
    r.caseName = "demo";
    r.methods = {"optimal", "lispsm-tight"};
    r.phases = phases;
    for (std::size_t l = 0; l < lights.size(); ++l) {
        spatial::Light light;
        light.position = {1.0 + static_cast<double>(l), 40.0, 2.0};
        r.lights.push_back(light);
        r.indices.push_back(l);
        r.receiverPixels.push_back(1000);
        std::vector<SweepCell> cells;
        for (const CellSpec& spec : lights[l]) {
            SweepCell c;
            c.misclassified = static_cast<std::int64_t>(spec.mean);
            c.misclassifiedMean = spec.mean;
            c.misclassifiedError = spec.error;
            c.h = spec.h;
            c.hGrazing = spec.hGrazing;
            cells.push_back(c);
        }
        r.cells.push_back(cells);
    }
    return r;
}

const nlohmann::json& FairEntry(const nlohmann::json& doc, const std::string& method) {
    for (const nlohmann::json& m : doc["fair_table"]["methods"])
        if (m["method"] == method) return m;
    throw std::runtime_error("no " + method);
}

// Report bugs once: the grazing share of h averaged only over lights with 0 < h < inf (a
// light without boundary samples has h = 0 and no share), and "h orders as errors" counting
// neither a tie in h (both 0) nor a difference within the noise (one phase: under 2% or a pixel).
TEST(SweepReport, GrazingShareAndHOrderingsSkipLightsWithoutOrder) {
    const SweepResult r = FairSweep({{{{0, 0, 0.0, 0.0}, {0, 0, 0.0, 0.0}}},        // no samples
                                     {{{100, 0, 10.0, 5.0}, {150, 0, 20.0, 5.0}}},  // h agrees
                                     {{{200, 0, 10.0, 2.5}, {201, 0, 30.0, 3.0}}},  // one pixel
                                     {{{50, 0, 10.0, 0.0}, {40, 0, 5.0, 0.0}}}},    // h agrees
                                    1);
    const nlohmann::json doc = SweepJson(r);
    const nlohmann::json& optimal = FairEntry(doc, "optimal");
    // (0.5 + 0.25 + 0) / 3, light 0 left out.
    EXPECT_DOUBLE_EQ(optimal["h_share_at_grazing_samples"].get<double>(), 0.25);
    const nlohmann::json& lispsm = FairEntry(doc, "lispsm-tight");
    // Lights 1 and 3 qualify, and h orders both right; light 0 ties, light 2 is one pixel.
    EXPECT_DOUBLE_EQ(lispsm["percent_lights_h_ranks_as_misclassified"].get<double>(), 100.0);
    // One phase: any difference is a win or a loss (lights 1, 2 lost, 3 won).
    EXPECT_DOUBLE_EQ(lispsm["percent_lights_beating_reference"].get<double>(), 25.0);
    EXPECT_DOUBLE_EQ(lispsm["percent_lights_reference_beats"].get<double>(), 50.0);
}

// "e orders as errors" counts as "h orders" does, on the edge energy: here h orders every light
// wrongly and e two of three rightly; a NaN e (a warped map) orders nothing.
TEST(SweepReport, EOrderingsCountLikeHOrderings) {
    SweepResult r = FairSweep({{{{100, 0, 10.0, 0.0}, {150, 0, 5.0, 0.0}}},
                               {{{100, 0, 10.0, 0.0}, {50, 0, 20.0, 0.0}}},
                               {{{100, 0, 10.0, 0.0}, {80, 0, 20.0, 0.0}}},
                               {{{100, 0, 10.0, 0.0}, {60, 0, 20.0, 0.0}}}},
                              1);
    const double e[4][2] = {
        {1.0, 2.0}, {1.0, 0.5}, {1.0, 2.0}, {1.0, std::numeric_limits<double>::quiet_NaN()}};
    for (std::size_t l = 0; l < 4; ++l)
        for (std::size_t m = 0; m < 2; ++m) r.cells[l][m].e = e[l][m];
    const nlohmann::json doc = SweepJson(r);
    const nlohmann::json& lispsm = FairEntry(doc, "lispsm-tight");
    EXPECT_DOUBLE_EQ(lispsm["percent_lights_h_ranks_as_misclassified"].get<double>(), 0.0);
    EXPECT_NEAR(lispsm["percent_lights_e_ranks_as_misclassified"].get<double>(), 200.0 / 3.0,
                1e-12);
    const std::string text = SweepTable(r, PublishedTable1());
    EXPECT_NE(text.find("e orders"), std::string::npos) << text;
}

// An opt-in partitioned method (sdsm-optimal-h) is compared at equal texels like the others.
TEST(SweepReport, OptInPartitionedMethodsJoinTheEqualTexelTable) {
    SweepResult r = FairSweep({{{{100, 0, 1.0, 0.0}, {80, 0, 2.0, 0.0}}}}, 1);
    r.methods[1] = "sdsm-optimal-h";
    const nlohmann::json doc = SweepJson(r);
    ASSERT_TRUE(doc.contains("equal_texel_table"));
    const nlohmann::json& methods = doc["equal_texel_table"]["methods"];
    ASSERT_EQ(methods.size(), 2u);
    EXPECT_EQ(methods[1]["method"], "sdsm-optimal-h");
    EXPECT_DOUBLE_EQ(methods[1]["percent_more"].get<double>(), -20.0);
}

// With phases, a win counts only beyond 1.96 standard errors of the difference.
TEST(SweepReport, WinsCountOnlyBeyondThePhaseNoise) {
    // Differences 10 with errors (3, 4): 10 > 1.96 · 5 = 9.8, a win; 9 is not; 20 is a loss.
    const SweepResult r = FairSweep({{{{100, 3, 1.0, 0.0}, {90, 4, 2.0, 0.0}}},
                                     {{{100, 3, 1.0, 0.0}, {91, 4, 2.0, 0.0}}},
                                     {{{100, 3, 1.0, 0.0}, {120, 4, 2.0, 0.0}}}},
                                    16);
    const nlohmann::json doc = SweepJson(r);
    EXPECT_EQ(doc["phases"], 16);
    const nlohmann::json& lispsm = FairEntry(doc, "lispsm-tight");
    EXPECT_NEAR(lispsm["percent_lights_beating_reference"].get<double>(), 100.0 / 3.0, 1e-12);
    EXPECT_NEAR(lispsm["percent_lights_reference_beats"].get<double>(), 100.0 / 3.0, 1e-12);
    // h (1 vs 2) orders light 0 wrongly and light 2 rightly; light 1 is within the noise.
    EXPECT_DOUBLE_EQ(lispsm["percent_lights_h_ranks_as_misclassified"].get<double>(), 50.0);
    // Means 100 and 100.33; the paired differences (−10, −9, +20) have s = √(1742/6) = 17.0392,
    // t(2) = 4.3027: half-width 4.3027 · 17.0392 / √3 = 42.328, as % of 100.
    EXPECT_NEAR(lispsm["percent_more_ci95"].get<double>(), 42.328, 0.001);
    EXPECT_NEAR(lispsm["mean_misclassified"].get<double>(), 301.0 / 3.0, 1e-12);
    // The residual noise: Σ errors / Σ means = 12 / 301.
    EXPECT_NEAR(lispsm["residual_noise"].get<double>(), 12.0 / 301.0, 1e-12);
    const std::string text = SweepTable(r, PublishedTable1());
    EXPECT_NE(text.find("mean over 16 sub-texel phases"), std::string::npos) << text;
}

}  // namespace
}  // namespace lexel::cases
