#include "lexel/cases/load/stored_fits.h"

#include "lexel/cases/load/json_reader.h"
#include "lexel/flatland/studies/scene_family.h"
#include "lexel/solvers/errors.h"

namespace lexel::cases {

namespace {

StoredFit ReadStoredFit(const JsonField& fit) {
    fit.ExpectObject({"case", "parameters", "worst_angle_deg", "worst_footprint"});
    StoredFit stored;
    stored.caseName = fit["case"].String();
    const flatland::SceneFamily* family = flatland::FindFamily(stored.caseName);
    if (!family) fit["case"].Fail("unknown thesis case '" + stored.caseName + "'");
    const JsonField values = fit["parameters"];
    values.ExpectKeys(family->ParameterNames());
    for (const auto& p : family->parameters)
        stored.parameters.push_back(values[p.name].NumberIn(p.lo, p.hi, false, false));
    stored.worstAngleDeg = fit["worst_angle_deg"].NumberIn(0.0, 180.0, false, false);
    stored.worstFootprint = fit["worst_footprint"].NumberIn(0.0, 1e9, false, false);
    return stored;
}

}  // namespace

std::vector<StoredFit> LoadStoredFits(const std::filesystem::path& path) {
    if (!std::filesystem::exists(path)) return {};
    const nlohmann::json document = ParseJsonFile(path);
    try {
        const JsonField root(document, "");
        root.ExpectObject({"fits"}, {"source"});
        if (root.Has("source")) root["source"].String();
        std::vector<StoredFit> fits;
        for (const JsonField& fit : root["fits"].Array()) fits.push_back(ReadStoredFit(fit));
        return fits;
    } catch (const InputError& e) {
        throw InputError(path.string() + ": " + e.what());
    }
}

}  // namespace lexel::cases
