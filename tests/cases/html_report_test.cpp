// index.html of `lexel run --out` and `lexel sweep --out`: the tables and what each
// means, images and files linked by encoded names, every text escaped. (That every link resolves
// in a real --out directory is checked by cli_tests with check_html_links.cmake.)
#include "lexel/cases/report/html_report.h"

#include <gtest/gtest.h>

#include <string>

#include "lexel/cases/report/sweep_report.h"

namespace lexel::cases {
namespace {

std::size_t Count(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1))
        ++n;
    return n;
}

SweepResult SmallSweep(std::size_t lights, std::string caseName) {
    SweepResult r;
    r.caseName = std::move(caseName);
    r.methods = {"optimal", "optimal-report", "focused", "sdsm"};
    for (std::size_t l = 0; l < lights; ++l) {
        spatial::Light light;
        light.position = {1.0 + l, 40.0, 2.0};
        r.lights.push_back(light);
        r.receiverPixels.push_back(1000);
        std::vector<SweepCell> cells(r.methods.size());
        for (std::size_t m = 0; m < cells.size(); ++m) {
            cells[m].misclassified = static_cast<std::int64_t>(10 * (m + 1) + l);
            cells[m].misclassifiedMean = static_cast<double>(cells[m].misclassified);
            cells[m].h = 5.0 * (m + 1);
            cells[m].cascades = r.methods[m] == "sdsm" ? 4 : 1;
        }
        r.cells.push_back(cells);
    }
    return r;
}

TEST(HtmlReport, SweepPageHoldsEveryTableWithWhatItMeans) {
    const ReportTable1 report =
        LoadReportTable1(std::string(LEXEL_CASES_DIR) + "/published/report_table1.json");
    const SweepResult r = SmallSweep(25, "walk <&> \"through\"");
    const std::vector<SpatialImageFile> images = {
        {"walk <&> \"through\"_light0_sdsm_frame.png", 0, "sdsm", "frame", "the frame <x>"}};
    const std::string html = SweepHtml(r, report, nullptr, "", images,
                                       {{"table1.csv", "the tables"}, {"lights.csv", "per light"}});
    EXPECT_TRUE(html.starts_with("<!DOCTYPE html>\n<html lang=\"en\">\n")) << html;
    EXPECT_TRUE(html.ends_with("</body>\n</html>\n"));
    const std::vector<ReportSection> sections = SweepSections(r, report, false);
    ASSERT_EQ(sections.size(), 4u);  // Table 1, its summary, fair, equal texels
    for (const ReportSection& s : sections) {
        EXPECT_NE(html.find("<p>" + HtmlText(s.explanation) + "</p>"), std::string::npos)
            << s.title;
    }
    EXPECT_EQ(Count(html, "<table>"), 4u);
    // All lights, and the worst 10% by optimal-report and by focused.
    EXPECT_EQ(Count(html, "<tr class=\"published\">"), 3u);
    EXPECT_NE(html.find("summed over its 500 lights"), std::string::npos);
    // Escaped text, encoded links.
    EXPECT_EQ(html.find("<&>"), std::string::npos);
    EXPECT_NE(html.find("walk &lt;&amp;&gt; &quot;through&quot;"), std::string::npos);
    EXPECT_NE(html.find("src=\"walk%20%3C%26%3E%20%22through%22_light0_sdsm_frame.png\""),
              std::string::npos);
    EXPECT_NE(html.find("alt=\"the frame &lt;x&gt;\""), std::string::npos);
    EXPECT_NE(html.find("<a href=\"lights.csv\">lights.csv</a>: per light"), std::string::npos);
    // Every in-page link has its anchor.
    for (const char* id : {"table0", "table1", "table2", "table3", "light0", "files"}) {
        EXPECT_NE(html.find("href=\"#" + std::string(id) + "\""), std::string::npos) << id;
        EXPECT_NE(html.find("id=\"" + std::string(id) + "\""), std::string::npos) << id;
    }
}

TEST(HtmlReport, FlatlandPageHasATablePerCase) {
    flatland::CaseReport a, b;
    a.caseName = "one";
    b.caseName = "two & more";
    flatland::MethodReport m;
    m.method = "optimal-l1";
    a.methods = {m};
    b.methods = {m, m};
    const std::vector<flatland::CaseReport> reports = {a, b};
    const std::string html = FlatlandRunHtml(reports, {{"one.json", "one"}});
    EXPECT_EQ(Count(html, "<table>"), 2u);
    EXPECT_EQ(Count(html, "<td>optimal-l1</td>"), 3u);
    EXPECT_NE(html.find("<h2>two &amp; more: "), std::string::npos);
}

}  // namespace
}  // namespace lexel::cases
