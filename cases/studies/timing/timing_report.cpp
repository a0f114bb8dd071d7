#include "lexel/cases/studies/timing/timing_report.h"

#include <sstream>

#include "lexel/cases/report/text_table.h"
#include "lexel/cases/run/sweep.h"

namespace lexel::cases {
namespace {

using spatial::FrameTimes;

// The columns of every format, in order: (name, value).
std::vector<std::pair<const char*, double>> Columns(const FrameTimes& t) {
    return {{"total", t.total},
            {"camera_pass", t.cameraPass},
            {"readback", t.readback},
            {"extraction", t.extraction},
            {"hull", t.hull},
            {"search", t.search},
            {"shadow_map", t.shadowMap},
            {"shading", t.shading}};
}

const std::vector<std::string> kTextHeader = {"ms per frame", "total",      "camera",
                                              "readback",     "extraction", "hull",
                                              "search",       "shadow map", "shading"};

std::vector<std::string> TextRow(const std::string& label, const FrameTimes& t) {
    std::vector<std::string> row{label};
    for (const auto& [name, value] : Columns(t)) row.push_back(Fixed(value, 2));
    return row;
}

double Ratio(const TimingRun& run) {
    const double focused = MeanTimes(run.focused).total;
    return focused > 0.0 ? MeanTimes(run.optimal).total / focused : 0.0;
}

// The report's Table 3 beside our means: its stages from our columns.
struct Stage {
    const char* name;   // Table 3's stage key
    const char* label;  // printed
    double (*ours)(const FrameTimes&);
};
const Stage kStages[] = {
    {"total", "total", [](const FrameTimes& t) { return t.total; }},
    {"optimization", "optimization (hull + search)",
     [](const FrameTimes& t) { return t.hull + t.search; }},
    {"convex_hull", "convex hull (hull)", [](const FrameTimes& t) { return t.hull; }},
    {"render_and_wait", "render & wait (total - optimization)",
     [](const FrameTimes& t) { return t.total - t.hull - t.search; }},
};

std::string OptionalMs(const std::optional<double>& v) { return v ? Fixed(*v, 2) : ""; }

std::string Table3Text(const TimingRun& run, const ReportTiming& report) {
    const FrameTimes optimal = MeanTimes(run.optimal), focused = MeanTimes(run.focused);
    TextTable table({"stage (ms)", "optimal", "report", "focused", "report"});
    for (const Stage& s : kStages)
        table.AddRow({s.label, Fixed(s.ours(optimal), 2),
                      OptionalMs(report.Table3Ms(s.name, "optimal")), Fixed(s.ours(focused), 2),
                      OptionalMs(report.Table3Ms(s.name, "focused"))});
    return table.Render();
}

std::string RatioText(const TimingRun& run, const ReportTiming& report) {
    std::ostringstream out;
    out << "frame time optimal/focused: " << Fixed(Ratio(run), 3) << " (ours, " << run.lights.size()
        << " lights)";
    const std::optional<double> o = report.Table3Ms("total", "optimal");
    const std::optional<double> f = report.Table3Ms("total", "focused");
    if (o && f)
        out << "; report Table 3: " << Fixed(*o / *f, 3) << " (" << report.table3Lights
            << " lights, " << report.table3MapSide << "² maps)";
    const auto ratios = report.Table2Ratios(static_cast<int>(run.lights.size()));
    if (!ratios.empty()) {
        out << "; Table 2 (" << run.lights.size() << " lights):";
        for (const auto& [side, ratio] : ratios)
            out << " " << Fixed(ratio, 3) << " at " << side << "²";
    }
    out << '\n';
    return out.str();
}

nlohmann::json TimesJson(const FrameTimes& t) {
    nlohmann::json j = nlohmann::json::object();
    for (const auto& [name, value] : Columns(t)) j[name] = value;
    return j;
}

nlohmann::json MethodJson(const std::vector<FrameTimes>& frames) {
    nlohmann::json list = nlohmann::json::array();
    for (const FrameTimes& t : frames) list.push_back(TimesJson(t));
    return {{"frames", list}, {"mean", TimesJson(MeanTimes(frames))}};
}

}  // namespace

std::string TimingText(const spatial::Scene& scene, const TimingRun& run,
                       const ReportTiming& report) {
    std::ostringstream header;
    header << "timing: " << run.caseName << ", " << run.lights.size() << " lights, "
           << run.focused.size() << " frames per method over " << run.poses
           << " camera pose(s), frame " << scene.camera.resolution.width << "×"
           << scene.camera.resolution.height << ", readback " << scene.readback.width << "×"
           << scene.readback.height << ", maps " << scene.shadowMap.width << "×"
           << scene.shadowMap.height << "\nbackend " << run.backend << "\ntimed: " << run.passClock
           << "\noptimal: " << run.optimizer << " every " << run.updateEvery
           << " frame(s), step 1 from a standard map every " << run.standardEvery
           << " update(s), else from the light's previous map";
    std::ostringstream out;
    for (std::istringstream lines(header.str()); !lines.eof();) {
        std::string line;
        std::getline(lines, line);
        out << WrapText(line, kTerminalColumns, "  ");
    }
    out << '\n';
    TextTable table(kTextHeader);
    for (const auto& [name, frames] :
         {std::pair{"focused", &run.focused}, std::pair{"optimal", &run.optimal}}) {
        for (std::size_t k = 0; k < frames->size(); ++k)
            table.AddRow(TextRow(std::string(name) + " " + std::to_string(k), (*frames)[k]));
        table.AddRow(TextRow(std::string(name) + " mean", MeanTimes(*frames)));
    }
    out << table.Render() << '\n'
        << WrapText(RatioText(run, report), kTerminalColumns, "  ") << '\n';
    out << "report Table 3 (" << report.table3Lights << " lights, " << report.table3MapSide
        << "² maps, GeForce 7800 GT) beside our means:\n"
        << Table3Text(run, report);
    return out.str();
}

nlohmann::json TimingJson(const spatial::Scene& scene, const TimingRun& run,
                          const ReportTiming& report) {
    nlohmann::json lights = nlohmann::json::array();
    for (const spatial::Light& l : run.lights) lights.push_back(LightLabel(l));
    nlohmann::json table3 = nlohmann::json::object();
    const auto orNull = [](const std::optional<double>& v) {
        return v ? nlohmann::json(*v) : nlohmann::json(nullptr);
    };
    for (const Stage& s : kStages)
        table3[s.name] = {{"optimal", s.ours(MeanTimes(run.optimal))},
                          {"focused", s.ours(MeanTimes(run.focused))},
                          {"report_optimal", orNull(report.Table3Ms(s.name, "optimal"))},
                          {"report_focused", orNull(report.Table3Ms(s.name, "focused"))}};
    nlohmann::json table2 = nlohmann::json::array();
    for (const auto& [side, ratio] : report.Table2Ratios(static_cast<int>(run.lights.size())))
        table2.push_back({{"map", side}, {"ratio", ratio}});
    const std::optional<double> o = report.Table3Ms("total", "optimal");
    const std::optional<double> f = report.Table3Ms("total", "focused");
    return {{"case", run.caseName},
            {"backend", run.backend},
            {"pass_clock", run.passClock},
            {"frame", {scene.camera.resolution.width, scene.camera.resolution.height}},
            {"readback", {scene.readback.width, scene.readback.height}},
            {"shadow_map", {scene.shadowMap.width, scene.shadowMap.height}},
            {"lights", lights},
            {"poses", run.poses},
            {"optimizer", run.optimizer},
            {"update_every", run.updateEvery},
            {"standard_every", run.standardEvery},
            {"focused", MethodJson(run.focused)},
            {"optimal", MethodJson(run.optimal)},
            {"ratio",
             {{"ours", Ratio(run)},
              {"report_table3", o && f ? nlohmann::json(*o / *f) : nlohmann::json(nullptr)},
              {"report_table2", table2}}},
            {"table3", table3}};
}

std::string TimingCsv(const TimingRun& run) {
    std::ostringstream out;
    out << "method,frame";
    for (const auto& [name, value] : Columns(FrameTimes{})) out << ',' << name << "_ms";
    out << '\n';
    // Not a structured binding: clang 14 (the sanitizer build) cannot capture one in a lambda.
    for (const auto& method :
         {std::pair{"focused", &run.focused}, std::pair{"optimal", &run.optimal}}) {
        const auto* frames = method.second;
        const auto row = [&](const std::string& frame, const FrameTimes& t) {
            out << method.first << ',' << frame;
            for (const auto& [column, value] : Columns(t)) out << ',' << CsvNumber(value);
            out << '\n';
        };
        for (std::size_t k = 0; k < frames->size(); ++k) row(std::to_string(k), (*frames)[k]);
        row("mean", MeanTimes(*frames));
    }
    return out.str();
}

}  // namespace lexel::cases
