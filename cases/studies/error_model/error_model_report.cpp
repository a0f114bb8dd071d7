// The error-model study's outputs (error_model_report.h).
#include "lexel/cases/studies/error_model/error_model_report.h"

#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "lexel/cases/plot/axes.h"
#include "lexel/cases/report/json_number.h"
#include "lexel/cases/report/text_table.h"
#include "lexel/cases/run/sweep.h"

namespace lexel::cases {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

bool Fitted(const ErrorModelSample& s) {
    return s.normal != glm::dvec2(0.0) && s.inRange && std::isfinite(s.predicted) &&
           std::isfinite(s.predictedIsotropic);
}

ErrorModelSummary Summarize(const ErrorModelStudy& study, const std::string& name, bool all,
                            std::size_t method) {
    ErrorModelSummary s;
    s.method = name;
    std::vector<double> x, xIso, y;
    // Per (light, method): Σ predicted, Σ measured.
    std::vector<double> lightX(study.lights.size() * study.methods.size(), 0.0);
    std::vector<double> lightY(lightX.size(), 0.0);
    for (const ErrorModelSample& e : study.samples) {
        if (!all && e.method != method) continue;
        ++s.samples;
        if (e.normal == glm::dvec2(0.0)) ++s.withoutNormal;
        if (!e.inRange) {
            ++s.outOfRange;
            s.measuredOutOfRange += e.measured;
        }
        if (!Fitted(e)) continue;
        lightX[e.light * study.methods.size() + e.method] += e.predicted;
        lightY[e.light * study.methods.size() + e.method] += e.measured;
        x.push_back(e.predicted);
        xIso.push_back(e.predictedIsotropic);
        y.push_back(e.measured);
        s.predicted += e.predicted;
        s.measured += e.measured;
    }
    s.fit = FitLine(x, y);
    s.fitIsotropic = FitLine(xIso, y);
    std::vector<double> perLightX, perLightY;
    for (std::size_t i = 0; i < lightX.size(); ++i) {
        if (!all && i % study.methods.size() != method) continue;
        if (study.samplesPerLight[i / study.methods.size()] == 0) continue;
        perLightX.push_back(lightX[i]);
        perLightY.push_back(lightY[i]);
    }
    s.fitPerLight = FitLine(perLightX, perLightY);
    for (std::size_t m = 0; m < study.totals.size(); ++m)
        if (all || m == method) s.totals += study.totals[m];
    return s;
}

nlohmann::json FitJson(const LineFit& f) {
    return {{"slope", FiniteOrNull(f.slope)},
            {"intercept", FiniteOrNull(f.intercept)},
            {"r", FiniteOrNull(f.r)},
            {"points", f.points}};
}

using plot::Rgb;
using plot::SetColour;

void Text(cairo_t* cr, double x, double y, const std::string& text, double alignX = 0.0) {
    plot::ShowBaselineText(cr, x, y, text, alignX);
}

}  // namespace

LineFit FitLine(std::span<const double> x, std::span<const double> y) {
    LineFit f;
    f.points = std::min(x.size(), y.size());
    if (f.points < 2) return {kNaN, kNaN, kNaN, f.points};
    const double n = static_cast<double>(f.points);
    double mx = 0.0, my = 0.0;
    for (std::size_t i = 0; i < f.points; ++i) mx += x[i], my += y[i];
    mx /= n;
    my /= n;
    double sxx = 0.0, syy = 0.0, sxy = 0.0;
    for (std::size_t i = 0; i < f.points; ++i) {
        sxx += (x[i] - mx) * (x[i] - mx);
        syy += (y[i] - my) * (y[i] - my);
        sxy += (x[i] - mx) * (y[i] - my);
    }
    if (!(sxx > 0.0)) return {kNaN, kNaN, kNaN, f.points};
    f.slope = sxy / sxx;
    f.intercept = my - f.slope * mx;
    f.r = syy > 0.0 ? sxy / std::sqrt(sxx * syy) : kNaN;
    return f;
}

double ErrorModelSummary::ExplainedShare() const {
    return totals.misclassified > 0.0 ? totals.explained / totals.misclassified : kNaN;
}

double ErrorModelSummary::UncoveredShare() const {
    return totals.misclassified > 0.0 ? totals.uncovered / totals.misclassified : kNaN;
}

std::vector<ErrorModelSummary> SummarizeErrorModel(const ErrorModelStudy& study) {
    std::vector<ErrorModelSummary> out;
    for (std::size_t m = 0; m < study.methods.size(); ++m)
        out.push_back(Summarize(study, study.methods[m], false, m));
    out.push_back(Summarize(study, "all", true, 0));
    return out;
}

