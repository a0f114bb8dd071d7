#include "lexel/cases/report/sweep_report.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>
#include <sstream>

#include "lexel/cases/plot/curve_plot.h"
#include "lexel/cases/report/columns.h"
#include "lexel/cases/report/json_number.h"
#include "lexel/cases/report/text_table.h"
#include "lexel/solvers/statistics.h"
#include "lexel/spatial/harness/sub_texel_phase.h"
#include "lexel/spatial/methods/method_info.h"

namespace lexel::cases {
namespace {

using spatial::Light;

// A table over some of the sweep's methods: indices into SweepResult::methods in display order,
// and the reference the percentages are taken against.
struct View {
    std::vector<std::size_t> methods;
    std::size_t reference = 0;
};

bool Contains(const std::vector<std::string>& names, const std::string& name) {
    return std::find(names.begin(), names.end(), name) != names.end();
}

// The methods of `names` the sweep ran, in the order of `names`; the reference is `preferred`
// when it ran, else the first of them. nullopt when none ran.
std::optional<View> ViewOf(const SweepResult& r, const std::vector<std::string>& names,
                           const std::string& preferred) {
    View view;
    for (const std::string& name : names)
        for (std::size_t m = 0; m < r.methods.size(); ++m)
            if (r.methods[m] == name) view.methods.push_back(m);
    if (view.methods.empty()) return std::nullopt;
    view.reference = view.methods.front();
    for (std::size_t m : view.methods)
        if (r.methods[m] == preferred) view.reference = m;
    return view;
}

// Table 1 as published: the report-faithful methods in its column order, against optimal-report,
// then any other method fitted to the view frustum as the report's are (tsm-report).
std::optional<View> ReportView(const SweepResult& r) {
    std::vector<std::string> names = spatial::ReportMethodNames();
    for (const std::string& m : r.methods)
        if (!Contains(names, m) && spatial::IsFrustumFittedMethod(m)) names.push_back(m);
    return ViewOf(r, names, spatial::kReportOptimalMethod);
}

// The fair comparison, against optimal: its methods, then any other single map that is not
// report-only.
std::optional<View> FairView(const SweepResult& r) {
    std::vector<std::string> names = spatial::FairMethodNames();
    for (const std::string& m : r.methods)
        if (!Contains(names, m) && !Contains(spatial::ReportMethodNames(), m) &&
            !spatial::IsFrustumFittedMethod(m) && !spatial::IsPartitionedMethod(m) &&
            !spatial::IsVirtualMethod(m))
            names.push_back(m);
    return ViewOf(r, names, spatial::kOptimalMethod);
}

// The equal-texel table: optimal (one map) against the partitioned methods and the virtual
// shadow maps, when any ran.
std::optional<View> EqualTexelView(const SweepResult& r) {
    std::vector<std::string> partitioned =
        spatial::MethodNamesOf(spatial::MethodFamily::kPartitioned);
    for (const std::string& m : spatial::MethodNamesOf(spatial::MethodFamily::kVirtual))
        partitioned.push_back(m);
    if (std::none_of(r.methods.begin(), r.methods.end(), [](const std::string& m) {
            return spatial::IsPartitionedMethod(m) || spatial::IsVirtualMethod(m);
        }))
        return std::nullopt;
    std::vector<std::string> names = {spatial::kOptimalMethod};
    names.insert(names.end(), partitioned.begin(), partitioned.end());
    for (const std::string& m : r.methods)  // the opt-in ones (sdsm-optimal-h) too
        if (spatial::IsPartitionedMethod(m) && !Contains(names, m)) names.push_back(m);
    return ViewOf(r, names, spatial::kOptimalMethod);
}

// The lights in a method's worst 10% (at least one), ties broken by light index.
std::vector<std::size_t> WorstLights(const SweepResult& r, std::size_t method) {
    std::vector<std::size_t> order(r.lights.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return r.cells[a][method].misclassifiedMean > r.cells[b][method].misclassifiedMean;
    });
    const std::size_t keep = std::max<std::size_t>(1, (r.lights.size() + 5) / 10);
    order.resize(std::min(keep, order.size()));
    return order;
}

struct Row {
    std::string set;           // "all" or the ranking method
    std::vector<double> mean;  // per method of the sweep: mean misclassified over the set
};

std::vector<double> MeanOver(const SweepResult& r, const std::vector<std::size_t>& lights) {
    std::vector<double> mean(r.methods.size(), 0.0);
    for (std::size_t m = 0; m < r.methods.size(); ++m) {
        for (std::size_t l : lights) mean[m] += r.cells[l][m].misclassifiedMean;
        mean[m] /= std::max<std::size_t>(1, lights.size());
    }
    return mean;
}

std::vector<std::size_t> AllLights(const SweepResult& r) {
    std::vector<std::size_t> all(r.lights.size());
    std::iota(all.begin(), all.end(), 0);
    return all;
}

// Table 1's rows: all lights, then each method's worst 10% when the sweep has enough lights for
// that to be more than one or two of them (kWorstRowsMinLights).
std::vector<Row> Table1Rows(const SweepResult& r, const View& view) {
    std::vector<Row> rows = {{"all", MeanOver(r, AllLights(r))}};
    if (r.lights.size() < kWorstRowsMinLights) return rows;
    for (std::size_t m : view.methods)
        rows.push_back({r.methods[m], MeanOver(r, WorstLights(r, m))});
    return rows;
}

double PercentMore(double value, double reference) {
    if (reference == 0.0) return value == 0.0 ? 0.0 : std::numeric_limits<double>::infinity();
    return 100.0 * (value - reference) / reference;
}

std::string Cell(double value, double reference, bool isReference) {
    if (isReference) return Fixed(value, 0) + " (0)";
    const double pct = PercentMore(value, reference);
    return Fixed(value, 0) + " (" + (pct >= 0 ? "+" : "") + Fixed(pct, 2) + "%)";
}

// Our name of a method in the report's Table 1: its optimal is our optimal-report.
std::string PublishedName(const std::string& ours) {
    return ours == spatial::kReportOptimalMethod ? spatial::kOptimalMethod : ours;
}

// The report's cells for our set and methods, or empty where it has none.
std::vector<std::string> ReportCells(const ReportTable1& report, const std::string& set,
                                     const SweepResult& r, const View& view) {
    std::vector<std::string> cells;
    const ReportTable1::Row* row = report.Find(PublishedName(set));
    if (!row) return cells;
    for (std::size_t m : view.methods) {
        const std::string name = PublishedName(r.methods[m]);
        const std::optional<std::size_t> c = report.Column(name);
        if (!c) {
            cells.push_back("");
            continue;
        }
        cells.push_back(Fixed(row->misclassified[*c], 0) +
                        (name == spatial::kOptimalMethod
                             ? " (0)"
                             : " (+" + Fixed(row->percentMore[*c], 2) + "%)"));
    }
    return cells;
}

// Whether two cells of one light differ beyond the noise of their phase means: by more than 1.96
// standard errors of the difference (independent phase means). With one phase there is no noise
// estimate and `fallback` decides: any difference (the wins), or one above 2% of the larger
// count and a pixel (the proxy's orderings, as the concordance audit counts them).
enum class Unmeasured { kAnyDifference, kTwoPercent };
bool DiffersBeyondNoise(const SweepCell& a, const SweepCell& b, int phases, Unmeasured fallback) {
    const double d = std::abs(a.misclassifiedMean - b.misclassifiedMean);
    if (phases > 1)
        return DifferBeyondNoise(a.misclassifiedMean, a.misclassifiedError, b.misclassifiedMean,
                                 b.misclassifiedError);
    if (fallback == Unmeasured::kAnyDifference) return d > 0.0;
    return d > std::max(1.0, 0.02 * std::max(a.misclassifiedMean, b.misclassifiedMean));
}

struct MethodSummary {
    double meanMisclassified = 0.0;
    double ci95 = std::numeric_limits<double>::quiet_NaN();  // 95% half-width over the lights
    // The 95% half-width of the paired difference against the reference (per light this −
    // reference; its mean is the difference of the means) as % of the reference's mean (NaN for
    // the reference itself).
    double pairedPercentCi95 = std::numeric_limits<double>::quiet_NaN();
    double losingPercent = 0.0;  // % of lights where the reference has fewer (beyond the noise)
    // The residual noise of the per-light phase means: Σ standard errors / Σ means (0 for one
    // phase).
    double residualNoise = 0.0;
    double meanH = 0.0;  // over lights where h is finite
    std::int64_t infiniteH = 0;
    double meanMs = 0.0;
    // % of lights with fewer misclassified pixels than the reference, beyond the noise
    // (DiffersBeyondNoise; one phase: any difference).
    double beatingPercent = 0.0;
    // % of the lights where the two differ in misclassified pixels (DiffersBeyondNoise; one
    // phase: by 2% and a pixel) and in h on which h orders this method and the reference the same
    // way (is h the right proxy?); NaN for the reference itself or when no light qualifies.
    double hAgreesPercent = std::numeric_limits<double>::quiet_NaN();
    double eAgreesPercent = std::numeric_limits<double>::quiet_NaN();  // the same for e
    // Mean over the lights with 0 < h < inf of the part of h from grazing samples.
    double grazingShare = 0.0;
    double meanFootprint = 0.0;        // mean over lights of the per-pixel mean σ₁(J⁻¹)
    double maxFootprint = 0.0;         // max over lights and pixels
    double meanUncovered = 0.0;        // counted pixels no map covers, mean per light
    std::int64_t emptyPartitions = 0;  // over all lights
    int cascades = 1;                  // maps per light (the most over lights)
    // Lloyd's storage factor measured per light (SweepCell::storageFactor): median and max over
    // the lights (the median: one number for the hemisphere that a few lights near the view
    // axis, where every single map needs far more, do not dominate).
    double medianStorage = 0.0, maxStorage = 0.0;
    // Virtual shadow maps: mean pages requested, resident and dropped per light, mean LOD bias
    // (NaN for the other methods).
    double meanPagesRequested = std::numeric_limits<double>::quiet_NaN();
    double meanPagesResident = std::numeric_limits<double>::quiet_NaN();
    double meanPagesDropped = std::numeric_limits<double>::quiet_NaN();
    double meanLodBias = std::numeric_limits<double>::quiet_NaN();
    // With shimmer poses: the mean over lights of SweepCell::shimmer (NaN without).
    double meanShimmer = std::numeric_limits<double>::quiet_NaN();
};

// Whether h ranks two cells at all: both finite and not equal (a tie at h = 0, lights without
// boundary samples, orders nothing).
bool Orders(double a, double b) { return std::isfinite(a) && std::isfinite(b) && a != b; }

// Of the lights where the energy ranks the two cells and their misclassified pixels differ beyond
// the noise (one phase: by 2% and a pixel), the % on which it ranks them as their errors; NaN
// for none.
double AgreesPercent(const SweepResult& r, std::size_t m, std::size_t reference,
                     double SweepCell::*energy) {
    std::size_t differ = 0, agree = 0;
    for (const auto& light : r.cells) {
        const SweepCell& c = light[m];
        const SweepCell& ref = light[reference];
        if (m == reference || !Orders(c.*energy, ref.*energy) ||
            !DiffersBeyondNoise(c, ref, r.phases, Unmeasured::kTwoPercent))
            continue;
        ++differ;
        agree += (c.*energy < ref.*energy) == (c.misclassifiedMean < ref.misclassifiedMean);
    }
    return differ ? 100.0 * agree / differ : std::numeric_limits<double>::quiet_NaN();
}

// The means over lights, their 95% half-width, and the paired difference against the reference.
void SummarizeMeans(const SweepResult& r, std::size_t m, std::size_t reference,
                    MethodSummary* out) {
    std::vector<double> values, differences;
    double refSum = 0.0, errors = 0.0;
    for (const auto& light : r.cells) {
        values.push_back(light[m].misclassifiedMean);
        differences.push_back(light[m].misclassifiedMean - light[reference].misclassifiedMean);
        refSum += light[reference].misclassifiedMean;
        errors += light[m].misclassifiedError;
    }
    const double sum = std::accumulate(values.begin(), values.end(), 0.0);
    out->ci95 = MeanInterval95(values).halfWidth;
    const double refMean = refSum / static_cast<double>(std::max<std::size_t>(1, values.size()));
    if (m != reference && refMean > 0.0)
        out->pairedPercentCi95 = 100.0 * MeanInterval95(differences).halfWidth / refMean;
    out->residualNoise = sum > 0.0 ? errors / sum : 0.0;
}

// The median and the largest storage factor over the lights.
void SummarizeStorage(const SweepResult& r, std::size_t m, MethodSummary* out) {
    std::vector<double> storage;
    for (const auto& light : r.cells) storage.push_back(light[m].storageFactor);
    if (storage.empty()) return;
    std::sort(storage.begin(), storage.end());
    const std::size_t half = storage.size() / 2;
    out->medianStorage =
        storage.size() % 2 ? storage[half] : 0.5 * (storage[half - 1] + storage[half]);
    out->maxStorage = storage.back();
}

// A virtual method's pages requested, resident and dropped and its LOD bias, means over the
// lights.
void SummarizePages(const SweepResult& r, std::size_t m, MethodSummary* out) {
    const double lights = static_cast<double>(std::max<std::size_t>(1, r.cells.size()));
    double requested = 0.0, resident = 0.0, dropped = 0.0, bias = 0.0;
    for (const auto& light : r.cells) {
        requested += static_cast<double>(light[m].pagesRequested);
        resident += static_cast<double>(light[m].pagesResident);
        dropped += static_cast<double>(light[m].pagesDropped);
        bias += light[m].lodBias;
    }
    out->meanPagesRequested = requested / lights;
    out->meanPagesResident = resident / lights;
    out->meanPagesDropped = dropped / lights;
    out->meanLodBias = bias / lights;
}

MethodSummary Summarize(const SweepResult& r, std::size_t m, std::size_t reference) {
    MethodSummary out;
    SummarizeMeans(r, m, reference, &out);
    std::size_t finite = 0, positive = 0, beating = 0, losing = 0;
    for (const auto& light : r.cells) {
        const SweepCell& c = light[m];
        const SweepCell& ref = light[reference];
        const bool beyond = DiffersBeyondNoise(c, ref, r.phases, Unmeasured::kAnyDifference);
        if (std::isfinite(c.h) && c.h > 0.0) {
            out.grazingShare += c.hGrazing / c.h;
            ++positive;
        }
        out.meanMisclassified += c.misclassifiedMean;
        if (std::isfinite(c.h)) {
            out.meanH += c.h;
            ++finite;
        } else {
            ++out.infiniteH;
        }
        out.meanMs += c.ms;
        beating += beyond && c.misclassifiedMean < ref.misclassifiedMean;
        losing += beyond && c.misclassifiedMean > ref.misclassifiedMean;
        out.meanFootprint += c.footprintMean;
        out.maxFootprint = std::max(out.maxFootprint, c.footprintMax);
        out.meanUncovered += static_cast<double>(c.uncovered);
        out.emptyPartitions += c.emptyPartitions;
        out.cascades = std::max(out.cascades, c.cascades);
    }
    SummarizeStorage(r, m, &out);
    const double lights = static_cast<double>(std::max<std::size_t>(1, r.cells.size()));
    out.meanMisclassified /= lights;
    out.meanH = finite ? out.meanH / finite : std::numeric_limits<double>::infinity();
    out.meanMs /= lights;
    out.meanFootprint /= lights;
    out.meanUncovered /= lights;
    out.beatingPercent = 100.0 * beating / lights;
    out.losingPercent = 100.0 * losing / lights;
    out.hAgreesPercent = AgreesPercent(r, m, reference, &SweepCell::h);
    out.eAgreesPercent = AgreesPercent(r, m, reference, &SweepCell::e);
    out.grazingShare = positive ? out.grazingShare / positive : 0.0;
    if (!r.cells.empty() && r.cells.front()[m].pagesRequested >= 0) SummarizePages(r, m, &out);
    if (r.shimmerPoses > 1) {
        double shimmer = 0.0;
        for (const auto& light : r.cells) shimmer += light[m].shimmer;
        out.meanShimmer = shimmer / lights;
    }
    return out;
}

// A method's row of a summary table (report, fair, equal-texel): over all lights, or over a
// worst-10% set of Table 1 (its mean and % only; the summary columns are empty there).
struct SummaryRow {
    std::string table;  // "report", "fair" or "equal-texel"
    std::string set;    // "all" or the method ranking the worst 10%
    std::string method;
    double setMean = 0.0;                     // mean misclassified over the set
    double setPercentMore = 0.0;              // ... % more than the reference's over the same set
    std::optional<MethodSummary> summary;     // over all lights; nullopt on a worst-10% row
    std::optional<double> reportPercentMore;  // the report's own % (Table 1), where it has one
    int phases = 1;
    bool isReference = false;
};

// The getter of a MethodSummary field: nothing on a worst-10% row.
template <class T>
std::function<CellValue(const SummaryRow&)> Summary(T MethodSummary::*field) {
    return [field](const SummaryRow& row) -> CellValue {
        if (!row.summary) return {};
        if constexpr (std::is_floating_point_v<T>)
            return CellValue(double((*row.summary).*field));
        else
            return CellValue(std::int64_t((*row.summary).*field));
    };
}

// A mean some sweeps or methods lack (a virtual shadow map's pages, the shimmer): JSON only, left
// out where NaN.
std::function<CellValue(const SummaryRow&)> Measured(double MethodSummary::*field) {
    return [field](const SummaryRow& row) -> CellValue {
        if (!row.summary || std::isnan((*row.summary).*field)) return {};
        return (*row.summary).*field;
    };
}

// The columns of a summary row in `lexel sweep --format json|csv`, in CSV order.
ColumnTable<SummaryRow> SummaryColumns() {
    using S = MethodSummary;
    using R = SummaryRow;
    const auto text = [](std::string R::*field) {
        return [field](const R& r) { return CellValue(r.*field); };
    };
    return {{"table", "", text(&R::table), kCsvColumn},
            {"set", "", text(&R::set), kCsvColumn},
            {"method", "", text(&R::method)},
            {"mean_misclassified", "pixels", [](const R& r) { return CellValue(r.setMean); }},
            {"percent_more", "%", [](const R& r) { return CellValue(r.setPercentMore); }},
            {"percent_lights_beating_reference", "% of lights", Summary(&S::beatingPercent)},
            {"mean_h", "pixels²/texel²", Summary(&S::meanH)},
            {"mean_ms", "ms", Summary(&S::meanMs)},
            {"report_percent_more", "%",
             [](const R& r) {
                 return r.reportPercentMore ? CellValue(*r.reportPercentMore) : CellValue{};
             },
             kCsvColumn},
            {"mean_footprint", "frame pixels/texel", Summary(&S::meanFootprint)},
            {"max_footprint", "frame pixels/texel", Summary(&S::maxFootprint)},
            {"mean_uncovered_pixels", "pixels", Summary(&S::meanUncovered)},
            {"empty_partitions", "partitions", Summary(&S::emptyPartitions)},
            {"median_storage_factor", "texels/pixel", Summary(&S::medianStorage)},
            {"max_storage_factor", "texels/pixel", Summary(&S::maxStorage)},
            {"mean_misclassified_ci95", "pixels", Summary(&S::ci95)},
            {"percent_more_ci95", "%", Summary(&S::pairedPercentCi95)},
            {"percent_lights_reference_beats", "% of lights", Summary(&S::losingPercent)},
            {"phases", "phases",
             [](const R& r) { return r.summary ? CellValue(std::int64_t{r.phases}) : CellValue{}; },
             kCsvColumn},
            {"residual_noise", "fraction", Summary(&S::residualNoise), kJsonColumn},
            {"lights_with_infinite_h", "lights", Summary(&S::infiniteH), kJsonColumn},
            {"percent_lights_h_ranks_as_misclassified", "% of lights", Summary(&S::hAgreesPercent),
             kJsonColumn},
            {"percent_lights_e_ranks_as_misclassified", "% of lights", Summary(&S::eAgreesPercent),
             kJsonColumn},
            {"h_share_at_grazing_samples", "fraction", Summary(&S::grazingShare), kJsonColumn},
            {"maps", "maps", Summary(&S::cascades), kJsonColumn},
            {"mean_pages_requested", "pages", Measured(&S::meanPagesRequested), kJsonColumn,
             JsonNull::kOmit},
            {"mean_pages_resident", "pages", Measured(&S::meanPagesResident), kJsonColumn,
             JsonNull::kOmit},
            {"mean_pages_dropped", "pages", Measured(&S::meanPagesDropped), kJsonColumn,
             JsonNull::kOmit},
            {"mean_lod_bias", "levels", Measured(&S::meanLodBias), kJsonColumn, JsonNull::kOmit},
            {"mean_shimmer", "% of stable pixels per step", Measured(&S::meanShimmer), kJsonColumn,
             JsonNull::kOmit}};
}

// The summary rows of a view over all lights (the reference's % is 0).
std::vector<SummaryRow> SummaryRows(const SweepResult& r, const View& view,
                                    const std::string& table) {
    const MethodSummary reference = Summarize(r, view.reference, view.reference);
    std::vector<SummaryRow> rows;
    for (std::size_t m : view.methods) {
        SummaryRow row;
        row.table = table;
        row.set = "all";
        row.method = r.methods[m];
        row.summary = Summarize(r, m, view.reference);
        row.setMean = row.summary->meanMisclassified;
        row.setPercentMore = PercentMore(row.setMean, reference.meanMisclassified);
        row.phases = r.phases;
        row.isReference = m == view.reference;
        rows.push_back(std::move(row));
    }
    return rows;
}

std::string SetLabel(const std::string& set) {
    return set == "all" ? "all lights" : "worst 10% by " + set;
}

// The label of the report's own rows: its counts are totals over its 500 lights on its scene and
// frame (ours: means per light), so only its percentages compare with ours.
constexpr const char* kPublishedLabel = "  published (report)";

TextTable MisclassifiedTable(const SweepResult& r, const View& view, const ReportTable1& report) {
    std::vector<std::string> header = {"lights"};
    for (std::size_t m : view.methods) header.push_back(r.methods[m]);
    TextTable table(header);
    const bool compareToReport = r.methods[view.reference] == spatial::kReportOptimalMethod;
    for (const Row& row : Table1Rows(r, view)) {
        std::vector<std::string> cells = {SetLabel(row.set)};
        for (std::size_t m : view.methods)
            cells.push_back(Cell(row.mean[m], row.mean[view.reference], m == view.reference));
        table.AddRow(cells);
        if (compareToReport) {
            std::vector<std::string> published = ReportCells(report, row.set, r, view);
            if (!published.empty()) {
                published.insert(published.begin(), kPublishedLabel);
                table.AddRow(published, "published");
            }
        }
    }
    return table;
}

std::string PercentCell(double pct, bool isReference) {
    return isReference ? "0" : (pct >= 0 ? "+" : "") + Fixed(pct, 2) + "%";
}

// "mean ± 95% half-width" (the half-width left out when there is none).
std::string MeanCell(double mean, double ci95) {
    return std::isfinite(ci95) ? Fixed(mean, 1) + " ± " + Fixed(ci95, 1) : Fixed(mean, 1);
}
// The % against the reference with its paired 95% half-width.
std::string PairedCell(double pct, double ci95, bool isReference) {
    if (isReference || !std::isfinite(ci95)) return PercentCell(pct, isReference);
    return (pct >= 0 ? "+" : "") + Fixed(pct, 2) + " ± " + Fixed(ci95, 2) + "%";
}

// The text columns both summary tables share: the mean with its interval, the % against the
// reference with its paired interval, and the % of lights won and lost.
std::vector<TextColumn<SummaryRow>> ComparisonText() {
    const auto lightsPercent = [](double MethodSummary::*field) {
        return [field](const SummaryRow& r) {
            return r.isReference ? std::string("–") : Fixed((*r.summary).*field, 0) + "%";
        };
    };
    return {{"mean\nmisclassified\n(95% CI)",
             [](const SummaryRow& r) {
                 return MeanCell(r.summary->meanMisclassified, r.summary->ci95);
             }},
            {"% more\nthan ref\n(95% CI)",
             [](const SummaryRow& r) {
                 return PairedCell(r.setPercentMore, r.summary->pairedPercentCi95, r.isReference);
             }},
            {"% lights\nbeating\nref", lightsPercent(&MethodSummary::beatingPercent)},
            {"% lights\nref\nbeats", lightsPercent(&MethodSummary::losingPercent)}};
}

// A share in % to no decimals; "–" where undefined.
std::string PercentOrDash(const CellValue& value) {
    const double* x = std::get_if<double>(&value);
    return !x || std::isnan(*x) ? "–" : Fixed(*x, 0) + "%";
}

// Mean misclassified, % more than the reference, % of lights beating it, mean h and time.
TextTable SummaryTable(const SweepResult& r, const View& view) {
    const ColumnTable<SummaryRow> columns = SummaryColumns();
    std::vector<TextColumn<SummaryRow>> text = {TextColumnOf(columns, "method", "method")};
    for (TextColumn<SummaryRow>& c : ComparisonText()) text.push_back(std::move(c));
    const std::vector<TextColumn<SummaryRow>> rest = {
        TextColumnOf(columns, "mean_h", "mean h\n(eq. 6)", SignificantText(5)),
        TextColumnOf(columns, "lights_with_infinite_h", "lights\nwith\nh = inf"),
        TextColumnOf(columns, "percent_lights_h_ranks_as_misclassified", "h orders\nas errors",
                     PercentOrDash),
        TextColumnOf(columns, "percent_lights_e_ranks_as_misclassified", "e orders\nas errors",
                     PercentOrDash),
        {"grazing\nshare\nof h",
         [](const SummaryRow& row) { return Fixed(100.0 * row.summary->grazingShare, 0) + "%"; }},
        TextColumnOf(columns, "median_storage_factor", "median\nstorage\nfactor"),
        TextColumnOf(columns, "mean_ms", "mean ms\nper light", FixedText(3))};
    text.insert(text.end(), rest.begin(), rest.end());
    return TextTableOf(text, SummaryRows(r, view, ""));
}

// At equal texels: mean misclassified, % more than optimal, % of lights beating it, the
// footprints σ₁(J⁻¹), uncovered pixels, empty partitions, time. The terminal leaves out the
// largest σ₁(J⁻¹) (it comes from grazing pixels) to fit kTerminalColumns.
TextTable EqualTexelTable(const SweepResult& r, const View& view, bool terminal) {
    const ColumnTable<SummaryRow> columns = SummaryColumns();
    std::vector<TextColumn<SummaryRow>> text = {TextColumnOf(columns, "method", "method"),
                                                TextColumnOf(columns, "maps", "maps")};
    for (TextColumn<SummaryRow>& c : ComparisonText()) text.push_back(std::move(c));
    text.push_back(TextColumnOf(columns, "mean_footprint", "mean\nσ1(J⁻¹)"));
    if (!terminal) text.push_back(TextColumnOf(columns, "max_footprint", "max\nσ1(J⁻¹)"));
    const std::vector<TextColumn<SummaryRow>> rest = {
        TextColumnOf(columns, "mean_uncovered_pixels", "uncovered\npixels\n(mean)", FixedText(1)),
        TextColumnOf(columns, "empty_partitions", "empty\nparti-\ntions"),
        TextColumnOf(columns, "median_storage_factor", "median\nstorage\nfactor"),
        TextColumnOf(columns, "mean_h", "mean h\n(eq. 6)", SignificantText(5)),
        TextColumnOf(columns, "mean_ms", "mean ms\nper light", FixedText(3))};
    text.insert(text.end(), rest.begin(), rest.end());
    return TextTableOf(text, SummaryRows(r, view, ""));
}

std::string Lights(const SweepResult& r) {
    std::size_t point = 0;
    for (const Light& l : r.lights) point += l.type == Light::Type::kPoint;
    const std::size_t directional = r.lights.size() - point;
    std::ostringstream out;
    if (point) out << point << " point";
    if (point && directional) out << " and ";
    if (directional) out << directional << " directional";
    out << (r.lights.size() == 1 ? " light" : " lights");
    return out.str();
}

// What the summary tables' columns mean (every section that has one says it).
constexpr const char* kSummaryColumns =
    "Columns: the mean misclassified pixels per light with its 95% confidence interval over the "
    "lights; how many % more than the reference (ref), with the 95% interval of the paired "
    "per-light difference; the % of lights on which the method misclassifies fewer pixels than "
    "the reference, and more, each counting only differences beyond the phase noise (see "
    "below); the mean energy h of the report's eq. (6), which Algorithm 1 minimizes (over the "
    "lights where it is finite), and the lights where it is infinite; h orders as errors: of "
    "the lights where the method and the reference differ in h and in misclassified pixels "
    "beyond the noise, the % on which h ranks them the same way (is h the right proxy?); e "
    "orders as errors: the same for the edge energy e that `optimal` minimizes; the "
    "part of h from boundary samples the light grazes (mean over the lights with 0 < h < inf); "
    "Lloyd et al. 2006's storage factor as measured (median over the lights); the time to "
    "compute the light matrix.";

// What "beyond the noise" means for this sweep, and how large the noise is.
std::string PhaseNote(const SweepResult& r) {
    if (r.phases <= 1)
        return "Each light's count is one measurement of each map (one sub-texel phase; "
               "--phases K averages K): a phase alone moves a light's count by 5-15%, so the "
               "wins count any difference and the h orderings differences above 2% and a pixel, "
               "and neither is beyond the noise.";
    double errors = 0.0, sum = 0.0, phases = 0.0;
    std::size_t raised = 0, unsettled = 0, cells = 0;
    std::vector<double> relative;  // per light and method with a mean of at least one pixel
    for (const auto& light : r.cells)
        for (const SweepCell& c : light) {
            errors += c.misclassifiedError;
            sum += c.misclassifiedMean;
            phases += c.phases;
            raised += c.phases > r.phases;
            unsettled += !spatial::PhaseMeanSettled({c.misclassifiedMean, c.misclassifiedError});
            ++cells;
            if (c.misclassifiedMean >= 1.0)
                relative.push_back(c.misclassifiedError / c.misclassifiedMean);
        }
    std::sort(relative.begin(), relative.end());
    const double median = relative.empty() ? 0.0 : relative[relative.size() / 2];
    const std::string adaptive =
        r.maxPhases <= r.phases
            ? ""
            : ", raised (doubling, up to " + std::to_string(r.maxPhases) +
                  ") where its standard error was above 2% of it and above a pixel: on " +
                  std::to_string(raised) + " of " + std::to_string(cells) +
                  " lights and methods, " + Fixed(cells ? phases / cells : 0.0, 1) +
                  " phases on average; " + std::to_string(unsettled) + " still above at " +
                  std::to_string(r.maxPhases);
    return "Each light's count is the mean over " + std::to_string(r.phases) +
           " sub-texel phases of its map(s)" + adaptive +
           "; its residual noise (standard error over mean) is " + Fixed(100.0 * median, 2) +
           "% for the median light and method, " +
           Fixed(sum > 0.0 ? 100.0 * errors / sum : 0.0, 2) +
           "% summed over them. A light counts as a win or loss (and as ordered by h) only "
           "where the two methods' means differ by more than 1.96 standard errors of their "
           "difference.";
}

std::vector<ReportSection> ReportSections(const SweepResult& r, const View& view,
                                          const ReportTable1& report) {
    const std::string ref = r.methods[view.reference];
    const bool worstRows = r.lights.size() >= kWorstRowsMinLights;
    ReportSection table1{
        "Table 1 as published (report-faithful baselines): misclassified shadow pixels, " +
            r.caseName + ", " + Lights(r) + "; in parentheses: % more than " + ref +
            " (Chong & Gortler, Table 1)",
        "The report's experiment with its methods as it describes them: per light, the counted "
        "pixels (visible, facing the light) whose shadow decision differs from exact shadow "
        "rays, averaged over all lights" +
            std::string(worstRows ? " and over each method's worst 10% of lights (ranked by "
                                    "that method's count)"
                                  : "") +
            ". Lower is better.",
        MisclassifiedTable(r, view, report),
        {}};
    if (ref == spatial::kReportOptimalMethod && report.Find("all"))
        table1.notes.push_back(
            "Rows \"published (report)\" are the report's own Table 1 as printed: absolute "
            "counts summed over its 500 lights on its own scene and frame, while ours are means "
            "per light on this case. The absolute numbers are on different scales and do not "
            "compare; the percentages do.");
    if (!worstRows)
        table1.notes.push_back("No worst-10% rows: they need at least " +
                               std::to_string(kWorstRowsMinLights) + " lights (this sweep has " +
                               std::to_string(r.lights.size()) +
                               ", so 10% would be one or two lights).");
    ReportSection summary{
        "The report's methods summarized: " + r.caseName + ", " + Lights(r) + "; ref = " + ref,
        kSummaryColumns,
        SummaryTable(r, view),
        {PhaseNote(r)}};
    return {std::move(table1), std::move(summary)};
}

ReportSection FairSection(const SweepResult& r, const View& view) {
    return {
        "The fair comparison (every method on the optimizer's information: the visible "
        "points, the same margin): " +
            r.caseName + ", " + Lights(r) + "; ref = " + r.methods[view.reference],
        "Every method gets what Algorithm 1 gets, the low-resolution readback's visible "
        "points and the same 2% margin, and optimal searches from every baseline's start. " +
            std::string(kSummaryColumns),
        SummaryTable(r, view),
        {PhaseNote(r)}};
}

ReportSection EqualTexelSection(const SweepResult& r, const View& view, bool terminal) {
    ReportSection section{
        "Equal texels (a method's maps or page pool hold at most the single map's texels; "
        "σ1(J⁻¹): frame pixels per texel): " +
            r.caseName + ", " + Lights(r) + "; ref = " + r.methods[view.reference],
        "The partitioned methods (cascades) and the virtual shadow maps against optimal's single "
        "map, all of a method's maps (a virtual map's resident pages) together holding at most "
        "the same texels. Besides the summary's columns: the maps per light (pages: the most "
        "over the lights), the "
        "mean and largest σ1(J⁻¹) (the most frame pixels one texel spans; above 1 where the map "
        "undersamples the view), the counted pixels no map covers (mean per light), and the "
        "partitions that served no visible point (summed over the lights).",
        EqualTexelTable(r, view, terminal),
        {PhaseNote(r)}};
    if (terminal) section.notes.push_back("max σ1(J⁻¹): in --format csv, json and markdown.");
    return section;
}

// The virtual shadow maps' pages, when any ran: mean per light.
std::optional<ReportSection> PageSection(const SweepResult& r, const View& view) {
    TextTable table({"method", "pages\nrequested\n(mean)", "pages\nresident\n(mean)",
                     "pages\ndropped\n(mean)", "mean\nLOD bias"});
    bool any = false;
    for (std::size_t m : view.methods) {
        const MethodSummary s = Summarize(r, m, view.reference);
        if (std::isnan(s.meanPagesRequested)) continue;
        table.AddRow({r.methods[m], Fixed(s.meanPagesRequested, 1), Fixed(s.meanPagesResident, 1),
                      Fixed(s.meanPagesDropped, 1), Fixed(s.meanLodBias, 3)});
        any = true;
    }
    if (!any) return std::nullopt;
    return ReportSection{
        "Virtual shadow maps' pages: " + r.caseName + ", " + Lights(r),
        "Per light, the distinct pages the readback's pixels asked for at the level their "
        "footprint asks for (plus the coarsest page), those the pool holds (the most requested; "
        "the pool holds at most the single map's texels) and those dropped, and the LOD bias "
        "added to every footprint level (vsm-dynamic raises it until the requests fit).",
        std::move(table),
        {}};
}

}  // namespace

