#include "lexel/cases/record/sweep_record_text.h"

#include <cmath>
#include <nlohmann/json.hpp>

namespace lexel::cases {

namespace {

using nlohmann::json;
using spatial::Light;

// A double as JSON: a number (nlohmann::json writes the shortest digits that read back as the
// same double), or "inf", "-inf", "nan" where JSON has none.
json Number(double v) {
    if (std::isnan(v)) return "nan";
    if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
    return v;
}

json Vec3(const glm::dvec3& v) { return json::array({Number(v.x), Number(v.y), Number(v.z)}); }

json IdentityJson(const SweepIdentity& id) {
    return {{"case", id.caseName},        {"case_fnv1a64", id.caseHash},
            {"methods", id.methods},      {"backend", id.backend},
            {"cascades", id.cascades},    {"phases", id.phases},
            {"max_phases", id.maxPhases}, {"shimmer_poses", id.shimmerPoses},
            {"lights", id.lights},        {"lights_fnv1a64", id.lightsHash}};
}

json CellJson(const SweepCell& c) {
    return json::array({c.misclassified,
                        Number(c.h),
                        Number(c.hGrazing),
                        c.winner,
                        Number(c.footprintMean),
                        Number(c.footprintMax),
                        c.uncovered,
                        c.cascades,
                        c.emptyPartitions,
                        Number(c.storageFactor),
                        c.pagesRequested,
                        c.pagesResident,
                        c.pagesDropped,
                        Number(c.lodBias),
                        Number(c.misclassifiedMean),
                        Number(c.misclassifiedError),
                        Number(c.e),
                        Number(c.shimmer),
                        Number(c.storageFactorP99),
                        c.phases});
}

json LightJson(const SweepLightRecord& light) {
    json cells = json::array(), ms = json::array();
    for (const SweepCell& c : light.cells) {
        cells.push_back(CellJson(c));
        ms.push_back(Number(c.ms));
    }
    return {{"index", light.index},
            {"type", light.light.type == Light::Type::kPoint ? "point" : "directional"},
            {"position", Vec3(light.light.position)},
            {"direction", Vec3(light.light.direction)},
            {"receiver_pixels", light.receiverPixels},
            {"cells", cells},
            {"ms", ms}};
}

json ImageJson(const SpatialImageFile& image) {
    return {{"file", image.file},
            {"light", image.light},
            {"method", image.method},
            {"kind", image.kind},
            {"caption", image.caption}};
}

}  // namespace

std::string SweepRecordText(const SweepRecord& record) {
    json images = json::array();
    for (const SpatialImageFile& image : record.images) images.push_back(ImageJson(image));
    std::string text = "{\n";
    const auto field = [&](const char* key, const json& value) {
        text += "  \"" + std::string(key) + "\": " + value.dump() + ",\n";
    };
    field("format", kSweepRecordFormat);
    field("identity", IdentityJson(record.identity));
    field("shard", ShardText(record.shard));
    field("seconds", Number(record.seconds));
    field("cell_fields", kSweepCellFields);
    field("study_counts", record.studyCounts);
    field("first_light_images", images);
    text += "  \"lights\": [";
    for (std::size_t l = 0; l < record.lights.size(); ++l) {
        json light = LightJson(record.lights[l]);
        json study = json::array();
        for (const auto& perLight : record.study) study.push_back(perLight.at(l));
        light["study"] = study;
        text += std::string(l == 0 ? "\n" : ",\n") + "    " + light.dump();
    }
    text += record.lights.empty() ? "]\n}\n" : "\n  ]\n}\n";
    return text;
}

std::string JournalHeaderLine(const SweepIdentity& identity, SweepShard shard) {
    return json{{"format", kSweepJournalFormat},
                {"identity", IdentityJson(identity)},
                {"shard", ShardText(shard)}}
               .dump() +
           "\n";
}

std::string JournalLightLine(const SweepLightRecord& light) {
    return json{{"light", LightJson(light)}}.dump() + "\n";
}

std::string JournalStudyLine(const StudyLightRecord& light) {
    return json{{"study",
                 {{"k", light.count},
                  {"index", light.index},
                  {"misclassified", light.misclassified}}}}
               .dump() +
           "\n";
}

}  // namespace lexel::cases