std::vector<ErrorModelBin> BinErrorModel(const ErrorModelStudy& study) {
    constexpr int kLowest = -5;
    std::vector<ErrorModelBin> bins;
    for (const ErrorModelSample& e : study.samples) {
        if (!Fitted(e)) continue;
        const int k = e.predicted > 0.0
                          ? std::max(kLowest, static_cast<int>(std::floor(std::log2(e.predicted))))
                          : kLowest;
        const auto index = static_cast<std::size_t>(k - kLowest);
        if (bins.size() <= index) bins.resize(index + 1);
        ErrorModelBin& b = bins[index];
        ++b.samples;
        b.predictedMean += e.predicted;
        b.measuredMean += e.measured;
    }
    for (std::size_t i = 0; i < bins.size(); ++i) {
        bins[i].lo = i == 0 ? 0.0 : std::ldexp(1.0, static_cast<int>(i) + kLowest);
        bins[i].hi = std::ldexp(1.0, static_cast<int>(i) + kLowest + 1);
        if (bins[i].samples == 0) continue;
        bins[i].predictedMean /= static_cast<double>(bins[i].samples);
        bins[i].measuredMean /= static_cast<double>(bins[i].samples);
    }
    std::erase_if(bins, [](const ErrorModelBin& b) { return b.samples == 0; });
    return bins;
}

std::string ErrorModelCsv(const ErrorModelStudy& study) {
    std::ostringstream out;
    out << "light,method,sample,readback_x,readback_y,normal_x,normal_y,predicted,"
           "predicted_isotropic,measured,in_range\n";
    const auto width = static_cast<std::uint32_t>(study.readback.width);
    for (const ErrorModelSample& e : study.samples)
        out << e.light << ',' << CsvText(study.methods[e.method]) << ',' << e.sample << ','
            << e.pixel % width << ',' << e.pixel / width << ',' << CsvNumber(e.normal.x) << ','
            << CsvNumber(e.normal.y) << ',' << CsvNumber(e.predicted) << ','
            << CsvNumber(e.predictedIsotropic) << ',' << CsvNumber(e.measured) << ','
            << (e.inRange ? 1 : 0) << '\n';
    return out.str();
}

nlohmann::json ErrorModelJson(const ErrorModelStudy& study) {
    nlohmann::json methods = nlohmann::json::array();
    for (const ErrorModelSummary& s : SummarizeErrorModel(study))
        methods.push_back(
            {{"method", s.method},
             {"fit", FitJson(s.fit)},
             {"fit_isotropic", FitJson(s.fitIsotropic)},
             {"fit_per_light", FitJson(s.fitPerLight)},
             {"samples", s.samples},
             {"samples_without_normal", s.withoutNormal},
             {"samples_out_of_range", s.outOfRange},
             {"measured_pixels_out_of_range", FiniteOrNull(s.measuredOutOfRange)},
             {"predicted_pixels", FiniteOrNull(s.predicted)},
             {"measured_pixels", FiniteOrNull(s.measured)},
             {"misclassified_pixels", FiniteOrNull(s.totals.misclassified)},
             {"explained_pixels", FiniteOrNull(s.totals.explained)},
             {"explained_share", FiniteOrNull(s.ExplainedShare())},
             {"uncovered_pixels", FiniteOrNull(s.totals.uncovered)},
             {"uncovered_share", FiniteOrNull(s.UncoveredShare())},
             {"single_phase_pixels", FiniteOrNull(s.totals.singlePhase)},
             {"false_shadow_pixels", FiniteOrNull(s.totals.falseShadow)},
             {"floor_pixels", FiniteOrNull(s.totals.onFloor)},
             {"off_floor_false_shadow_pixels", FiniteOrNull(s.totals.falseShadowOffFloor)}});
    std::size_t withSamples = 0;
    for (std::size_t n : study.samplesPerLight) withSamples += n > 0;
    nlohmann::json bins = nlohmann::json::array();
    for (const ErrorModelBin& b : BinErrorModel(study))
        bins.push_back({{"predicted_lo", b.lo},
                        {"predicted_hi", b.hi},
                        {"samples", b.samples},
                        {"predicted_mean", b.predictedMean},
                        {"measured_mean", b.measuredMean}});
    return {{"case", study.caseName},
            {"lights", study.lights.size()},
            {"lights_with_samples", withSamples},
            {"phases", study.phases},
            {"readback", {study.readback.width, study.readback.height}},
            {"frame", {study.frame.width, study.frame.height}},
            {"max_assign_radius_readback_pixels", kMaxAssignRadius},
            {"seconds", study.seconds},
            {"methods", methods},
            {"bins", bins}};
}

