#include "lexel/cases/record/sweep_record_reader.h"

#include <algorithm>
#include <limits>
#include <optional>
#include <set>
#include <string_view>

#include "lexel/cases/load/case_name.h"
#include "lexel/cases/load/hostile_file.h"
#include "lexel/cases/load/json_reader.h"
#include "lexel/cases/load/spatial_case.h"
#include "lexel/cases/record/sweep_record_text.h"
#include "lexel/solvers/errors.h"
#include "lexel/spatial/harness/sub_texel_phase.h"
#include "lexel/spatial/partitions.h"

namespace lexel::cases {

namespace fs = std::filesystem;
using spatial::Light;

namespace {

constexpr long long kMaxCount = std::numeric_limits<long long>::max();

// A double of the record: a number, or "inf", "-inf", "nan".
double RecordNumber(const JsonField& field, const nlohmann::json& value) {
    if (value.is_string()) {
        const std::string text = field.String();
        if (text == "inf") return std::numeric_limits<double>::infinity();
        if (text == "-inf") return -std::numeric_limits<double>::infinity();
        if (text == "nan") return std::numeric_limits<double>::quiet_NaN();
        field.Fail("must be a number, \"inf\", \"-inf\" or \"nan\", got \"" + text + "\"");
    }
    return field.Number();
}

std::vector<std::string> Strings(const JsonField& field) {
    std::vector<std::string> out;
    for (const JsonField& item : field.Array()) out.push_back(item.String());
    return out;
}

SweepShard ParseShardText(const JsonField& field) {
    const std::string text = field.String();
    const std::size_t slash = text.find('/');
    try {
        if (slash != std::string::npos) {
            std::size_t used = 0;
            const unsigned long k = std::stoul(text.substr(0, slash), &used);
            const unsigned long n = std::stoul(text.substr(slash + 1));
            if (used == slash && n >= 1 && k < n && n <= kMaxSweepLights) return {k, n};
        }
    } catch (const std::exception&) {
    }
    field.Fail("must be \"K/N\" with 0 <= K < N <= " + std::to_string(kMaxSweepLights) +
               ", got \"" + text + "\"");
}

SweepIdentity ParseIdentity(const JsonField& f) {
    f.ExpectObject({"case", "case_fnv1a64", "methods", "backend", "cascades", "phases",
                    "max_phases", "shimmer_poses", "lights", "lights_fnv1a64"});
    SweepIdentity id;
    id.caseName = f["case"].String();
    if (const std::optional<std::string> problem = CaseNameProblem(id.caseName))
        f["case"].Fail(*problem);
    id.caseHash = f["case_fnv1a64"].String();
    id.methods = Strings(f["methods"]);
    id.backend = f["backend"].String();
    id.cascades = static_cast<int>(f["cascades"].Integer(0, spatial::kMaxCascades));
    id.phases = static_cast<int>(f["phases"].Integer(1, spatial::kMaxPhases));
    id.maxPhases = static_cast<int>(f["max_phases"].Integer(id.phases, spatial::kMaxPhases));
    id.shimmerPoses = static_cast<int>(f["shimmer_poses"].Integer(0, kMaxShimmerPoses));
    if (id.shimmerPoses == 1)
        f["shimmer_poses"].Fail("must be 0 (none) or 2 ... " + std::to_string(kMaxShimmerPoses) +
                                ", got 1");
    id.lights = static_cast<std::size_t>(f["lights"].Integer(1, kMaxSweepLights));
    id.lightsHash = f["lights_fnv1a64"].String();
    return id;
}

glm::dvec3 RecordVec3(const JsonField& f, const nlohmann::json& value) {
    const std::vector<JsonField> items = f.Array(3);
    if (items.size() != 3) f.Fail("must be 3 numbers, got " + std::to_string(items.size()));
    glm::dvec3 v;
    for (int i = 0; i < 3; ++i) v[i] = RecordNumber(items[i], value.at(i));
    return v;
}

SweepCell ParseCell(const JsonField& f, const nlohmann::json& value) {
    const std::vector<JsonField> x = f.Array();
    constexpr std::size_t kFields = std::size(kSweepCellFields);
    if (x.size() != kFields)
        f.Fail("must have " + std::to_string(kFields) + " fields, got " + std::to_string(x.size()));
    SweepCell c;
    c.misclassified = x[0].Integer(0, kMaxCount);
    c.h = RecordNumber(x[1], value[1]);
    c.hGrazing = RecordNumber(x[2], value[2]);
    c.winner = x[3].String();
    c.footprintMean = RecordNumber(x[4], value[4]);
    c.footprintMax = RecordNumber(x[5], value[5]);
    c.uncovered = x[6].Integer(0, kMaxCount);
    c.cascades = static_cast<int>(x[7].Integer(0, 1 << 30));
    c.emptyPartitions = static_cast<int>(x[8].Integer(0, 1 << 30));
    c.storageFactor = RecordNumber(x[9], value[9]);
    c.pagesRequested = x[10].Integer(-1, kMaxCount);
    c.pagesResident = x[11].Integer(-1, kMaxCount);
    c.pagesDropped = x[12].Integer(-1, kMaxCount);
    c.lodBias = RecordNumber(x[13], value[13]);
    c.misclassifiedMean = x[14].NumberIn(0.0, static_cast<double>(kMaxCount), false, false);
    c.misclassifiedError = x[15].NumberIn(0.0, static_cast<double>(kMaxCount), false, false);
    c.e = RecordNumber(x[16], value[16]);
    c.shimmer = RecordNumber(x[17], value[17]);
    c.storageFactorP99 = RecordNumber(x[18], value[18]);
    c.phases = static_cast<int>(x[19].Integer(1, spatial::kMaxPhases));
    return c;
}

// One light: its index, kind, coordinates, receiver pixels and `methods` cells with their times.
SweepLightRecord ParseLight(const JsonField& f, const nlohmann::json& value, std::size_t methods,
                            bool withStudy) {
    if (withStudy)
        f.ExpectObject(
            {"index", "type", "position", "direction", "receiver_pixels", "cells", "ms", "study"});
    else
        f.ExpectObject(
            {"index", "type", "position", "direction", "receiver_pixels", "cells", "ms"});
    SweepLightRecord light;
    light.index = static_cast<std::size_t>(f["index"].Integer(0, kMaxCount));
    const std::string type = f["type"].String();
    if (type != "point" && type != "directional")
        f["type"].Fail("must be \"point\" or \"directional\", got \"" + type + "\"");
    light.light.type = type == "point" ? Light::Type::kPoint : Light::Type::kDirectional;
    light.light.position = RecordVec3(f["position"], value.at("position"));
    light.light.direction = RecordVec3(f["direction"], value.at("direction"));
    light.receiverPixels = f["receiver_pixels"].Integer(0, kMaxCount);
    const std::vector<JsonField> cells = f["cells"].Array(), ms = f["ms"].Array();
    if (cells.size() != methods || ms.size() != methods)
        f["cells"].Fail("must have one cell and one time per method (" + std::to_string(methods) +
                        "), got " + std::to_string(cells.size()) + " and " +
                        std::to_string(ms.size()));
    for (std::size_t m = 0; m < methods; ++m) {
        light.cells.push_back(ParseCell(cells[m], value.at("cells").at(m)));
        light.cells.back().ms = RecordNumber(ms[m], value.at("ms").at(m));
    }
    return light;
}

// The study's misclassified pixels per study method.
std::vector<double> StudyCounts(const JsonField& f, std::size_t studyMethods) {
    const std::vector<JsonField> items = f.Array();
    if (items.size() != studyMethods)
        f.Fail("must have one count per study method (" + std::to_string(studyMethods) + "), got " +
               std::to_string(items.size()));
    std::vector<double> counts;  // phase means
    for (const JsonField& item : items)
        counts.push_back(item.NumberIn(0.0, static_cast<double>(kMaxCount), false, false));
    return counts;
}

SpatialImageFile ParseImage(const JsonField& f) {
    f.ExpectObject({"file", "light", "method", "kind", "caption"});
    SpatialImageFile image;
    image.file = f["file"].String();
    // A plain file name beside the record: merge copies it, and nothing outside the directory.
    // A case name (a safe file stem, echoed nowhere) with ".png" after it.
    if (!image.file.ends_with(".png") ||
        CaseNameProblem(std::string_view(image.file).substr(0, image.file.size() - 4)))
        f["file"].Fail("must be a plain .png file name (a safe file stem and .png)");
    image.light = static_cast<std::size_t>(f["light"].Integer(0, kMaxCount));
    image.method = f["method"].String();
    image.kind = f["kind"].String();
    image.caption = f["caption"].String();
    return image;
}

SweepRecord ParseRecord(const nlohmann::json& doc) {
    const JsonField f(doc, "");
    f.ExpectObject({"format", "identity", "shard", "seconds", "cell_fields", "study_counts",
                    "first_light_images", "lights"});
    if (f["format"].String() != kSweepRecordFormat)
        f["format"].Fail("must be \"" + std::string(kSweepRecordFormat) + "\"");
    SweepRecord r;
    r.identity = ParseIdentity(f["identity"]);
    r.shard = ParseShardText(f["shard"]);
    r.seconds = f["seconds"].Number();
    const std::vector<std::string> fields = Strings(f["cell_fields"]);
    if (fields !=
        std::vector<std::string>(std::begin(kSweepCellFields), std::end(kSweepCellFields)))
        f["cell_fields"].Fail("are not this lexel's cell fields (a record of another version?)");
    const std::vector<int> extraCounts = CascadeStudyExtraCounts(r.identity.cascades);
    for (const JsonField& k : f["study_counts"].Array()) {
        r.studyCounts.push_back(static_cast<int>(k.Integer(1, spatial::kMaxCascades)));
        if (std::find(extraCounts.begin(), extraCounts.end(), r.studyCounts.back()) ==
                extraCounts.end() ||
            (r.studyCounts.size() > 1 && r.studyCounts.back() <= r.studyCounts.rbegin()[1]))
            k.Fail("must be a count of the partitions study beside cascades " +
                   std::to_string(r.identity.cascades) + ", increasing");
    }
    std::set<std::string> imageFiles;
    for (const JsonField& image : f["first_light_images"].Array()) {
        r.images.push_back(ParseImage(image));
        if (!imageFiles.insert(r.images.back().file).second)
            image["file"].Fail("names an image listed before");
    }
    const std::size_t studyMethods = CascadeStudyMethods(r.identity.methods).size();
    r.study.assign(r.studyCounts.size(), {});
    const std::vector<JsonField> lights = f["lights"].Array();
    for (std::size_t l = 0; l < lights.size(); ++l) {
        const nlohmann::json& value = doc.at("lights").at(l);
        r.lights.push_back(ParseLight(lights[l], value, r.identity.methods.size(), true));
        if (l > 0 && r.lights[l].index <= r.lights[l - 1].index)
            lights[l]["index"].Fail("must increase from light to light");
        if (r.lights[l].index >= r.identity.lights ||
            r.lights[l].index % r.shard.count != r.shard.index)
            lights[l]["index"].Fail("must be a light of shard " + ShardText(r.shard) + " of " +
                                    std::to_string(r.identity.lights) + " lights, got " +
                                    std::to_string(r.lights[l].index));
        const std::vector<JsonField> study = lights[l]["study"].Array();
        if (study.size() != r.studyCounts.size())
            lights[l]["study"].Fail("must have one entry per study count (" +
                                    std::to_string(r.studyCounts.size()) + ")");
        for (std::size_t c = 0; c < study.size(); ++c)
            r.study[c].push_back(StudyCounts(study[c], studyMethods));
    }
    return r;
}

}  // namespace

SweepRecord ParseSweepRecord(const std::string& text, const std::string& source) {
    const nlohmann::json doc = ParseJsonText(text, source);
    try {
        return ParseRecord(doc);
    } catch (const InputError& e) {
        throw InputError(source + ": " + e.what());
    }
}

SweepRecord ReadSweepRecord(const fs::path& dir) {
    const fs::path path = dir / "sweep-record.json";
    const std::string text =
        ReadHostileFile(path, kMaxSweepRecordBytes, path.string(),
                        " (is " + dir.string() + " the --out directory of a lexel sweep?)");
    return ParseSweepRecord(text, path.string());
}

JournalHeader ParseJournalHeader(const std::string& line, const std::string& source) {
    const nlohmann::json doc = ParseJsonText(line, source);
    try {
        const JsonField f(doc, "");
        f.ExpectObject({"format", "identity", "shard"});
        if (f["format"].String() != kSweepJournalFormat)
            f["format"].Fail("must be \"" + std::string(kSweepJournalFormat) + "\"");
        return {ParseIdentity(f["identity"]), ParseShardText(f["shard"])};
    } catch (const InputError& e) {
        throw InputError(source + ": " + e.what());
    }
}

void ParseJournalEntry(const std::string& line, const std::string& source, std::size_t methods,
                       std::size_t studyMethods, SweepDone& done) {
    const nlohmann::json doc = ParseJsonText(line, source);
    try {
        const JsonField f(doc, "");
        if (f.Has("light")) {
            f.ExpectObject({"light"});
            SweepLightRecord light = ParseLight(f["light"], doc.at("light"), methods, false);
            done.lights[light.index] = std::move(light);
            return;
        }
        f.ExpectObject({"study"});
        const JsonField s = f["study"];
        s.ExpectObject({"k", "index", "misclassified"});
        StudyLightRecord light;
        light.count = static_cast<int>(s["k"].Integer(1, 1 << 20));
        light.index = static_cast<std::size_t>(s["index"].Integer(0, kMaxCount));
        light.misclassified = StudyCounts(s["misclassified"], studyMethods);
        done.study[{light.count, light.index}] = std::move(light);
    } catch (const InputError& e) {
        throw InputError(source + ": " + e.what());
    }
}

}  // namespace lexel::cases