std::vector<ReportSection> SweepSections(const SweepResult& r, const ReportTable1& report,
                                         bool terminal) {
    std::vector<ReportSection> sections;
    if (const auto view = ReportView(r))
        for (ReportSection& s : ReportSections(r, *view, report)) sections.push_back(std::move(s));
    if (const auto view = FairView(r)) sections.push_back(FairSection(r, *view));
    if (const auto view = EqualTexelView(r)) {
        sections.push_back(EqualTexelSection(r, *view, terminal));
        if (std::optional<ReportSection> pages = PageSection(r, *view))
            sections.push_back(std::move(*pages));
    }
    return sections;
}

namespace {

nlohmann::json ViewJson(const SweepResult& r, const View& view, bool worstRows) {
    nlohmann::json doc;
    doc["reference"] = r.methods[view.reference];
    const ColumnTable<SummaryRow> columns = SummaryColumns();
    for (const SummaryRow& row : SummaryRows(r, view, "")) {
        nlohmann::json method;
        AddJsonColumns(columns, row, method);
        doc["methods"].push_back(method);
    }
    if (worstRows) {
        doc["worst_10_percent"] = nlohmann::json::array();  // empty under kWorstRowsMinLights
        const std::vector<Row> rows = Table1Rows(r, view);
        for (std::size_t k = 1; k < rows.size(); ++k) {
            nlohmann::json means;
            for (std::size_t m : view.methods) means[r.methods[m]] = rows[k].mean[m];
            doc["worst_10_percent"].push_back(
                {{"ranked_by", rows[k].set}, {"mean_misclassified", means}});
        }
    }
    return doc;
}

}  // namespace

