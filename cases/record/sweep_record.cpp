#include "lexel/cases/record/sweep_record.h"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <utility>

#include "lexel/solvers/errors.h"

namespace lexel::cases {

using spatial::Light;

std::string Fnv1a64Hex(const std::string& bytes) {
    std::uint64_t hash = 0xcbf29ce484222325ull;  // FNV-1a 64 offset basis and prime
    for (const char c : bytes) {
        hash ^= static_cast<unsigned char>(c);
        hash *= 0x100000001b3ull;
    }
    char hex[17];
    std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(hash));
    return hex;
}

namespace {

// The shortest text that reads back as `v` (std::to_chars without a format).
std::string Shortest(double v) {
    char text[32];
    const auto [end, error] = std::to_chars(text, text + sizeof text, v);
    return error == std::errc() ? std::string(text, end) : std::string("?");
}

}  // namespace

std::string LightsHash(const std::vector<Light>& lights) {
    std::string text;
    for (const Light& light : lights) {
        text += light.type == Light::Type::kPoint ? "point" : "directional";
        for (const glm::dvec3& v : {light.position, light.direction})
            for (int i = 0; i < 3; ++i) text += ' ' + Shortest(v[i]);
        text += '\n';
    }
    return Fnv1a64Hex(text);
}

namespace {

std::string Joined(const std::vector<std::string>& names) {
    std::string text;
    for (const std::string& n : names) text += (text.empty() ? "" : ",") + n;
    return text;
}

}  // namespace

std::string IdentityDifference(const SweepIdentity& a, const SweepIdentity& b) {
    const auto differ = [](const char* field, const std::string& x, const std::string& y) {
        return std::string(field) + " ('" + x + "' vs '" + y + "')";
    };
    if (a.caseName != b.caseName) return differ("case", a.caseName, b.caseName);
    if (a.caseHash != b.caseHash)
        return differ("case file (FNV-1a 64 of its bytes)", a.caseHash, b.caseHash);
    if (a.methods != b.methods) return differ("methods", Joined(a.methods), Joined(b.methods));
    if (a.backend != b.backend) return differ("backend", a.backend, b.backend);
    if (a.cascades != b.cascades)
        return differ("cascades", std::to_string(a.cascades), std::to_string(b.cascades));
    if (a.phases != b.phases)
        return differ("phases", std::to_string(a.phases), std::to_string(b.phases));
    if (a.maxPhases != b.maxPhases)
        return differ("max phases", std::to_string(a.maxPhases), std::to_string(b.maxPhases));
    if (a.shimmerPoses != b.shimmerPoses)
        return differ("shimmer poses", std::to_string(a.shimmerPoses),
                      std::to_string(b.shimmerPoses));
    if (a.lights != b.lights)
        return differ("number of lights", std::to_string(a.lights), std::to_string(b.lights));
    if (a.lightsHash != b.lightsHash)
        return differ("lights (FNV-1a 64 of their coordinates)", a.lightsHash, b.lightsHash);
    return {};
}

SweepRecord RecordOf(const SweepIdentity& identity, SweepShard shard, const SweepResult& share,
                     const std::vector<int>& studyCounts, const StudyMisclassified& study,
                     const std::vector<SpatialImageFile>& images) {
    SweepRecord record{identity, shard, share.seconds, {}, studyCounts, study, images};
    for (std::size_t l = 0; l < share.lights.size(); ++l)
        record.lights.push_back(
            {share.indices[l], share.lights[l], share.receiverPixels[l], share.cells[l]});
    return record;
}

SweepResult ResultOf(const SweepRecord& record) {
    SweepResult r;
    r.caseName = record.identity.caseName;
    r.methods = record.identity.methods;
    r.phases = record.identity.phases;
    r.maxPhases = record.identity.maxPhases;
    r.shimmerPoses = record.identity.shimmerPoses;
    r.seconds = record.seconds;
    for (const SweepLightRecord& light : record.lights) {
        r.indices.push_back(light.index);
        r.lights.push_back(light.light);
        r.cells.push_back(light.cells);
        r.receiverPixels.push_back(light.receiverPixels);
    }
    return r;
}

