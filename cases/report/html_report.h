// index.html for the --out directories of `lexel run` and `lexel sweep`: one page that
// shows a run's tables and images together, says in a sentence what each table means and what
// each colour of an image is, and links every file the run wrote. Self-contained (inline CSS, no
// script), every link relative to the directory; names are percent-encoded (MarkdownLinkTarget)
// and text escaped (HtmlText).
#pragma once

#include <span>
#include <string>
#include <vector>

#include "lexel/cases/load/published.h"
#include "lexel/cases/report/spatial_report.h"
#include "lexel/cases/run/cascade_study.h"
#include "lexel/cases/run/sweep.h"
#include "lexel/flatland/methods.h"

namespace lexel::cases {

// A file the page links, with one line saying what it holds.
struct LinkedFile {
    std::string file;
    std::string description;
};

// `lexel run --out` on a 3D case: per light its facts, the methods' table, Algorithm 1's
// iterations, the cascades, and the frame, error and map images of every method; the camera-path
// study; the data files.
std::string SpatialRunHtml(const spatial::Scene& scene, const SpatialRun& run,
                           const std::vector<SpatialImageFile>& images,
                           const std::vector<LinkedFile>& files);

// `lexel run --out` on flatland cases: each case's table, and the files.
std::string FlatlandRunHtml(std::span<const flatland::CaseReport> reports,
                            const std::vector<LinkedFile>& files);

// `lexel sweep --out`: every table of the sweep with what it means (SweepSections), the
// cascade-count study and its plot when it ran (`cascadePlot`: the file name, empty without),
// the first light's images, and the files.
std::string SweepHtml(const SweepResult& result, const ReportTable1& report,
                      const CascadeCountStudy* study, const std::string& cascadePlot,
                      const std::vector<SpatialImageFile>& images,
                      const std::vector<LinkedFile>& files);

}  // namespace lexel::cases