std::string SweepTable(const SweepResult& r, const ReportTable1& report) {
    return SectionsText(SweepSections(r, report, true));
}

std::string SweepMarkdown(const SweepResult& r, const ReportTable1& report) {
    return SectionsMarkdown(SweepSections(r, report, false));
}

namespace {

// The CSV rows of one view: per set of `rows` (all lights, then Table 1's worst-10% sets), a row
// per method, with the report's own % where it has one (against optimal-report only).
std::vector<SummaryRow> CsvRows(const SweepResult& r, const View& view, const std::string& table,
                                const std::vector<Row>& sets, const ReportTable1& report) {
    const bool published = r.methods[view.reference] == spatial::kReportOptimalMethod;
    std::vector<SummaryRow> out;
    for (const Row& set : sets) {
        const ReportTable1::Row* reportRow = report.Find(PublishedName(set.set));
        for (std::size_t m : view.methods) {
            SummaryRow row;
            row.table = table;
            row.set = set.set;
            row.method = r.methods[m];
            row.setMean = set.mean[m];
            row.setPercentMore = PercentMore(set.mean[m], set.mean[view.reference]);
            if (set.set == "all") row.summary = Summarize(r, m, view.reference);
            const std::optional<std::size_t> col = report.Column(PublishedName(r.methods[m]));
            if (published && reportRow && col) row.reportPercentMore = reportRow->percentMore[*col];
            row.phases = r.phases;
            row.isReference = m == view.reference;
            out.push_back(std::move(row));
        }
    }
    return out;
}

}  // namespace

