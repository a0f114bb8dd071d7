#include "lexel/cases/report.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace lexel::cases {

std::string Fixed(double value, int digits) {
    if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
    // Values that round to zero print as 0, never as "-0.000".
    if (std::abs(value) < 0.5 * std::pow(10.0, -digits)) value = 0.0;
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*f", digits, value);
    return buffer;
}

std::string Significant(double value, int digits) {
    if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*g", digits, value);
    return buffer;
}

namespace {
// Terminal columns of a UTF-8 string: one per code point (continuation bytes are 10xxxxxx), so
// "σ" and "∞" take one column like the ASCII around them.
std::size_t DisplayWidth(const std::string& text) {
    std::size_t width = 0;
    for (unsigned char c : text) width += (c & 0xC0) != 0x80;
    return width;
}
}  // namespace

std::string TextTable::Render() const {
    std::vector<std::size_t> width;
    for (const auto& row : rows_)
        for (std::size_t c = 0; c < row.size(); ++c) {
            if (width.size() <= c) width.push_back(0);
            width[c] = std::max(width[c], DisplayWidth(row[c]));
        }
    std::ostringstream out;
    for (std::size_t r = 0; r < rows_.size(); ++r) {
        for (std::size_t c = 0; c < rows_[r].size(); ++c) {
            const std::string& cell = rows_[r][c];
            const std::string pad(width[c] - DisplayWidth(cell), ' ');
            out << (c ? "  " : "") << (c == 0 ? cell + pad : pad + cell);
        }
        out << '\n';
        if (r == 0) {
            std::size_t total = 0;
            for (std::size_t c = 0; c < width.size(); ++c) total += width[c] + (c ? 2 : 0);
            out << std::string(total, '-') << '\n';
        }
    }
    return out.str();
}

std::string TextTable::RenderMarkdown() const {
    std::ostringstream out;
    for (std::size_t r = 0; r < rows_.size(); ++r) {
        out << '|';
        for (const auto& cell : rows_[r]) out << ' ' << cell << " |";
        out << '\n';
        if (r == 0) {
            out << '|';
            for (std::size_t c = 0; c < rows_[0].size(); ++c)
                out << (c == 0 ? " --- |" : " ---: |");
            out << '\n';
        }
    }
    return out.str();
}

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
    out.precision(17);
    out << "case,method,lexel_plane_deg,worst,average,mean_plus_sigma,median,l1,l2,linf,pixels_"
           "visible,"
           "solve_ms,frusta,note\n";
    for (const auto& r : reports)
        for (const auto& m : r.methods) {
            std::string note = m.note;
            for (char& c : note)
                if (c == ',' || c == '"') c = ';';
            out << r.caseName << ',' << m.method << ',' << m.lexelPlaneDeg << ',' << m.stats.worst()
                << ',' << m.stats.average << ',' << m.stats.meanPlusSigma << ',' << m.stats.median
                << ',' << m.stats.l1 << ',' << m.stats.l2 << ',' << m.stats.linf << ','
                << m.stats.count << ',' << m.solveMs << ','
                << (m.frusta.empty() ? 1 : m.frusta.size()) << ',' << note << '\n';
        }
    return out.str();
}

namespace {
TextTable MethodTable(const flatland::CaseReport& report) {
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
}  // namespace

std::string CaseTable(const flatland::CaseReport& report) {
    return CaseHeader(report) + "\n" + MethodTable(report).Render();
}

std::string CaseMarkdown(const flatland::CaseReport& report) {
    return "## " + CaseHeader(report) + "\n\n" + MethodTable(report).RenderMarkdown();
}

void WriteFileAtomically(const std::string& path, const std::string& content) {
    const std::string temporary = path + ".partial";
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        if (!out) throw std::runtime_error(path + ": cannot write");
        out << content;
        if (!out) throw std::runtime_error(path + ": write failed");
    }
    std::filesystem::rename(temporary, path);
}

}  // namespace lexel::cases
