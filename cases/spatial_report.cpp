#include "lexel/cases/spatial_report.h"

#include <tbb/parallel_for.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <iostream>
#include <map>
#include <mutex>
#include <numeric>
#include <sstream>

#include "lexel/cases/report.h"
#include "lexel/cases/spatial_case.h"
#include "lexel/solvers/errors.h"
#include "lexel/spatial/harness/generator.h"
#include "lexel/spatial/harness/images.h"
#include "lexel/spatial/harness/methods.h"
#include "lexel/spatial/light_space.h"
#include "lexel/spatial/temporal.h"

namespace lexel::cases {
namespace {

using spatial::Light;

// Chong & Gortler, report Table 1: misclassified pixels over 500 hemisphere lights, and for each
// method's worst 10% of lights the mean of every method. Columns in the report's order.
const std::vector<std::string> kReportMethods = {"optimal", "focused", "lispsm", "plane-optimal",
                                                 "normal"};
const std::map<std::string, std::vector<double>> kReportTable1 = {
    {"all", {1886057, 2407686, 2929613, 7828974, 5405579}},
    {"optimal", {304839, 403529, 324559, 500413, 1146830}},
    {"focused", {263638, 485088, 354289, 373324, 1203575}},
    {"lispsm", {253331, 422387, 377762, 408887, 1068285}},
    {"plane-optimal", {170056, 217869, 197196, 1242144, 692796}},
    {"normal", {272953, 448302, 338566, 521885, 1308651}},
};

// The same table's printed percentages ("% more than optimal"), verbatim: recomputing them from
// the counts differs in the last digit (e.g. 27.66 for the printed 27.65).
const std::map<std::string, std::vector<double>> kReportPercent = {
    {"all", {0, 27.65, 55.33, 315.09, 186.60}},
    {"optimal", {0, 32.37, 6.47, 64.16, 276.21}},
    {"focused", {0, 84.00, 34.38, 41.60, 356.53}},
    {"lispsm", {0, 66.73, 49.12, 61.40, 321.70}},
    {"plane-optimal", {0, 28.12, 15.96, 630.43, 307.39}},
    {"normal", {0, 64.24, 24.04, 91.20, 379.44}},
};

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
std::vector<std::string> ReportCells(const std::string& set, const std::vector<std::string>& ours) {
    std::vector<std::string> cells;
    const auto row = kReportTable1.find(set);
    if (row == kReportTable1.end()) return cells;
    for (const std::string& m : ours) {
        const auto col = std::find(kReportMethods.begin(), kReportMethods.end(), m);
        if (col == kReportMethods.end()) {
            cells.push_back("");
            continue;
        }
        const std::size_t c = col - kReportMethods.begin();
        const double pct = kReportPercent.at(set)[c];
        cells.push_back(Fixed(row->second[c], 0) +
                        (m == "optimal" ? " (0)" : " (+" + Fixed(pct, 2) + "%)"));
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

TextTable MisclassifiedTable(const SweepResult& r, bool withReport) {
    std::vector<std::string> header = {"lights"};
    header.insert(header.end(), r.methods.begin(), r.methods.end());
    TextTable table(header);
    const std::size_t ref = ReferenceIndex(r);
    const bool compareToReport = withReport && r.methods[ref] == "optimal";
    for (const Row& row : Table1Rows(r)) {
        std::vector<std::string> cells = {SetLabel(row.set)};
        for (std::size_t m = 0; m < r.methods.size(); ++m)
            cells.push_back(Cell(row.mean[m], row.mean[ref], m == ref));
        table.AddRow(cells);
        if (compareToReport) {
            std::vector<std::string> report = ReportCells(row.set, r.methods);
            if (!report.empty()) {
                report.insert(report.begin(), "  report (Table 1)");
                table.AddRow(report);
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

// A progress bar on a terminal, silent otherwise.
class Progress {
  public:
    Progress(std::size_t total, bool enabled)
        : total_(total),
          enabled_(enabled && isatty(STDERR_FILENO)),
          start_(std::chrono::steady_clock::now()) {}
    void Step() {
        const std::size_t done = ++done_;
        if (!enabled_) return;
        std::lock_guard<std::mutex> lock(mutex_);
        const double s =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
        const int width = 30,
                  filled = static_cast<int>(width * done / std::max<std::size_t>(1, total_));
        std::cerr << "\rsweep [" << std::string(filled, '#') << std::string(width - filled, '.')
                  << "] " << done << "/" << total_ << " lights, " << Fixed(s, 0) << " s"
                  << (done == total_ ? "\n" : "") << std::flush;
    }

  private:
    std::size_t total_;
    bool enabled_;
    std::chrono::steady_clock::time_point start_;
    std::atomic<std::size_t> done_{0};
    std::mutex mutex_;
};

std::vector<std::string> ResolveMethods(std::vector<std::string> methods) {
    if (methods.empty()) return spatial::SpatialMethodNames();
    for (const std::string& m : methods) spatial::CheckSpatialMethod(m);
    return methods;
}

std::string LightLabel(const Light& light) {
    std::ostringstream out;
    const glm::dvec3 v = light.type == Light::Type::kPoint ? light.position : light.direction;
    out << (light.type == Light::Type::kPoint ? "point (" : "directional (") << Significant(v.x, 4)
        << ", " << Significant(v.y, 4) << ", " << Significant(v.z, 4) << ")";
    return out.str();
}

// Algorithm 1 step 5 along the case's camera_path: per light, per pose, whether `optimal`
// replaced the previous matrix, and the misclassified pixels with and without hysteresis.
void CameraPathSection(const spatial::Scene& scene, const spatial::RenderBackend& backend,
                       nlohmann::json* doc, std::ostringstream* text) {
    spatial::EvaluationOptions evalOptions;
    evalOptions.methods = {"optimal"};
    const double margin = spatial::OptimizerOptions{}.margin;
    for (std::size_t l = 0; l < scene.lights.size(); ++l) {
        const Light& light = scene.lights[l];
        std::optional<spatial::LightMatrix> previous;
        int changes = 0;
        TextTable table({"pose", "P changed", "median badness kept", "median badness new",
                         "misclassified (hysteresis)", "misclassified (fresh)"});
        nlohmann::json poses = nlohmann::json::array();
        for (std::size_t k = 0; k < scene.cameraPath.size(); ++k) {
            spatial::Scene poseScene = scene;
            poseScene.camera = scene.cameraPath[k];
            std::optional<spatial::Evaluator> built;
            try {
                built.emplace(poseScene, backend);
            } catch (const InputError& e) {
                std::string reason = e.what();
                if (reason.rfind("/camera: ", 0) == 0) reason = reason.substr(9);
                throw InputError("/camera_path/" + std::to_string(k) + ": " + reason);
            }
            const spatial::Evaluator& evaluator = *built;
            const spatial::LightOutcome o = evaluator.Evaluate(light, evalOptions);
            const spatial::HysteresisDecision d = spatial::ApplyHysteresis(
                previous, o.methods[0].matrix, o.samples, scene.shadowMap, margin);
            const std::int64_t fresh = o.methods[0].misclassified;
            const std::int64_t kept = d.changed ? fresh : evaluator.Misclassified(light, d.matrix);
            changes += d.changed;
            previous = d.matrix;
            table.AddRow({std::to_string(k), d.changed ? "yes" : "no",
                          Significant(d.medianPrevious, 5), Significant(d.medianCandidate, 5),
                          std::to_string(kept), std::to_string(fresh)});
            poses.push_back({{"pose", k},
                             {"changed", d.changed},
                             {"median_badness_kept", std::isfinite(d.medianPrevious)
                                                         ? nlohmann::json(d.medianPrevious)
                                                         : nlohmann::json(nullptr)},
                             {"median_badness_new", d.medianCandidate},
                             {"misclassified_hysteresis", kept},
                             {"misclassified_fresh", fresh}});
        }
        (*doc)["camera_path"].push_back(
            {{"light", l}, {"poses", poses.size()}, {"changes", changes}, {"frames", poses}});
        *text << "\ncamera path, light " << l << ": P changed in " << changes << " of "
              << scene.cameraPath.size() << " poses (hysteresis: keep P unless the new median "
              << "badness is below 80% of the kept one)\n"
              << table.Render();
    }
}

}  // namespace

std::vector<Light> SweepLightsOf(const spatial::Scene& scene, int lights) {
    if (!scene.lightSweep)
        throw InputError("/light_sweep: the case has none; add {\"count\", \"seed\", \"radius\"}");
    spatial::LightSweep sweep = *scene.lightSweep;
    if (lights > 0) sweep.count = lights;
    return spatial::SweepLights(sweep, scene.geometry.ComputeBounds().Center());
}

SweepResult RunSweep(const spatial::Scene& scene, const std::vector<std::string>& methods,
                     const std::vector<Light>& lights, bool progress) {
    const auto start = std::chrono::steady_clock::now();
    const auto backend = spatial::MakeCpuRenderer(scene.geometry);
    const spatial::Evaluator evaluator(scene, *backend);
    SweepResult r;
    r.caseName = scene.name;
    r.methods = methods;
    r.lights = lights;
    r.cells.assign(lights.size(), std::vector<SweepCell>(methods.size()));
    r.receiverPixels.assign(lights.size(), 0);
    spatial::EvaluationOptions options;
    options.methods = methods;
    Progress bar(lights.size(), progress);
    tbb::parallel_for(std::size_t(0), lights.size(), [&](std::size_t l) {
        spatial::LightOutcome outcome;
        try {
            outcome = evaluator.Evaluate(lights[l], options);
        } catch (const InputError& e) {
            throw InputError("light " + std::to_string(l) + " " + LightLabel(lights[l]) + ": " +
                             e.what());
        }
        for (std::size_t m = 0; m < methods.size(); ++m)
            r.cells[l][m] = {outcome.methods[m].misclassified, outcome.methods[m].h,
                             outcome.methods[m].ms};
        r.receiverPixels[l] = outcome.receiverPixels;
        bar.Step();
    });
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return r;
}

std::string SweepTable(const SweepResult& r) {
    return Caption(r) + "\n" + MisclassifiedTable(r, true).Render() + "\n" +
           MethodTable(r).Render();
}

std::string SweepMarkdown(const SweepResult& r) {
    return "## " + Caption(r) + "\n\n" + MisclassifiedTable(r, true).RenderMarkdown() + "\n" +
           MethodTable(r).RenderMarkdown();
}

std::string SweepCsv(const SweepResult& r) {
    std::ostringstream out;
    out << "set,method,mean_misclassified,percent_more,report_percent_more\n";
    const std::size_t ref = ReferenceIndex(r);
    for (const Row& row : Table1Rows(r)) {
        const auto report = kReportTable1.find(row.set);
        for (std::size_t m = 0; m < r.methods.size(); ++m) {
            out << row.set << ',' << r.methods[m] << ',' << Fixed(row.mean[m], 3) << ','
                << Fixed(PercentMore(row.mean[m], row.mean[ref]), 4) << ',';
            const auto col = std::find(kReportMethods.begin(), kReportMethods.end(), r.methods[m]);
            if (r.methods[ref] == "optimal" && report != kReportTable1.end() &&
                col != kReportMethods.end())
                out << Fixed(kReportPercent.at(row.set)[col - kReportMethods.begin()], 2);
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

namespace {
int RunSweepLoaded(const std::filesystem::path& casePath, const spatial::Scene& scene,
                   const SweepOptions& options);
int RunSpatialLoaded(const std::filesystem::path& casePath, const spatial::Scene& scene,
                     const SpatialRunOptions& options);

// Errors found after loading (no visible geometry, a light the evaluation rejects, a missing
// light_sweep) get the case file's name in front, like the loader's own.
template <class Options>
int WithCaseName(const std::filesystem::path& casePath, const Options& options,
                 int (*body)(const std::filesystem::path&, const spatial::Scene&, const Options&)) {
    const spatial::Scene scene = LoadSpatialScene(casePath);
    try {
        return body(casePath, scene, options);
    } catch (const InputError& e) {
        throw InputError(casePath.string() + ": " + e.what());
    }
}
}  // namespace

int RunSweepCommand(const std::filesystem::path& casePath, const SweepOptions& options) {
    return WithCaseName(casePath, options, &RunSweepLoaded);
}

int RunSpatialCommand(const std::filesystem::path& casePath, const SpatialRunOptions& options) {
    return WithCaseName(casePath, options, &RunSpatialLoaded);
}

namespace {
int RunSweepLoaded(const std::filesystem::path&, const spatial::Scene& scene,
                   const SweepOptions& options) {
    const std::vector<std::string> methods = ResolveMethods(options.methods);
    const std::vector<Light> lights = SweepLightsOf(scene, options.lights);
    const SweepResult r = RunSweep(scene, methods, lights, true);
    if (options.format == "json")
        std::cout << SweepJson(r).dump(2) << '\n';
    else if (options.format == "csv")
        std::cout << SweepCsv(r);
    else if (options.format == "markdown")
        std::cout << SweepMarkdown(r);
    else
        std::cout << SweepTable(r) << "sweep: " << Fixed(r.seconds, 1) << " s for "
                  << r.lights.size() << " lights\n";
    if (!options.outDir.empty()) {
        std::filesystem::create_directories(options.outDir);
        const std::filesystem::path dir(options.outDir);
        WriteFileAtomically((dir / "table1.md").string(), SweepMarkdown(r));
        WriteFileAtomically((dir / "table1.csv").string(), SweepCsv(r));
        WriteFileAtomically((dir / "sweep.json").string(), SweepJson(r).dump(2) + "\n");
        std::ostringstream perLight;
        perLight << "light,kind,x,y,z,receiver_pixels";
        for (const auto& m : methods)
            perLight << ',' << m << "_misclassified," << m << "_h," << m << "_ms";
        perLight << '\n';
        for (std::size_t l = 0; l < lights.size(); ++l) {
            const glm::dvec3 v =
                lights[l].type == Light::Type::kPoint ? lights[l].position : lights[l].direction;
            perLight << l << ','
                     << (lights[l].type == Light::Type::kPoint ? "point" : "directional") << ','
                     << Significant(v.x, 9) << ',' << Significant(v.y, 9) << ','
                     << Significant(v.z, 9) << ',' << r.receiverPixels[l];
            for (const SweepCell& c : r.cells[l])
                perLight << ',' << c.misclassified << ',' << Significant(c.h, 9) << ','
                         << Fixed(c.ms, 4);
            perLight << '\n';
        }
        WriteFileAtomically((dir / "lights.csv").string(), perLight.str());
        std::cerr << "lexel: wrote table1.md, table1.csv, sweep.json, lights.csv to "
                  << options.outDir << '\n';
    }
    return 0;
}

int RunSpatialLoaded(const std::filesystem::path&, const spatial::Scene& scene,
                     const SpatialRunOptions& options) {
    const std::vector<std::string> methods = ResolveMethods(options.methods);
    if (scene.lights.empty())
        throw InputError(
            "/lights: the case has no fixed lights; run `lexel sweep` for its "
            "light_sweep");
    const auto backend = spatial::MakeCpuRenderer(scene.geometry);
    const spatial::Evaluator evaluator(scene, *backend);
    spatial::EvaluationOptions evalOptions;
    evalOptions.methods = methods;
    evalOptions.mapTruth = options.mapTruth;
    evalOptions.keepBuffers = !options.outDir.empty();

    // Everything is computed before anything is written.
    std::vector<spatial::LightOutcome> outcomes;
    for (std::size_t l = 0; l < scene.lights.size(); ++l) {
        try {
            outcomes.push_back(evaluator.Evaluate(scene.lights[l], evalOptions));
        } catch (const InputError& e) {
            throw InputError("/lights/" + std::to_string(l) + ": " + e.what());
        }
    }

    nlohmann::json doc;
    doc["case"] = scene.name;
    std::ostringstream text, csv;
    csv << "light,method,misclassified,false_shadow,false_light,h,ms\n";
    for (std::size_t l = 0; l < outcomes.size(); ++l) {
        const auto& o = outcomes[l];
        nlohmann::json light = {{"light", l},
                                {"description", LightLabel(o.light)},
                                {"receiver_pixels", o.receiverPixels},
                                {"truth_shadowed", o.truthShadowed},
                                {"boundary_samples", o.samples.lsX.size()}};
        if (o.mapTruthDisagree >= 0) light["map4000_disagrees_with_rays"] = o.mapTruthDisagree;
        TextTable table(
            {"method", "misclassified", "false shadow", "false light", "h (eq. 6)", "ms"});
        for (const auto& m : o.methods) {
            const std::int64_t falseLight = m.misclassified - m.falseShadow;
            table.AddRow({m.method, std::to_string(m.misclassified), std::to_string(m.falseShadow),
                          std::to_string(falseLight), Significant(m.h, 6), Fixed(m.ms, 3)});
            light["methods"].push_back(
                {{"method", m.method},
                 {"misclassified", m.misclassified},
                 {"false_shadow", m.falseShadow},
                 {"false_light", falseLight},
                 {"h", std::isfinite(m.h) ? nlohmann::json(m.h) : nlohmann::json(nullptr)},
                 {"ms", m.ms}});
            csv << l << ',' << m.method << ',' << m.misclassified << ',' << m.falseShadow << ','
                << falseLight << ',' << Significant(m.h, 9) << ',' << Fixed(m.ms, 4) << '\n';
        }
        doc["lights"].push_back(light);
        text << (l ? "\n" : "") << "light " << l << ": " << LightLabel(o.light) << " — "
             << o.receiverPixels << " pixels face it, " << o.truthShadowed
             << " shadowed (Embree rays)";
        if (o.mapTruthDisagree >= 0)
            text << "; the report's focused 4000² map disagrees on " << o.mapTruthDisagree << " ("
                 << Fixed(100.0 * o.mapTruthDisagree / std::max<std::int64_t>(1, o.receiverPixels),
                          3)
                 << "%)";
        text << "; " << o.samples.lsX.size() << " boundary samples\n" << table.Render();
        for (std::size_t k = 0; k < o.methods.size(); ++k) {
            const auto& m = o.methods[k];
            if (m.hAfterIteration.empty()) continue;
            text << m.method << ": h after each iteration (Algorithm 1)";
            for (std::size_t i = 0; i < m.hAfterIteration.size(); ++i)
                text << (i ? " → " : " ") << Significant(m.hAfterIteration[i], 6);
            if (m.h < m.hBeforeRefine) text << "; refined " << Significant(m.h, 6);
            text << '\n';
            light["methods"][k]["h_after_iteration"] = m.hAfterIteration;
        }
    }
    if (!scene.cameraPath.empty()) CameraPathSection(scene, *backend, &doc, &text);
    if (options.format == "json")
        std::cout << doc.dump(2) << '\n';
    else if (options.format == "csv")
        std::cout << csv.str();
    else
        std::cout << text.str();

    if (!options.outDir.empty()) {
        const std::filesystem::path dir(options.outDir);
        std::filesystem::create_directories(dir);
        int images = 0;
        for (std::size_t l = 0; l < outcomes.size(); ++l) {
            const spatial::LightSpace lightSpace(outcomes[l].light, evaluator.bounds());
            for (const auto& m : outcomes[l].methods) {
                const std::string base =
                    (dir / (scene.name + "_light" + std::to_string(l) + "_" + m.method)).string();
                spatial::WriteImage(base + "_frame.png",
                                    spatial::FrameImage(evaluator.frame(), lightSpace, m.shades));
                spatial::WriteImage(base + "_errors.png",
                                    spatial::MisclassificationImage(evaluator.frame(), lightSpace,
                                                                    m.shades, outcomes[l].truth));
                spatial::WriteImage(base + "_map.png",
                                    spatial::ShadowMapImage(m.map, outcomes[l].samples));
                images += 3;
            }
        }
        WriteFileAtomically((dir / (scene.name + ".json")).string(), doc.dump(2) + "\n");
        WriteFileAtomically((dir / (scene.name + ".csv")).string(), csv.str());
        std::cerr << "lexel: wrote " << images << " images and " << scene.name << ".json/.csv to "
                  << options.outDir << '\n';
    }
    return 0;
}

}  // namespace

}  // namespace lexel::cases