std::string SweepColumnReference() { return ColumnReference(SummaryColumns()); }

std::string SweepCsv(const SweepResult& r, const ReportTable1& report) {
    const ColumnTable<SummaryRow> columns = SummaryColumns();
    std::string out = CsvHeader(columns) + '\n';
    const auto write = [&](const std::vector<SummaryRow>& rows) {
        for (const SummaryRow& row : rows) out += CsvRow(columns, row) + '\n';
    };
    if (const auto view = ReportView(r))
        write(CsvRows(r, *view, "report", Table1Rows(r, *view), report));
    const std::vector<Row> all = {{"all", MeanOver(r, AllLights(r))}};
    if (const auto view = FairView(r)) write(CsvRows(r, *view, "fair", all, report));
    if (const auto view = EqualTexelView(r)) write(CsvRows(r, *view, "equal-texel", all, report));
    return out;
}

nlohmann::json SweepJson(const SweepResult& r) {
    nlohmann::json doc;
    doc["case"] = r.caseName;
    doc["lights"] = r.lights.size();
    doc["phases"] = r.phases;
    doc["max_phases"] = r.maxPhases;
    doc["shimmer_poses"] = r.shimmerPoses;
    if (const auto view = ReportView(r)) doc["report_table"] = ViewJson(r, *view, true);
    if (const auto view = FairView(r)) doc["fair_table"] = ViewJson(r, *view, false);
    if (const auto view = EqualTexelView(r)) doc["equal_texel_table"] = ViewJson(r, *view, false);
    doc["seconds"] = r.seconds;
    return doc;
}

