#include "lexel/cases/report/html_report.h"

#include <cstdio>
#include <map>
#include <sstream>

#include "lexel/cases/report/flatland_report.h"
#include "lexel/cases/report/sweep_report.h"
#include "lexel/cases/report/text_table.h"
#include "lexel/spatial/harness/images.h"

namespace lexel::cases {
namespace {

// One stylesheet for every page: readable widths, tables that line numbers up, image grids.
constexpr const char* kStyle = R"(
body { font: 15px/1.45 system-ui, -apple-system, "Segoe UI", sans-serif; color: #1d1d1f;
       margin: 0 auto; padding: 1.5em 2em 4em; max-width: 1400px; }
h1 { font-size: 1.7em; margin-bottom: 0.2em; }
h2 { font-size: 1.3em; margin-top: 2em; border-bottom: 1px solid #ccc; padding-bottom: 0.2em; }
h3 { font-size: 1.1em; margin-top: 1.5em; }
p, li { max-width: 60em; }
.lead { color: #444; font-size: 1.05em; }
.note { color: #555; font-size: 0.93em; }
nav { background: #f4f4f6; padding: 0.6em 1em; border-radius: 6px; }
nav a { margin-right: 1.2em; }
table { border-collapse: collapse; margin: 0.8em 0; font-size: 0.92em; }
th, td { padding: 0.25em 0.7em; border-bottom: 1px solid #e2e2e6; text-align: left;
         white-space: nowrap; }
th { background: #f4f4f6; vertical-align: bottom; }
td.num, th.num { text-align: right; font-variant-numeric: tabular-nums; }
tbody tr:hover { background: #fafae6; }
tr.published td { color: #666; font-style: italic; }
dl { display: grid; grid-template-columns: max-content 1fr; gap: 0.25em 1em; max-width: 70em; }
dt { font-weight: 600; }
dd { margin: 0; }
.images { margin: 0.4em 0 1.4em; }
.imagerow { display: flex; gap: 0.8em; margin-bottom: 0.8em; align-items: flex-start; }
.imagerow .method { font-weight: 600; width: 9em; flex: none; padding-top: 0.3em; }
.figures { flex: 1; display: grid; grid-template-columns: repeat(auto-fill, minmax(280px, 1fr));
           gap: 0.6em; }
figure { margin: 0; }
figure img { width: 100%; border: 1px solid #ddd; }
figcaption { font-size: 0.85em; color: #555; }
.key span { display: inline-block; width: 0.9em; height: 0.9em; border: 1px solid #777;
            vertical-align: -0.1em; margin: 0 0.3em 0 1em; }
.key span:first-child { margin-left: 0; }
)";

std::string Link(const std::string& file, const std::string& text) {
    return "<a href=\"" + MarkdownLinkTarget(file) + "\">" + HtmlText(text) + "</a>";
}

std::string Paragraph(const std::string& text, const char* cssClass = nullptr) {
    return std::string("<p") + (cssClass ? std::string(" class=\"") + cssClass + "\"" : "") + ">" +
           HtmlText(text) + "</p>\n";
}

std::string Page(const std::string& title, const std::string& body) {
    return "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
           "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<title>" +
           HtmlText(title) + "</title>\n<style>" + kStyle + "</style>\n</head>\n<body>\n" + body +
           "<p class=\"note\">Written by lexel. Every number is also in the CSV and JSON files "
           "above; their columns are described in cases/README.md.</p>\n</body>\n</html>\n";
}

std::string FilesSection(const std::vector<LinkedFile>& files) {
    std::string out = "<h2 id=\"files\">Files</h2>\n<ul>\n";
    for (const LinkedFile& f : files)
        out += "<li>" + Link(f.file, f.file) + ": " + HtmlText(f.description) + "</li>\n";
    return out + "</ul>\n";
}

std::string SectionHtml(const ReportSection& s, const std::string& id) {
    std::string out = "<h2 id=\"" + id + "\">" + HtmlText(s.title) + "</h2>\n";
    if (!s.explanation.empty()) out += Paragraph(s.explanation);
    out += s.table.RenderHtml();
    for (const std::string& note : s.notes) out += Paragraph(note, "note");
    return out;
}

// A colour key in HTML (the images carry their own; this one is read before them).
std::string KeySwatch(const spatial::ImageColour& c, const std::string& label) {
    char rgb[32];
    std::snprintf(rgb, sizeof rgb, "#%02x%02x%02x", static_cast<int>(255 * c.r + 0.5f),
                  static_cast<int>(255 * c.g + 0.5f), static_cast<int>(255 * c.b + 0.5f));
    return "<span style=\"background:" + std::string(rgb) + "\"></span>" + HtmlText(label);
}

std::string ImageKeys() {
    using namespace spatial;
    return "<dl>\n<dt>frame</dt><dd class=\"key\">the camera's image shaded with the method's "
           "shadows: " +
           KeySwatch({0.75f, 0.75f, 0.75f}, "lit (grey by n·l)") +
           KeySwatch({kAmbient, kAmbient, kAmbient}, "shadowed or facing away") +
           KeySwatch(kUncoveredColour, "uncovered: no map covers it") +
           KeySwatch(kSkyColour, "no geometry") +
           "</dd>\n<dt>errors</dt><dd class=\"key\">where the method's shadow decision differs "
           "from exact shadow rays: " +
           KeySwatch(kFalseShadowColour, "false shadow") +
           KeySwatch(kFalseLightColour, "false light") +
           KeySwatch({0.6f, 0.6f, 0.6f}, "agrees (darker: truly shadowed)") +
           KeySwatch(kUncoveredColour, "uncovered") +
           "</dd>\n<dt>map</dt><dd class=\"key\">the shadow map's depth (near light, far dark; "
           "the scale is under each image) with " +
           KeySwatch(kVisiblePointColour, "visible points of the readback") +
           KeySwatch(kBoundarySampleColour, "boundary samples") +
           KeySwatch(kEmptyTexelColour, "empty texels") +
           "; a partitioned method has one map per cascade</dd>\n</dl>\n";
}

// The images of one light: a row per method, its frame, errors and map(s).
std::string ImageGrid(const std::vector<SpatialImageFile>& images, std::size_t light) {
    std::vector<std::string> methods;
    std::map<std::string, std::vector<const SpatialImageFile*>> byMethod;
    for (const SpatialImageFile& image : images) {
        if (image.light != light) continue;
        if (!byMethod.count(image.method)) methods.push_back(image.method);
        byMethod[image.method].push_back(&image);
    }
    if (methods.empty()) return "";
    std::string out = "<div class=\"images\">\n";
    for (const std::string& method : methods) {
        out += "<div class=\"imagerow\"><div class=\"method\">" + HtmlText(method) +
               "</div><div class=\"figures\">\n";
        for (const SpatialImageFile* image : byMethod[method]) {
            const std::string target = MarkdownLinkTarget(image->file);
            out += "<figure><a href=\"" + target + "\"><img src=\"" + target +
                   "\" loading=\"lazy\" alt=\"" + HtmlText(image->caption) + "\"></a><figcaption>" +
                   HtmlText(image->kind) + "</figcaption></figure>\n";
        }
        out += "</div></div>\n";
    }
    return out + "</div>\n";
}

constexpr const char* kRunDefinitions =
    "<dl>\n"
    "<dt>counted pixels</dt><dd>visible frame pixels whose surface faces the light (n·l &gt; 0); "
    "those facing away are in shadow for every method and the truth alike</dd>\n"
    "<dt>misclassified</dt><dd>counted pixels whose shadow decision differs from an exact "
    "(Embree) shadow ray: false shadow (a lit pixel shadowed) plus false light (a shadowed "
    "pixel lit); the report's Table 1 measure, lower is better</dd>\n"
    "<dt>uncovered</dt><dd>counted pixels no map covers (outside its texels, behind its plane, "
    "or outside every cascade); they are shaded lit</dd>\n"
    "<dt>σ1(J⁻¹)</dt><dd>per covered pixel, the most frame pixels one texel spans (above 1 "
    "where the map undersamples the view): mean and maximum</dd>\n"
    "<dt>storage factor</dt><dd>Lloyd et al. 2006's S̄ measured: the texels, over the frame's "
    "pixels, the map would need for a worst perspective aliasing of 1</dd>\n"
    "<dt>h (eq. 6)</dt><dd>the energy Algorithm 1 minimizes: Σ ||J⁻¹||² over the light's "
    "boundary samples</dd>\n"
    "<dt>ms</dt><dd>the time to compute the light matrix</dd>\n"
    "</dl>\n";

std::string LightSection(const SpatialRun& run, std::size_t l,
                         const std::vector<SpatialImageFile>& images) {
    const spatial::LightOutcome& o = run.outcomes[l];
    std::string out = "<h2 id=\"light" + std::to_string(l) + "\">Light " + std::to_string(l) +
                      ": " + HtmlText(LightLabel(o.light)) + "</h2>\n";
    std::string facts = std::to_string(o.receiverPixels) + " counted pixels face it, " +
                        std::to_string(o.truthShadowed) + " of them shadowed (Embree rays); " +
                        SampleCountText(o.samples);
    const std::vector<std::string> header = LightHeaderLines(l, o);
    for (std::size_t k = 1; k < header.size(); ++k) facts += "; " + header[k];
    out += Paragraph(facts + ".");
    out += "<p>Per method, on the " + std::to_string(o.receiverPixels) +
           " counted pixels (lower is better in every column but ms):</p>\n";
    out += SpatialMethodTable(o).RenderHtml();
    for (const std::string& line : IterationLines(o)) out += Paragraph(line, "note");
    if (const std::optional<TextTable> cascades = CascadeTable(o)) {
        out += "<h3>Cascades of the partitioned methods</h3>\n" +
               Paragraph(
                   "Each partitioned method's maps: the planar eye depth interval each "
                   "serves, its texels, the readback points it was fitted to, the frame "
                   "pixels it shades and its part of h.") +
               cascades->RenderHtml();
    }
    if (const std::optional<TextTable> pages = PageTable(o)) {
        out += "<h3>Pages of the virtual shadow maps</h3>\n" +
               Paragraph(
                   "Each virtual shadow map's page size and physical pool (its pages hold at "
                   "most the single map's texels), the distinct pages the readback's pixels "
                   "asked for, those resident (the most requested) and those dropped, and the "
                   "LOD bias the requests were made with.") +
               pages->RenderHtml();
    }
    const std::string grid = ImageGrid(images, l);
    if (!grid.empty())
        out += "<h3>Images</h3>\n" +
               Paragraph(
                   "Click an image for its full size; each carries its title, counts and "
                   "colour key.") +
               grid;
    return out;
}

std::string CameraPathSection(const CameraPathStudy& study, std::size_t l) {
    return "<h2 id=\"path" + std::to_string(l) + "\">" + HtmlText(CameraPathCaption(study, l)) +
           "</h2>\n" +
           Paragraph(
               "Algorithm 1 step 5 along the case's camera_path: at each pose whether "
               "optimal's new matrix replaced the kept one, the median per-sample badness "
               "of both, and the misclassified pixels with the hysteresis and without it.") +
           CameraPathTable(study).RenderHtml() + "<h3>" + HtmlText(ShimmerCaption(l)) + "</h3>\n" +
           ShimmerTable(study).RenderHtml();
}

std::string Nav(const std::vector<std::pair<std::string, std::string>>& anchors) {
    std::string out = "<nav>";
    for (const auto& [id, text] : anchors)
        out += "<a href=\"#" + id + "\">" + HtmlText(text) + "</a>";
    return out + "</nav>\n";
}

// The cascade-count study: its plot (`cascadePlot`, a file name; none when empty) and table.
std::string PartitionStudySection(const CascadeCountStudy& study, const std::string& cascadePlot) {
    std::string out =
        "<h2 id=\"partitions\">Partitions k = 1, 2, 4, 8 at equal texels</h2>\n" +
        Paragraph(
            "The partitioned methods rerun on the same lights with k maps that together hold the "
            "single map's texels: mean misclassified pixels against k; optimal's single map is "
            "the dashed line.");
    if (!cascadePlot.empty())
        out += "<figure><img src=\"" + MarkdownLinkTarget(cascadePlot) +
               "\" alt=\"misclassified pixels against partitions k\" "
               "style=\"max-width:900px\"></figure>\n";
    std::vector<std::string> header = {"method"};
    for (int k : study.counts) header.push_back("k = " + std::to_string(k));
    TextTable table(header);
    if (study.optimalMean) {
        std::vector<std::string> row = {"optimal (one map)"};
        for (std::size_t k = 0; k < study.counts.size(); ++k)
            row.push_back(k == 0 ? Fixed(*study.optimalMean, 1) : "");
        table.AddRow(row);
    }
    for (std::size_t m = 0; m < study.methods.size(); ++m) {
        std::vector<std::string> row = {study.methods[m]};
        for (double mean : study.meanMisclassified[m]) row.push_back(Fixed(mean, 1));
        table.AddRow(row);
    }
    return out + table.RenderHtml();
}

}  // namespace

std::string SpatialRunHtml(const spatial::Scene& scene, const SpatialRun& run,
                           const std::vector<SpatialImageFile>& images,
                           const std::vector<LinkedFile>& files) {
    std::vector<std::pair<std::string, std::string>> anchors;
    for (std::size_t l = 0; l < run.outcomes.size(); ++l)
        anchors.emplace_back("light" + std::to_string(l), "light " + std::to_string(l));
    for (std::size_t l = 0; l < run.cameraPath.size(); ++l)
        anchors.emplace_back("path" + std::to_string(l), "camera path " + std::to_string(l));
    anchors.emplace_back("files", "files");
    std::string body = "<h1>lexel run: " + HtmlText(scene.name) + "</h1>\n";
    body += Paragraph(
        "Camera " + std::to_string(scene.camera.resolution.width) + "×" +
            std::to_string(scene.camera.resolution.height) + ", shadow maps " +
            std::to_string(scene.shadowMap.width) + "×" + std::to_string(scene.shadowMap.height) +
            ", readback " + std::to_string(scene.readback.width) + "×" +
            std::to_string(scene.readback.height) + ", " + std::to_string(run.outcomes.size()) +
            (run.outcomes.size() == 1 ? " light" : " lights") + ", " +
            std::to_string(run.outcomes.empty() ? 0 : run.outcomes.front().methods.size()) +
            " methods. Every method computes a light matrix for each light; its shadow map's "
            "decisions on the frame are compared with exact shadow rays.",
        "lead");
    body += Nav(anchors);
    body += "<h2>How to read this page</h2>\n" + std::string(kRunDefinitions);
    body += "<p>The images, per light and method:</p>\n" + ImageKeys();
    for (std::size_t l = 0; l < run.outcomes.size(); ++l) body += LightSection(run, l, images);
    for (std::size_t l = 0; l < run.cameraPath.size(); ++l)
        body += CameraPathSection(run.cameraPath[l], l);
    body += FilesSection(files);
    return Page("lexel run: " + scene.name, body);
}

std::string FlatlandRunHtml(std::span<const flatland::CaseReport> reports,
                            const std::vector<LinkedFile>& files) {
    std::string body = "<h1>lexel run: " + std::to_string(reports.size()) + " flatland case" +
                       (reports.size() == 1 ? "" : "s") + "</h1>\n";
    body += Paragraph(
        "Per case and method the lexel plane angle (degrees counterclockwise from vertical) and "
        "the footprint f = |dp/dl| (pixels per lexel) over the visible pixels at full resolution: "
        "its worst, average, mean + σ, the sums L1 = Σf and L2 = Σf², L∞ = max f, and the "
        "solver's time (Chong 2003, §4.1.3). Lower footprints alias less.",
        "lead");
    for (const flatland::CaseReport& r : reports)
        body += "<h2>" + HtmlText(CaseHeader(r)) + "</h2>\n" + CaseMethodTable(r).RenderHtml();
    body += FilesSection(files);
    return Page("lexel run: flatland", body);
}

std::string SweepHtml(const SweepResult& r, const ReportTable1& report,
                      const CascadeCountStudy* study, const std::string& cascadePlot,
                      const std::vector<SpatialImageFile>& images,
                      const std::vector<LinkedFile>& files) {
    const std::vector<ReportSection> sections = SweepSections(r, report, false);
    std::vector<std::pair<std::string, std::string>> anchors;
    for (std::size_t k = 0; k < sections.size(); ++k) {
        // The title up to its first parenthesis or colon.
        std::string name = sections[k].title.substr(0, sections[k].title.find_first_of("(:"));
        while (!name.empty() && name.back() == ' ') name.pop_back();
        anchors.emplace_back("table" + std::to_string(k), name);
    }
    if (study) anchors.emplace_back("partitions", "partitions k");
    if (!images.empty()) anchors.emplace_back("light0", "first light's images");
    anchors.emplace_back("files", "files");
    std::string body = "<h1>lexel sweep: " + HtmlText(r.caseName) + ", " +
                       std::to_string(r.lights.size()) + " lights</h1>\n";
    body += Paragraph(
        "The experiment of Chong & Gortler's report §3: every method computes a light matrix for "
        "each of " +
            std::to_string(r.lights.size()) +
            " lights on a distant hemisphere around the scene, and the frame's shadow decisions "
            "are compared with exact shadow rays. A misclassified pixel is a counted pixel "
            "(visible, facing the light) whose decision differs from its ray's. The tables "
            "average over the lights (" +
            Fixed(r.seconds, 1) +
            " s in all); lower is better in every column but the % of "
            "lights beating the reference.",
        "lead");
    body += Nav(anchors);
    for (std::size_t k = 0; k < sections.size(); ++k)
        body += SectionHtml(sections[k], "table" + std::to_string(k));
    if (study) body += PartitionStudySection(*study, cascadePlot);
    if (!images.empty())
        body += "<h2 id=\"light0\">The first light's images: " +
                HtmlText(LightLabel(r.lights.front())) + "</h2>\n" +
                Paragraph(
                    "The partitioned methods on the sweep's first light, as lexel run "
                    "--out draws them.") +
                ImageKeys() + ImageGrid(images, 0);
    body += FilesSection(files);
    return Page("lexel sweep: " + r.caseName, body);
}

}  // namespace lexel::cases
