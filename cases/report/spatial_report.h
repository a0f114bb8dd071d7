// `lexel run` on a 3D case: per fixed light and method the misclassified pixels, h and time as
// terminal text, one JSON document and CSV (schemas in cases/README.md), the camera-path study,
// and the images (frame, error map, shadow map with samples) per light and method.
#pragma once

#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "lexel/cases/report/text_table.h"
#include "lexel/cases/run/spatial_run.h"

namespace lexel::cases {

std::string SpatialRunText(const spatial::Scene& scene, const SpatialRun& run);

// The pieces SpatialRunText prints, for the other formats (html_report.h).
// "209 boundary samples", and " and 79 at thin-shadow contacts" when there are any (samples.h).
std::string SampleCountText(const spatial::LightSamples& samples);
// Per light: "light L: ... pixels face it, ..." and the truth map's disagreement when measured.
std::vector<std::string> LightHeaderLines(std::size_t light, const spatial::LightOutcome& o);
TextTable SpatialMethodTable(const spatial::LightOutcome& o);
// optimal*: h after each Algorithm 1 iteration, one line per method.
std::vector<std::string> IterationLines(const spatial::LightOutcome& o);
// Every cascade of the partitioned methods; nullopt when none ran.
std::optional<TextTable> CascadeTable(const spatial::LightOutcome& o);
// The virtual shadow maps' pages per method (page size, pool, requested, resident, dropped, LOD
// bias); nullopt when no vsm* method ran.
std::optional<TextTable> PageTable(const spatial::LightOutcome& o);
// The camera-path study of one light: the hysteresis per pose and the shimmer per method.
std::string CameraPathCaption(const CameraPathStudy& study, std::size_t light);
TextTable CameraPathTable(const CameraPathStudy& study);
std::string ShimmerCaption(std::size_t light);
TextTable ShimmerTable(const CameraPathStudy& study);
nlohmann::json SpatialRunJson(const spatial::Scene& scene, const SpatialRun& run);
std::string SpatialRunCsv(const SpatialRun& run);
// The columns of a method's row (JSON and CSV; the phase columns with --phases K > 1) as a
// Markdown table of key, unit and formats (columns.h, ColumnReference): cases/README.md's list.
std::string SpatialRunColumnReference();

// One image of WriteSpatialImages: its file name (in the directory given), what it shows, and its
// caption (the figure's title and first line, for an index).
struct SpatialImageFile {
    std::string file;
    std::size_t light = 0;
    std::string method;
    std::string kind;  // "frame", "errors", "map", or "map<i>" for cascade i
    std::string caption;
};

// <case>_light<k>_<method>_{frame,errors,map}.png in `dir` (the run must have kept its buffers),
// a partitioned method's map as map<i> per cascade; each a figure (cases/plot/image_figure.h)
// titled with the case, the light and the method, its counts, its colour key, uncovered pixels
// marked and, for maps, the depth scale. Returns the files in the order written. Throws
// std::runtime_error when a file cannot be written. `onImage` (may be empty) is called after each
// file (a progress bar; SpatialImageCount in all).
std::vector<SpatialImageFile> WriteSpatialImages(const std::filesystem::path& dir,
                                                 const spatial::Scene& scene, const SpatialRun& run,
                                                 const std::function<void()>& onImage = {});
// The images WriteSpatialImages writes for `run`.
std::size_t SpatialImageCount(const SpatialRun& run);

}  // namespace lexel::cases
