#include "lexel/cases/report/flatland_report.h"

#include <sstream>

#include "lexel/cases/report/text_table.h"

namespace lexel::cases {

namespace {

nlohmann::json StatsJson(const FootprintStats& s) {
    return {{"worst", s.worst()},
            {"average", s.average},
            {"mean_plus_sigma", s.meanPlusSigma},
            {"median", s.median},
            {"l1", s.l1},
            {"l2", s.l2},
            {"linf", s.linf},
            {"pixels_visible", s.count}};
}

}  // namespace

nlohmann::json CaseReportJson(const flatland::CaseReport& report) {
    nlohmann::json methods = nlohmann::json::array();
    for (const auto& m : report.methods) {
        nlohmann::json j = {{"method", m.method}, {"lexel_plane_deg", m.lexelPlaneDeg}};
        j.update(StatsJson(m.stats));
        j["solve_ms"] = m.solveMs;
        if (!m.note.empty()) j["note"] = m.note;
        if (!m.frusta.empty()) {
            nlohmann::json frusta = nlohmann::json::array();
            for (const auto& f : m.frusta) {
                nlohmann::json fj = {{"ray_low_deg", f.wsRayLowDeg},
                                     {"ray_high_deg", f.wsRayHighDeg},
                                     {"lexel_plane_deg", f.lexelPlaneDeg},
                                     {"lexels", f.lexels}};
                fj.update(StatsJson(f.stats));
                frusta.push_back(fj);
            }
            j["frusta"] = frusta;
        }
        methods.push_back(j);
    }
    return {{"case", report.caseName},
            {"pixels", report.pixels},
            {"decision_pixels", report.decisionPixels},
            {"pixels_visible", report.pixelsVisible},
            {"lexels", report.lexels},
            {"metric", std::string(MetricName(report.metric))},
            {"sampling_ms", report.samplingMs},
            {"methods", methods}};
}

nlohmann::json RunJson(std::span<const flatland::CaseReport> reports) {
    if (reports.size() == 1) return CaseReportJson(reports[0]);
    nlohmann::json cases = nlohmann::json::array();
    for (const auto& r : reports) cases.push_back(CaseReportJson(r));
    return {{"cases", cases}};
}

std::string RunCsv(std::span<const flatland::CaseReport> reports) {
    std::ostringstream out;
    out << "case,method,lexel_plane_deg,worst,average,mean_plus_sigma,median,l1,l2,linf,pixels_"
           "visible,"
           "solve_ms,frusta,note\n";
    for (const auto& r : reports)
        for (const auto& m : r.methods) {
            const auto num = [](double v) { return CsvNumber(v); };  // NaN: empty
            out << CsvText(r.caseName) << ',' << CsvText(m.method) << ',' << num(m.lexelPlaneDeg)
                << ',' << num(m.stats.worst()) << ',' << num(m.stats.average) << ','
                << num(m.stats.meanPlusSigma) << ',' << num(m.stats.median) << ','
                << num(m.stats.l1) << ',' << num(m.stats.l2) << ',' << num(m.stats.linf) << ','
                << m.stats.count << ',' << num(m.solveMs) << ','
                << (m.frusta.empty() ? 1 : m.frusta.size()) << ',' << CsvText(m.note) << '\n';
        }
    return out.str();
}

TextTable CaseMethodTable(const flatland::CaseReport& report) {
    TextTable table(
        {"method", "angle", "worst", "average", "mean+σ", "l1", "l2", "linf", "ms", "note"});
    for (const auto& m : report.methods) {
        std::string angle = Fixed(m.lexelPlaneDeg, 3);
        if (!m.frusta.empty()) {
            angle.clear();
            for (const auto& f : m.frusta)
                angle += (angle.empty() ? "" : "/") + Fixed(f.lexelPlaneDeg, 1);
        }
        table.AddRow({m.method, angle, Significant(m.stats.worst()), Significant(m.stats.average),
                      Significant(m.stats.meanPlusSigma), Significant(m.stats.l1, 6),
                      Significant(m.stats.l2, 6), Significant(m.stats.linf), Fixed(m.solveMs, 3),
                      m.note});
    }
    return table;
}

std::string CaseHeader(const flatland::CaseReport& r) {
    return r.caseName + ": " + std::to_string(r.pixelsVisible) + " of " + std::to_string(r.pixels) +
           " pixels visible, " + std::to_string(r.lexels) + " lexels, decision pass " +
           std::to_string(r.decisionPixels) + " pixels";
}

std::string CaseTable(const flatland::CaseReport& report) {
    return CaseHeader(report) + "\n" + CaseMethodTable(report).Render();
}

std::string CaseMarkdown(const flatland::CaseReport& report) {
    return "## " + CaseHeader(report) + "\n\n" + CaseMethodTable(report).RenderMarkdown();
}

}  // namespace lexel::cases