std::string ErrorModelText(const ErrorModelStudy& study) {
    std::ostringstream out;
    std::size_t withSamples = 0;
    for (std::size_t n : study.samplesPerLight) withSamples += n > 0;
    out << "error model, " << study.caseName << ": " << study.lights.size() << " lights ("
        << withSamples << " with boundary samples), " << study.phases << " phases\n";
    out << "measured = slope * predicted + intercept per boundary sample (frame pixels)\n";
    out << std::left << std::setw(18) << "method" << std::right << std::setw(9) << "samples"
        << std::setw(9) << "slope" << std::setw(11) << "intercept" << std::setw(8) << "r"
        << std::setw(10) << "r (iso)" << std::setw(11) << "explained" << std::setw(11)
        << "uncovered" << std::setw(13) << "light slope" << std::setw(9) << "light r" << '\n';
    for (const ErrorModelSummary& s : SummarizeErrorModel(study))
        out << std::left << std::setw(18) << s.method << std::right << std::setw(9) << s.fit.points
            << std::setw(9) << Fixed(s.fit.slope, 3) << std::setw(11) << Fixed(s.fit.intercept, 3)
            << std::setw(8) << Fixed(s.fit.r, 3) << std::setw(10) << Fixed(s.fitIsotropic.r, 3)
            << std::setw(10) << Fixed(100.0 * s.ExplainedShare(), 1) << "%" << std::setw(10)
            << Fixed(100.0 * s.UncoveredShare(), 1) << "%" << std::setw(13)
            << Fixed(s.fitPerLight.slope, 3) << std::setw(9) << Fixed(s.fitPerLight.r, 3) << '\n';
    out << "where the misclassified pixels lie (phase means summed over the lights):\n"
        << std::left << std::setw(18) << "method" << std::right << std::setw(14) << "misclassified"
        << std::setw(10) << "on floor" << std::setw(11) << "off floor" << std::setw(15)
        << "false shadow" << std::setw(24) << "false shadow off floor" << '\n';
    for (const ErrorModelSummary& s : SummarizeErrorModel(study))
        out << std::left << std::setw(18) << s.method << std::right << std::setw(14)
            << Fixed(s.totals.misclassified, 1) << std::setw(10) << Fixed(s.totals.onFloor, 1)
            << std::setw(11) << Fixed(s.totals.misclassified - s.totals.onFloor, 1) << std::setw(15)
            << Fixed(s.totals.falseShadow, 1) << std::setw(24)
            << Fixed(s.totals.falseShadowOffFloor, 1) << '\n';
    out << "all methods binned by prediction (frame pixels):\n"
        << std::right << std::setw(20) << "predicted in" << std::setw(9) << "samples"
        << std::setw(11) << "predicted" << std::setw(10) << "measured" << std::setw(8) << "ratio"
        << '\n';
    for (const ErrorModelBin& b : BinErrorModel(study))
        out << std::setw(20) << ("[" + Significant(b.lo, 3) + ", " + Significant(b.hi, 3) + ")")
            << std::setw(9) << b.samples << std::setw(11) << Fixed(b.predictedMean, 3)
            << std::setw(10) << Fixed(b.measuredMean, 3) << std::setw(8)
            << Fixed(b.measuredMean / b.predictedMean, 3) << '\n';
    return out.str();
}

