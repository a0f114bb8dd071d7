#include "lexel/cases/studies/thesis/fit_report.h"

#include <nlohmann/json.hpp>
#include <sstream>

#include "lexel/cases/report/text_table.h"

namespace lexel::cases {

using flatland::ComparedNumber;
using flatland::Quantity;
using flatland::SceneFamily;
using flatland::TableAgreement;

namespace {

// Shortest text that reads back to the same double (nlohmann's round-trip formatting).
std::string Num(double value) { return nlohmann::json(value).dump(); }
std::string Point(const flatland::Vec2& p) {
    std::ostringstream out;
    out << '[' << Num(p.x()) << ", " << Num(p.y()) << ']';
    return out.str();
}

std::string Percent(double relative) { return Fixed(100.0 * relative, 1) + "%"; }

std::string AgreementLine(const TableAgreement& a) {
    return "worst angle error " + Fixed(a.worstAngleDeg, 2) + "°, worst footprint error " +
           Percent(a.worstFootprint);
}

std::string Description(const CaseFit& fit) {
    std::ostringstream values;
    for (std::size_t i = 0; i < fit.best.parameters.size(); ++i)
        values << (i ? ", " : "") << fit.family->parameters[i].name << " = "
               << Significant(fit.best.parameters[i], 6);
    return "Chong 2003 §4.1.3, fitted by `lexel fit-thesis` to the published table with the " +
           fit.family->name + " family (" + values.str() +
           "): " + AgreementLine(fit.best.agreement) + ".";
}

}  // namespace

std::string FittedCaseJson(const CaseFit& fit) {
    const flatland::FlatScene& scene = fit.best.scene;
    const auto& cam = scene.camera;
    std::ostringstream out;
    out << "{\n  \"name\": " << nlohmann::json(scene.name).dump()
        << ",\n  \"description\": " << nlohmann::json(Description(fit)).dump()
        << ",\n  \"camera\": {\"position\": " << Point(cam.wsPosition)
        << ", \"direction\": " << Point(cam.wsDirection) << ", \"fov_deg\": " << Num(cam.fovDeg)
        << ", \"pixels\": " << cam.pixels << ", \"near\": " << Num(cam.near)
        << ", \"far\": " << Num(cam.far) << "},\n"
        << "  \"light\": {\"position\": " << Point(scene.wsLight) << "},\n"
        << "  \"lexels\": " << scene.lexels << ",\n"
        << "  \"decision_pixels\": " << scene.DecisionPixels() << ",\n";
    if (scene.frusta)
        out << "  \"frusta\": {\"max\": " << scene.frusta->max
            << ", \"budget\": " << scene.frusta->budget << ", \"metric\": \""
            << MetricName(scene.frusta->metric) << "\"},\n";
    out << "  \"geometry\": [\n";
    for (std::size_t i = 0; i < scene.geometry.size(); ++i) {
        out << "    [";
        for (std::size_t j = 0; j < scene.geometry[i].size(); ++j)
            out << (j ? ", " : "") << Point(scene.geometry[i][j]);
        out << "]" << (i + 1 < scene.geometry.size() ? "," : "") << "\n";
    }
    out << "  ]\n}\n";
    return out.str();
}

std::string StoredFitsJson(const std::vector<StoredFit>& fits) {
    std::ostringstream out;
    out << "{\n  \"source\": \"lexel fit-thesis: each case's scene-family parameters and the "
           "agreement of its fitted case file with the published table\",\n  \"fits\": [\n";
    for (std::size_t k = 0; k < fits.size(); ++k) {
        const StoredFit& fit = fits[k];
        const SceneFamily* family = flatland::FindFamily(fit.caseName);
        out << "    {\"case\": " << nlohmann::json(fit.caseName).dump() << ", \"parameters\": {";
        for (std::size_t i = 0; i < fit.parameters.size(); ++i)
            out << (i ? ", " : "") << nlohmann::json(family->parameters[i].name).dump() << ": "
                << Num(fit.parameters[i]);
        out << "},\n     \"worst_angle_deg\": " << Num(fit.worstAngleDeg)
            << ", \"worst_footprint\": " << Num(fit.worstFootprint) << "}"
            << (k + 1 < fits.size() ? "," : "") << "\n";
    }
    out << "  ]\n}\n";
    return out.str();
}

namespace {

std::string ParameterLines(const SceneFamily& family, const std::vector<double>& values) {
    TextTable table({"parameter", "value", "range"});
    for (std::size_t i = 0; i < values.size(); ++i) {
        const auto& p = family.parameters[i];
        std::ostringstream range;
        range << '[' << Significant(p.lo, 3) << ", " << Significant(p.hi, 3) << ']';
        table.AddRow({p.name, Significant(values[i], 6), range.str()});
    }
    std::ostringstream out;
    out << table.Render();
    for (const auto& p : family.parameters)
        out << WrapText("  " + p.name + ": " + p.meaning, kTerminalColumns, "    ");
    return out.str();
}

std::string ErrorText(const ComparedNumber& n) {
    std::ostringstream out;
    out << (n.error >= 0 ? "+" : "");
    if (n.quantity == Quantity::kAngle)
        out << Fixed(n.error, 2) << "°";
    else
        out << Percent(n.error);
    return out.str();
}

TextTable NumbersTable(const flatland::PublishedTable& table,
                       const std::vector<ComparedNumber>& numbers) {
    TextTable out({"row", "method", "quantity", "published", "fitted", "error", "ok"});
    for (const auto& n : numbers) {
        const auto& row = table.rows[n.row];
        const bool ok = flatland::NormalizedError(n, {}) <= 1.0;
        out.AddRow({row.label,
                    n.quantity == Quantity::kTwoFrustaMean ? table.splitMethod : row.method,
                    flatland::QuantityName(n.quantity), Significant(n.published, 4),
                    Significant(n.value, 4), ErrorText(n), ok ? "yes" : "NO"});
    }
    return out;
}

std::string NumberName(const flatland::PublishedTable& table, const ComparedNumber& n) {
    return table.rows[n.row].label + " (" + table.rows[n.row].method + ") " +
           flatland::QuantityName(n.quantity);
}

std::string DroppedText(const CaseFit& fit) {
    TextTable out({"left out", "its error / tolerance", "worst of the rest / tolerance"});
    for (const auto& d : fit.dropped)
        out.AddRow({NumberName(fit.table, fit.best.numbers[d.number]),
                    Fixed(d.droppedNormalized, 2), Fixed(d.restWorstNormalized, 2)});
    return "Which numbers cannot be met together (refit with each left out; ≤ 1.00 means the "
           "rest are met):\n" +
           out.Render() + '\n';
}

}  // namespace

std::string FitText(const CaseFit& fit) {
    std::ostringstream out;
    out << fit.thesis.title << " — family " << fit.family->name << ", " << fit.best.evaluations
        << " scenes measured in " << Fixed(fit.seconds, 1) << " s\n"
        << WrapText(fit.family->layout) << "\n"
        << ParameterLines(*fit.family, fit.best.parameters) << '\n'
        << NumbersTable(fit.table, fit.best.numbers).Render() << '\n'
        << "fitted: " << AgreementLine(fit.best.agreement)
        << " (tolerances 2°, 10%): " << (fit.best.agreement.accepted ? "met" : "NOT met") << "\n"
        << "shipped reconstruction: " << AgreementLine(fit.reconstruction) << "\n\n";
    if (!fit.dropped.empty()) out << DroppedText(fit);
    return out.str();
}

}  // namespace lexel::cases