std::string CascadeStudyCsv(const CascadeCountStudy& study) {
    std::ostringstream out;
    out << "method,k,mean_misclassified\n";
    if (study.optimalMean) out << "optimal,1," << CsvNumber(*study.optimalMean) << '\n';
    for (std::size_t m = 0; m < study.methods.size(); ++m)
        for (std::size_t k = 0; k < study.counts.size(); ++k)
            out << study.methods[m] << ',' << study.counts[k] << ','
                << CsvNumber(study.meanMisclassified[m][k]) << '\n';
    return out.str();
}

void WriteCascadeStudyPlot(const std::string& pngPath, const CascadeCountStudy& study,
                           const SweepResult& sweep) {
    CurvePlot figure;
    figure.title = "Misclassified pixels against partitions at equal texels: " + sweep.caseName +
                   ", " + Lights(sweep);
    figure.xLabel = "partitions k (maps of (W/√k) × (H/√k))";
    figure.yLabel = "mean misclassified pixels";
    for (int k : study.counts) figure.xTicks.push_back(k);
    for (std::size_t m = 0; m < study.methods.size(); ++m) {
        PlotCurve curve{study.methods[m], {}, study.meanMisclassified[m]};
        for (int k : study.counts) curve.x.push_back(k);
        figure.curves.push_back(std::move(curve));
    }
    if (study.optimalMean) {
        figure.guideY = *study.optimalMean;
        figure.guideLabel = "optimal (one map): " + Fixed(*study.optimalMean, 0);
    }
    WriteCurvePlot(pngPath, figure);
}

}  // namespace lexel::cases