namespace {

// The scatter plot's square of predicted against measured band widths: [0, hi] on both axes,
// gridded every `step` (frame pixels), drawn at (left, top) in a plotW × plotH box (image pixels).
struct ScatterFrame {
    double left = 80, top = 50, plotW = 700, plotH = 570;
    double hi = 1.0, step = 1.0;
    double X(double v) const { return left + plotW * v / hi; }
    double Y(double v) const { return top + plotH * (1.0 - v / hi); }
};

ScatterFrame FrameOf(const ErrorModelStudy& study) {
    ScatterFrame frame;
    double hi = 0.0;
    for (const ErrorModelSample& e : study.samples)
        if (Fitted(e)) hi = std::max({hi, e.predicted, e.measured});
    if (!(hi > 0.0)) hi = 1.0;
    frame.step = plot::NiceStepAtLeast(hi);
    frame.hi = std::ceil(hi / frame.step) * frame.step;
    return frame;
}

void DrawGrid(cairo_t* cr, const ScatterFrame& f) {
    for (double v = 0.0; v <= f.hi * (1 + 1e-9); v += f.step) {
        plot::GridLine(cr, f.X(v), f.top, f.X(v), f.top + f.plotH);
        plot::GridLine(cr, f.left, f.Y(v), f.left + f.plotW, f.Y(v));
        cairo_set_source_rgb(cr, 0, 0, 0);
        Text(cr, f.X(v), f.top + f.plotH + 16, Significant(v, 4), 0.5);
        Text(cr, f.left - 6, f.Y(v) + 4, Significant(v, 4), 1.0);
    }
}

// The samples, one colour per method, then y = x (dashed) and the pooled fit, clipped to the box.
void DrawSamples(cairo_t* cr, const ScatterFrame& f, const ErrorModelStudy& study,
                 const ErrorModelSummary& pooled) {
    cairo_save(cr);
    cairo_rectangle(cr, f.left, f.top, f.plotW, f.plotH);
    cairo_clip(cr);
    for (const ErrorModelSample& e : study.samples) {
        if (!Fitted(e)) continue;
        SetColour(cr, plot::PaletteColour(e.method), 0.35);
        cairo_arc(cr, f.X(e.predicted), f.Y(e.measured), 2.0, 0, 2 * M_PI);
        cairo_fill(cr);
    }
    const double dashes[] = {6.0, 4.0};
    cairo_set_source_rgb(cr, 0.3, 0.3, 0.3);
    cairo_set_line_width(cr, 1.2);
    cairo_set_dash(cr, dashes, 2, 0);
    cairo_move_to(cr, f.X(0), f.Y(0));
    cairo_line_to(cr, f.X(f.hi), f.Y(f.hi));
    cairo_stroke(cr);
    cairo_set_dash(cr, nullptr, 0, 0);
    if (std::isfinite(pooled.fit.slope)) {
        cairo_set_source_rgb(cr, 0, 0, 0);
        cairo_set_line_width(cr, 2.0);
        cairo_move_to(cr, f.X(0), f.Y(pooled.fit.intercept));
        cairo_line_to(cr, f.X(f.hi), f.Y(pooled.fit.intercept + pooled.fit.slope * f.hi));
        cairo_stroke(cr);
    }
    cairo_restore(cr);
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_set_line_width(cr, 1.2);
    cairo_rectangle(cr, f.left, f.top, f.plotW, f.plotH);
    cairo_stroke(cr);
}

void DrawTitleAndAxes(cairo_t* cr, const ScatterFrame& f, const ErrorModelStudy& study) {
    cairo_set_font_size(cr, 15);
    Text(cr, f.left + f.plotW / 2, 28,
         "Error model, " + study.caseName + ": " + std::to_string(study.lights.size()) +
             " lights, " + std::to_string(study.phases) + " phases",
         0.5);
    cairo_set_font_size(cr, 13);
    Text(cr, f.left + f.plotW / 2, f.top + f.plotH + 40,
         "predicted band at the sample (frame pixels, ExpectedBandWidth)", 0.5);
    cairo_save(cr);
    cairo_translate(cr, 22, f.top + f.plotH / 2);
    cairo_rotate(cr, -M_PI / 2);
    Text(cr, 0, 0, "measured misclassified pixels nearest the sample (phase mean)", 0.5);
    cairo_restore(cr);
}

// Under the plot: one line per method's fit, the pooled one last in black.
void DrawLegend(cairo_t* cr, const ScatterFrame& f,
                const std::vector<ErrorModelSummary>& summaries) {
    cairo_set_font_size(cr, 12);
    double y = f.top + f.plotH + 64;
    for (std::size_t m = 0; m < summaries.size(); ++m) {
        const ErrorModelSummary& s = summaries[m];
        const bool isPooled = m + 1 == summaries.size();
        SetColour(cr, isPooled ? Rgb{0, 0, 0} : plot::PaletteColour(m));
        cairo_arc(cr, f.left + 16, y - 4, 4, 0, 2 * M_PI);
        cairo_fill(cr);
        cairo_set_source_rgb(cr, 0, 0, 0);
        Text(cr, f.left + 26, y,
             (isPooled ? "fit, all: " : s.method + ": ") + "slope " + Fixed(s.fit.slope, 3) +
                 ", intercept " + Fixed(s.fit.intercept, 3) + ", r " + Fixed(s.fit.r, 3) +
                 ", explained " + Fixed(100.0 * s.ExplainedShare(), 1) + "%; per light: slope " +
                 Fixed(s.fitPerLight.slope, 3) + ", r " + Fixed(s.fitPerLight.r, 3));
        y += 17;
    }
    Text(cr, f.left + 26, y, "dashed: measured = predicted");
}

}  // namespace

void WriteErrorModelPlot(const std::string& pngPath, const ErrorModelStudy& study) {
    const std::vector<ErrorModelSummary> summaries = SummarizeErrorModel(study);
    const int width = 820, height = 690 + 17 * static_cast<int>(summaries.size() + 1);
    const ScatterFrame frame = FrameOf(study);
    plot::RenderPng(pngPath, width, height, [&](cairo_t* cr) {
        plot::SetFont(cr, 12);
        DrawGrid(cr, frame);
        DrawSamples(cr, frame, study, summaries.back());
        DrawTitleAndAxes(cr, frame, study);
        DrawLegend(cr, frame, summaries);
    });
}

}  // namespace lexel::cases
