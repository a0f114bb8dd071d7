#include "lexel/cases/tables.h"

#include <filesystem>
#include <iostream>
#include <sstream>
#include <stdexcept>

#include "lexel/cases/figures.h"
#include "lexel/cases/flatland_case.h"
#include "lexel/cases/report.h"
#include "lexel/solvers/errors.h"

namespace lexel::cases {

namespace fs = std::filesystem;

const std::vector<ThesisCase>& ThesisCases() {
    // Chong 2003, §4.1.3, the four tables as printed (angles in degrees, footprints in pixels).
    static const std::vector<ThesisCase> cases = {
        {"single_plane.json",
         "Single Plane Geometry",
         {{"Our Method (both)", "optimal-l1", 9, 0.975, 0.960, 0.968},
          {"Our Method (both)", "optimal-l2", 9, 0.975, 0.960, 0.968},
          {"Perspective SM", "psm-thesis", 91, 4.33, 1.88, 3.10},
          {"Normal SM", "normal", 51, 2.08, 1.17, 1.65}}},
        {"simple_geometry.json",
         "Simple Geometry",
         {{"Our Method (L1)", "optimal-l1", 24.8, 1.54, 1.09, 1.42},
          {"Our Method (L2)", "optimal-l2", 29.2, 1.54, 1.10, 1.41},
          {"Perspective SM", "psm-thesis", 86.8, 4.74, 1.95, 3.20},
          {"Normal SM", "normal", 25.3, 1.54, 1.09, 1.42}}},
        {"light_from_top.json",
         "Light from Top",
         {{"Our Method (L1)", "optimal-l1", 5.11, 6.42, 3.38, 4.39},
          {"Our Method (L2)", "optimal-l2", 5.13, 6.42, 3.38, 4.36},
          {"Perspective SM", "psm-thesis", 77.3, 73.7, 44.4, 67.4},
          {"Normal SM", "normal", 83.1, 76.7, 46.2, 70.2}}},
        {"projection_aliasing.json",
         "Projection Aliasing",
         {{"Our Method (L1)", "optimal-l1", 33.9, 60.0, 17.7, 41.4, 7.75},
          {"Perspective SM", "psm-thesis", 67.7, 72.7, 22.1, 50.5},
          {"Normal SM", "normal", 83.7, 82.5, 25.3, 57.5}}},
    };
    return cases;
}

const std::vector<std::pair<std::string, std::string>>& TableRows() {
    static const std::vector<std::pair<std::string, std::string>> rows = {
        {"Our Method (L1)", "optimal-l1"},   {"Our Method (L2)", "optimal-l2"},
        {"Our Method (L∞)", "optimal-linf"}, {"Perspective SM", "psm-thesis"},
        {"PSM (true sampling)", "psm"},      {"Normal SM", "normal"},
        {"plane-optimal", "plane-optimal"},  {"split-dp", "split-dp"}};
    return rows;
}

const flatland::MethodReport& TableResult::Method(const std::string& name) const {
    for (const auto& m : report.methods)
        if (m.method == name) return m;
    throw std::logic_error("method not in table: " + name);
}

std::vector<TableResult> RunThesisTables(const std::string& casesDir) {
    const fs::path dir =
        casesDir.empty() ? fs::path(LEXEL_CASES_DIR) / "flatland" : fs::path(casesDir);
    std::vector<std::string> methods;
    for (const auto& [label, method] : TableRows()) methods.push_back(method);
    std::vector<TableResult> results;
    for (const ThesisCase& thesis : ThesisCases()) {
        const fs::path path = dir / thesis.file;
        const flatland::FlatScene scene = LoadFlatScene(path);
        try {
            results.push_back(
                {thesis, scene, flatland::RunFlatlandCase(scene, methods, Metric::kL1)});
        } catch (const InputError& e) {
            throw InputError(path.string() + ": " + e.what());
        }
    }
    return results;
}

namespace {

const ThesisRow* PublishedRow(const ThesisCase& thesis, const std::string& method) {
    for (const auto& row : thesis.rows)
        if (row.method == method) return &row;
    return nullptr;
}

// Ratio of a row's average to our L1 optimum's average, ours and the thesis's: the improvement
// factor the thesis reports, which a reconstruction of its scene should reproduce in kind.
TextTable ComparisonTable(const TableResult& r) {
    const bool twoFrusta = r.thesis.title == "Projection Aliasing";
    std::vector<std::string> header = {"row", "angle", "worst", "average", "mean+σ"};
    if (twoFrusta) header.push_back("mean (2 frusta)");
    for (const char* h : {"thesis angle", "thesis worst", "thesis average", "thesis mean+σ"})
        header.push_back(h);
    if (twoFrusta) header.push_back("thesis mean (2 frusta)");
    header.push_back("avg / L1 opt");
    header.push_back("thesis avg / L1 opt");
    TextTable table(header);
    const double oursL1 = r.Method("optimal-l1").stats.average;
    const ThesisRow* thesisL1 = PublishedRow(r.thesis, "optimal-l1");
    const std::string twoFrustaMean = Significant(r.Method("split-dp").stats.average, 3);
    for (const auto& [label, method] : TableRows()) {
        const flatland::MethodReport& m = r.Method(method);
        const ThesisRow* published = PublishedRow(r.thesis, method);
        // A lexel plane's orientation is defined mod 180°; the thesis prints e.g. 91° where our
        // (−90°, 90°] convention says −89°, so show the representative nearest the published one.
        const double shown =
            published
                ? m.lexelPlaneDeg + 180.0 * std::round((published->angle - m.lexelPlaneDeg) / 180.0)
                : m.lexelPlaneDeg;
        std::string angle = Fixed(shown, 2);
        if (!m.frusta.empty()) {
            angle.clear();
            for (const auto& f : m.frusta)
                angle += (angle.empty() ? "" : "/") + Fixed(f.lexelPlaneDeg, 1);
        }
        std::vector<std::string> row = {label, angle, Significant(m.stats.worst(), 3),
                                        Significant(m.stats.average, 3),
                                        Significant(m.stats.meanPlusSigma, 3)};
        if (twoFrusta) row.push_back(method == "optimal-l1" ? twoFrustaMean : "–");
        if (published) {
            row.push_back(Significant(published->angle, 3));
            row.push_back(Significant(published->worst, 3));
            row.push_back(Significant(published->average, 3));
            row.push_back(Significant(published->meanPlusSigma, 3));
            if (twoFrusta)
                row.push_back(std::isnan(published->twoFrustaMean)
                                  ? "–"
                                  : Significant(published->twoFrustaMean, 3));
        } else {
            for (int k = 0; k < (twoFrusta ? 5 : 4); ++k) row.push_back("–");
        }
        row.push_back(Fixed(m.stats.average / oursL1, 2));
        row.push_back(published && thesisL1 ? Fixed(published->average / thesisL1->average, 2)
                                            : "–");
        table.AddRow(row);
    }
    return table;
}

std::string LowresSummary(const std::vector<TableResult>& results,
                          const std::vector<std::vector<LowresRow>>& lowres) {
    // The thesis: "Most of the scene configurations gain less than five percent additional error
    // when using angles determined from ten samples."
    int agree = 0;
    for (const auto& rows : lowres)
        for (const auto& row : rows)
            if (row.decisionPixels == 10 && row.extraPercent[0] < 5.0 && row.extraPercent[1] < 5.0)
                ++agree;
    std::ostringstream out;
    out << "With K = 10 decision pixels, " << agree << " of " << results.size()
        << " cases gain under 5% extra error for both L1 and L2; the thesis reports this for most "
           "scenes: "
        << (2 * agree > static_cast<int>(results.size()) ? "ours agrees." : "ours does not agree.")
        << '\n';
    return out.str();
}

}  // namespace

std::string TablesText(const std::vector<TableResult>& results) {
    std::ostringstream out;
    for (const auto& r : results)
        out << r.thesis.title << " (" << r.thesis.file << ", " << r.report.pixelsVisible
            << " visible pixels, " << r.report.lexels << " lexels)\n"
            << ComparisonTable(r).Render() << '\n';
    return out.str();
}

std::string TablesMarkdown(const std::vector<TableResult>& results) {
    std::ostringstream out;
    out << "# Chong 2003, ch. 4.1.3, reproduced by lexel\n\n"
        << "Our numbers on the reconstructed cases beside the thesis's published ones. Angles in "
           "degrees "
           "(counterclockwise from vertical), footprints in pixels per lexel. The last two columns "
           "are each "
           "row's average over our L1 optimum's average, ours and the thesis's.\n\n";
    for (const auto& r : results)
        out << "## " << r.thesis.title << "\n\n`cases/flatland/" << r.thesis.file
            << "`: " << r.report.pixelsVisible << " visible pixels, " << r.report.lexels
            << " lexels.\n\n"
            << ComparisonTable(r).RenderMarkdown() << "\n![" << r.thesis.title << "]("
            << fs::path(r.thesis.file).stem().string() << ".png)\n\n";
    return out.str();
}

std::string TablesCsv(const std::vector<TableResult>& results) {
    std::ostringstream out;
    out.precision(17);
    out << "case,row,method,angle,worst,average,mean_plus_sigma,thesis_angle,thesis_worst,thesis_"
           "average,"
           "thesis_mean_plus_sigma,thesis_two_frusta_mean\n";
    for (const auto& r : results)
        for (const auto& [label, method] : TableRows()) {
            const auto& m = r.Method(method);
            const ThesisRow* p = PublishedRow(r.thesis, method);
            out << fs::path(r.thesis.file).stem().string() << ',' << label << ',' << method << ','
                << m.lexelPlaneDeg << ',' << m.stats.worst() << ',' << m.stats.average << ','
                << m.stats.meanPlusSigma << ',';
            if (p)
                out << p->angle << ',' << p->worst << ',' << p->average << ',' << p->meanPlusSigma
                    << ','
                    << (std::isnan(p->twoFrustaMean) ? std::string()
                                                     : std::to_string(p->twoFrustaMean));
            else
                out << ",,,,";
            out << '\n';
        }
    return out.str();
}

std::vector<int> LowresResolutions(int fullPixels) {
    std::vector<int> out;
    for (int k : {5, 10, 20, 50, 100, 200})
        if (k < fullPixels) out.push_back(k);
    out.push_back(fullPixels);
    return out;
}

std::vector<LowresRow> RunLowresStudy(const flatland::FlatScene& scene) {
    static const std::vector<std::string> methods = {"optimal-l1", "optimal-l2", "optimal-linf"};
    auto errorOf = [](const FootprintStats& s, int metric) {
        return metric == 0 ? s.average : metric == 1 ? s.meanPlusSigma : s.worst();
    };
    flatland::FlatScene full = scene;
    full.decisionPixels = 0;
    const flatland::CaseReport reference = flatland::RunFlatlandCase(full, methods, Metric::kL1);
    // Every K is measured on the same full-resolution pass: compute it once.
    const auto fullPass = reference.fullPass;
    std::vector<LowresRow> rows;
    for (int k : LowresResolutions(scene.camera.pixels)) {
        LowresRow row;
        row.decisionPixels = k;
        flatland::FlatScene low = scene;
        low.decisionPixels = k;
        try {
            const flatland::CaseReport report =
                flatland::RunFlatlandCase(low, methods, Metric::kL1, fullPass);
            for (int m = 0; m < 3; ++m)
                row.extraPercent[m] = 100.0 * (errorOf(report.methods[m].stats, m) /
                                                   errorOf(reference.methods[m].stats, m) -
                                               1.0);
        } catch (const InputError&) {
            // K pixels may see no geometry, or too little to span a frustum: no decision possible.
        }
        rows.push_back(row);
    }
    return rows;
}

namespace {
TextTable LowresTable(const std::vector<LowresRow>& rows) {
    TextTable table(
        {"decision pixels K", "L1 extra (average) %", "L2 extra (mean+σ) %", "L∞ extra (worst) %"});
    for (const auto& row : rows) {
        std::vector<std::string> cells = {std::to_string(row.decisionPixels)};
        for (double v : row.extraPercent) cells.push_back(std::isnan(v) ? "n/a" : Fixed(v, 3));
        table.AddRow(cells);
    }
    return table;
}

std::vector<LowresCurve> LowresCurves(const std::vector<LowresRow>& rows) {
    std::vector<LowresCurve> curves = {
        {"L1 (average)", {}, {}}, {"L2 (mean+sigma)", {}, {}}, {"Linf (worst)", {}, {}}};
    for (const auto& row : rows)
        for (int m = 0; m < 3; ++m)
            if (!std::isnan(row.extraPercent[m])) {
                curves[m].pixels.push_back(row.decisionPixels);
                curves[m].extraPercent.push_back(std::max(0.0, row.extraPercent[m]));
            }
    return curves;
}
}  // namespace

std::string LowresText(const std::string& caseName, const std::vector<LowresRow>& rows) {
    return "Low-resolution decision: " + caseName + "\n" + LowresTable(rows).Render();
}

std::string LowresMarkdown(const std::string& caseName, const std::vector<LowresRow>& rows) {
    return "### Low-resolution decision: " + caseName + "\n\n" +
           LowresTable(rows).RenderMarkdown() + "\n![lowres " + caseName + "](lowres_" + caseName +
           ".png)\n\n";
}

int RunTablesCommand(const std::string& outDir, const std::string& casesDir) {
    const std::vector<TableResult> results = RunThesisTables(casesDir);
    std::vector<std::vector<LowresRow>> lowres;
    std::vector<flatland::FlatScene> scenes;
    for (const auto& r : results) {
        scenes.push_back(r.scene);
        lowres.push_back(RunLowresStudy(r.scene));
    }
    std::cout << TablesText(results);
    for (std::size_t i = 0; i < results.size(); ++i)
        std::cout << LowresText(scenes[i].name, lowres[i]) << '\n';
    const std::string summary = LowresSummary(results, lowres);
    std::cout << summary;

    fs::create_directories(outDir);
    std::string markdown =
        TablesMarkdown(results) + "## Low-resolution decision (thesis 4.1.1, Fig. 4.1)\n\n";
    std::ostringstream lowresCsv;
    lowresCsv << "case,decision_pixels,l1_extra_percent,l2_extra_percent,linf_extra_percent\n";
    for (std::size_t i = 0; i < results.size(); ++i) {
        const std::string stem = fs::path(results[i].thesis.file).stem().string();
        WriteCaseFigure((fs::path(outDir) / (stem + ".png")).string(), scenes[i],
                        results[i].report);
        WriteLowresPlot((fs::path(outDir) / ("lowres_" + scenes[i].name + ".png")).string(),
                        "Low-resolution decision: " + scenes[i].name, LowresCurves(lowres[i]));
        markdown += LowresMarkdown(scenes[i].name, lowres[i]);
        for (const auto& row : lowres[i])
            lowresCsv << scenes[i].name << ',' << row.decisionPixels << ',' << row.extraPercent[0]
                      << ',' << row.extraPercent[1] << ',' << row.extraPercent[2] << '\n';
    }
    markdown += summary;
    WriteFileAtomically((fs::path(outDir) / "tables.md").string(), markdown);
    WriteFileAtomically((fs::path(outDir) / "tables.csv").string(), TablesCsv(results));
    WriteFileAtomically((fs::path(outDir) / "lowres.csv").string(), lowresCsv.str());
    std::cout << "\nlexel: wrote tables.md, tables.csv, lowres.csv and " << 2 * results.size()
              << " figures to " << fs::absolute(outDir).string() << '\n';
    return 0;
}

int RunLowresCommand(const std::string& casePath, const std::string& outDir) {
    const flatland::FlatScene scene = LoadFlatScene(casePath);
    std::vector<LowresRow> rows;
    try {
        rows = RunLowresStudy(scene);
    } catch (const InputError& e) {
        throw InputError(casePath + ": " + e.what());
    }
    std::cout << LowresText(scene.name, rows);
    if (!outDir.empty()) {
        fs::create_directories(outDir);
        WriteFileAtomically((fs::path(outDir) / ("lowres_" + scene.name + ".md")).string(),
                            LowresMarkdown(scene.name, rows));
        WriteLowresPlot((fs::path(outDir) / ("lowres_" + scene.name + ".png")).string(),
                        "Low-resolution decision: " + scene.name, LowresCurves(rows));
    }
    return 0;
}

}  // namespace lexel::cases