namespace {

// "3, 5 and 8" (the first ten, then "and N more").
std::string IndexList(const std::vector<std::size_t>& indices) {
    std::string text;
    const std::size_t shown = std::min<std::size_t>(indices.size(), 10);
    for (std::size_t i = 0; i < shown; ++i)
        text += (i == 0                                      ? ""
                 : i + 1 == shown && shown == indices.size() ? " and "
                                                             : ", ") +
                std::to_string(indices[i]);
    if (shown < indices.size()) text += " and " + std::to_string(indices.size() - shown) + " more";
    return text;
}

// Where each light of the whole sweep is: (record, position in it). Throws for a light in two
// records or in none.
std::vector<std::pair<std::size_t, std::size_t>> LightOwners(
    const std::vector<SweepRecord>& records, const std::vector<std::string>& sources) {
    const std::size_t total = records.front().identity.lights;
    constexpr std::size_t kNone = static_cast<std::size_t>(-1);
    std::vector<std::pair<std::size_t, std::size_t>> owner(total, {kNone, 0});
    for (std::size_t d = 0; d < records.size(); ++d)
        for (std::size_t l = 0; l < records[d].lights.size(); ++l) {
            const std::size_t i = records[d].lights[l].index;
            if (i >= total)
                throw InputError("merge: " + sources[d] + " holds light " + std::to_string(i) +
                                 " of a sweep of " + std::to_string(total) + " lights");
            if (owner[i].first != kNone)
                throw InputError("merge: light " + std::to_string(i) + " is in both " +
                                 sources[owner[i].first] + " and " + sources[d] +
                                 " (overlapping shards)");
            owner[i] = {d, l};
        }
    std::vector<std::size_t> missing;
    for (std::size_t i = 0; i < total; ++i)
        if (owner[i].first == kNone) missing.push_back(i);
    if (!missing.empty())
        throw InputError("merge: light" + std::string(missing.size() > 1 ? "s " : " ") +
                         IndexList(missing) + " of " + std::to_string(total) +
                         " are in none of the shards given (missing shards?)");
    return owner;
}

}  // namespace

MergedSweep MergeRecords(const std::vector<SweepRecord>& records,
                         const std::vector<std::string>& sources) {
    if (records.empty()) throw InputError("merge: give at least one shard directory");
    for (std::size_t d = 1; d < records.size(); ++d)
        if (const std::string diff = IdentityDifference(records[0].identity, records[d].identity);
            !diff.empty())
            throw InputError("merge: " + sources[d] + " is not a shard of the sweep of " +
                             sources[0] + ": they differ in " + diff);
    for (std::size_t d = 1; d < records.size(); ++d)
        if (records[d].studyCounts != records[0].studyCounts)
            throw InputError("merge: " + sources[d] + " and " + sources[0] +
                             " differ in the cascade-count study (one ran it, one did not)");
    MergedSweep merged;
    SweepRecord& out = merged.record;
    out.identity = records[0].identity;
    out.studyCounts = records[0].studyCounts;
    out.study.assign(out.studyCounts.size(), {});
    for (const SweepRecord& record : records) out.seconds += record.seconds;
    for (const auto& [d, l] : LightOwners(records, sources)) {
        out.lights.push_back(records[d].lights[l]);
        for (std::size_t c = 0; c < out.studyCounts.size(); ++c)
            out.study[c].push_back(records[d].study.at(c).at(l));
    }
    std::vector<Light> lights;
    for (const SweepLightRecord& light : out.lights) lights.push_back(light.light);
    if (LightsHash(lights) != out.identity.lightsHash)
        throw InputError("merge: the shards' lights do not hash to their sweep's lights_hash " +
                         out.identity.lightsHash + " (an edited record?)");
    for (std::size_t d = 0; d < records.size(); ++d)
        if (!records[d].images.empty()) {
            merged.imagesFrom = static_cast<int>(d);
            out.images = records[d].images;
        }
    merged.result = ResultOf(out);
    return merged;
}

}  // namespace lexel::cases
