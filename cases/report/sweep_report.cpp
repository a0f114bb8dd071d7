#include "lexel/cases/report/sweep_report.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>
#include <sstream>

#include "lexel/cases/report/text_table.h"

namespace lexel::cases {
namespace {

using spatial::Light;

std::size_t ReferenceIndex(const SweepResult& r) {
    const auto it = std::find(r.methods.begin(), r.methods.end(), "optimal");
    return it == r.methods.end() ? 0 : static_cast<std::size_t>(it - r.methods.begin());
}

// The lights in a method's worst 10% (at least one), ties broken by light index.
std::vector<std::size_t> WorstLights(const SweepResult& r, std::size_t method) {
    std::vector<std::size_t> order(r.lights.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return r.cells[a][method].misclassified > r.cells[b][method].misclassified;
    });
    const std::size_t keep = std::max<std::size_t>(1, (r.lights.size() + 5) / 10);
    order.resize(std::min(keep, order.size()));
    return order;
}

struct Row {
    std::string set;           // "all" or the ranking method
    std::vector<double> mean;  // per method: mean misclassified over the set
};

std::vector<Row> Table1Rows(const SweepResult& r) {
    std::vector<Row> rows;
    std::vector<std::size_t> all(r.lights.size());
    std::iota(all.begin(), all.end(), 0);
    const auto meanOver = [&](const std::vector<std::size_t>& set) {
        std::vector<double> mean(r.methods.size(), 0.0);
        for (std::size_t m = 0; m < r.methods.size(); ++m) {
            for (std::size_t l : set) mean[m] += r.cells[l][m].misclassified;
            mean[m] /= std::max<std::size_t>(1, set.size());
        }
        return mean;
    };
    rows.push_back({"all", meanOver(all)});
    for (std::size_t m = 0; m < r.methods.size(); ++m)
        rows.push_back({r.methods[m], meanOver(WorstLights(r, m))});
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

// The report's cells for our set and methods, or empty where it has none.
std::vector<std::string> ReportCells(const ReportTable1& report, const std::string& set,
                                     const std::vector<std::string>& ours) {
    std::vector<std::string> cells;
    const ReportTable1::Row* row = report.Find(set);
    if (!row) return cells;
    for (const std::string& m : ours) {
        const std::optional<std::size_t> c = report.Column(m);
        if (!c) {
            cells.push_back("");
            continue;
        }
        cells.push_back(Fixed(row->misclassified[*c], 0) +
                        (m == "optimal" ? " (0)" : " (+" + Fixed(row->percentMore[*c], 2) + "%)"));
    }
    return cells;
}

struct MethodSummary {
    double meanH = 0.0;  // over lights where h is finite
    std::int64_t infiniteH = 0;
    double meanMs = 0.0;
};

std::vector<MethodSummary> Summaries(const SweepResult& r) {
    std::vector<MethodSummary> out(r.methods.size());
    for (std::size_t m = 0; m < r.methods.size(); ++m) {
        std::size_t finite = 0;
        for (const auto& light : r.cells) {
            const SweepCell& c = light[m];
            if (std::isfinite(c.h)) {
                out[m].meanH += c.h;
                ++finite;
            } else {
                ++out[m].infiniteH;
            }
            out[m].meanMs += c.ms;
        }
        out[m].meanH = finite ? out[m].meanH / finite : std::numeric_limits<double>::infinity();
        out[m].meanMs /= std::max<std::size_t>(1, r.cells.size());
    }
    return out;
}

std::string SetLabel(const std::string& set) {
    return set == "all" ? "all lights" : "worst 10% by " + set;
}

TextTable MisclassifiedTable(const SweepResult& r, const ReportTable1* report) {
    std::vector<std::string> header = {"lights"};
    header.insert(header.end(), r.methods.begin(), r.methods.end());
    TextTable table(header);
    const std::size_t ref = ReferenceIndex(r);
    const bool compareToReport = report && r.methods[ref] == "optimal";
    for (const Row& row : Table1Rows(r)) {
        std::vector<std::string> cells = {SetLabel(row.set)};
        for (std::size_t m = 0; m < r.methods.size(); ++m)
            cells.push_back(Cell(row.mean[m], row.mean[ref], m == ref));
        table.AddRow(cells);
        if (compareToReport) {
            std::vector<std::string> cells = ReportCells(*report, row.set, r.methods);
            if (!cells.empty()) {
                cells.insert(cells.begin(), "  report (Table 1)");
                table.AddRow(cells);
            }
        }
    }
    return table;
}

TextTable MethodTable(const SweepResult& r) {
    TextTable table({"method", "mean h (eq. 6)", "lights with h = inf", "mean ms per light"});
    const auto sums = Summaries(r);
    for (std::size_t m = 0; m < r.methods.size(); ++m)
        table.AddRow({r.methods[m], Significant(sums[m].meanH, 5),
                      std::to_string(sums[m].infiniteH), Fixed(sums[m].meanMs, 3)});
    return table;
}

std::string Caption(const SweepResult& r) {
    std::ostringstream out;
    out << "Misclassified shadow pixels, " << r.caseName << ", " << r.lights.size()
        << " lights; in parentheses: % more than " << r.methods[ReferenceIndex(r)]
        << " (Chong & Gortler, Table 1)";
    return out.str();
}

}  // namespace

std::string SweepTable(const SweepResult& r, const ReportTable1& report) {
    return Caption(r) + "\n" + MisclassifiedTable(r, &report).Render() + "\n" +
           MethodTable(r).Render();
}

std::string SweepMarkdown(const SweepResult& r, const ReportTable1& report) {
    return "## " + Caption(r) + "\n\n" + MisclassifiedTable(r, &report).RenderMarkdown() + "\n" +
           MethodTable(r).RenderMarkdown();
}

std::string SweepCsv(const SweepResult& r, const ReportTable1& report) {
    std::ostringstream out;
    out << "set,method,mean_misclassified,percent_more,report_percent_more\n";
    const std::size_t ref = ReferenceIndex(r);
    for (const Row& row : Table1Rows(r)) {
        const ReportTable1::Row* published = report.Find(row.set);
        for (std::size_t m = 0; m < r.methods.size(); ++m) {
            out << row.set << ',' << r.methods[m] << ',' << Fixed(row.mean[m], 3) << ','
                << Fixed(PercentMore(row.mean[m], row.mean[ref]), 4) << ',';
            const std::optional<std::size_t> col = report.Column(r.methods[m]);
            if (r.methods[ref] == "optimal" && published && col)
                out << Fixed(published->percentMore[*col], 2);
            out << '\n';
        }
    }
    return out.str();
}

nlohmann::json SweepJson(const SweepResult& r) {
    nlohmann::json doc;
    doc["case"] = r.caseName;
    doc["lights"] = r.lights.size();
    doc["reference"] = r.methods[ReferenceIndex(r)];
    const auto rows = Table1Rows(r);
    const auto sums = Summaries(r);
    const auto finiteOrNull = [](double v) -> nlohmann::json {
        return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
    };
    for (std::size_t m = 0; m < r.methods.size(); ++m)
        doc["methods"].push_back(
            {{"method", r.methods[m]},
             {"mean_misclassified", rows[0].mean[m]},
             {"percent_more",
              finiteOrNull(PercentMore(rows[0].mean[m], rows[0].mean[ReferenceIndex(r)]))},
             {"mean_h", finiteOrNull(sums[m].meanH)},
             {"lights_with_infinite_h", sums[m].infiniteH},
             {"mean_ms", sums[m].meanMs}});
    for (std::size_t k = 1; k < rows.size(); ++k) {
        nlohmann::json means;
        for (std::size_t m = 0; m < r.methods.size(); ++m) means[r.methods[m]] = rows[k].mean[m];
        doc["worst_10_percent"].push_back(
            {{"ranked_by", rows[k].set}, {"mean_misclassified", means}});
    }
    doc["seconds"] = r.seconds;
    return doc;
}

std::string SweepLightsCsv(const SweepResult& r) {
    std::ostringstream perLight;
    perLight << "light,kind,x,y,z,receiver_pixels";
    for (const auto& m : r.methods)
        perLight << ',' << m << "_misclassified," << m << "_h," << m << "_ms";
    perLight << '\n';
    for (std::size_t l = 0; l < r.lights.size(); ++l) {
        const Light& light = r.lights[l];
        const glm::dvec3 v = light.type == Light::Type::kPoint ? light.position : light.direction;
        perLight << l << ',' << (light.type == Light::Type::kPoint ? "point" : "directional") << ','
                 << Significant(v.x, 9) << ',' << Significant(v.y, 9) << ',' << Significant(v.z, 9)
                 << ',' << r.receiverPixels[l];
        for (const SweepCell& c : r.cells[l])
            perLight << ',' << c.misclassified << ',' << Significant(c.h, 9) << ','
                     << Fixed(c.ms, 4);
        perLight << '\n';
    }
    return perLight.str();
}

}  // namespace lexel::cases
