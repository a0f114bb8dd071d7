#include "lexel/cases/studies/thesis/fit_thesis.h"

#include <algorithm>
#include <optional>

#include "lexel/cases/load/flatland_case.h"
#include "lexel/cases/studies/thesis/thesis_scene.h"
#include "lexel/solvers/errors.h"
#include "lexel/solvers/stopwatch.h"

namespace lexel::cases {

namespace fs = std::filesystem;
using flatland::FitResult;
using flatland::SceneFamily;

namespace {

std::string StemOf(const std::string& file) { return fs::path(file).stem().string(); }

const SceneFamily& FamilyOf(const ThesisTable& thesis) {
    const SceneFamily* family = flatland::FindFamily(StemOf(thesis.file));
    if (!family)
        throw InputError("thesis table '" + thesis.title + "': no scene family for case '" +
                         StemOf(thesis.file) + "'");
    return *family;
}

const StoredFit* FindStored(const std::vector<StoredFit>& stored, const std::string& name) {
    for (const StoredFit& s : stored)
        if (s.caseName == name) return &s;
    return nullptr;
}

// The best of the committed fit (as it stands and refined) and the random starts.
FitResult FitOneCase(const SceneFamily& family, const flatland::PublishedTable& table,
                     const FitThesisOptions& options, const StoredFit* stored,
                     const fs::path& storedPath) {
    flatland::FitOptions fit;
    fit.seed = options.seed;
    fit.screenSamples = options.samples;
    fit.starts = options.starts;
    fit.minimaxRounds = options.minimaxRounds;
    fit.patternEvaluations = options.patternEvaluations;
    std::optional<FitResult> best;
    auto consider = [&](FitResult r) {
        const int evaluations = (best ? best->evaluations : 0) + r.evaluations;
        if (!best || MatchesBetter(r.agreement, best->agreement)) best = std::move(r);
        best->evaluations = evaluations;
    };
    if (stored) {
        try {
            consider(flatland::EvaluateFamily(family, table, stored->parameters));
        } catch (const DomainError& e) {
            throw InputError(storedPath.string() + ": the committed fit of '" + family.name +
                             "' builds a scene lexel refuses: " + e.what());
        }
        consider(flatland::RefineFamily(family, table, stored->parameters, fit));
    }
    if (options.samples > 0 && options.starts > 0)
        if (std::optional<FitResult> r = flatland::FitFamily(family, table, fit))
            consider(std::move(*r));
    if (!best)
        throw InputError("fit of '" + family.name + "': none of the " +
                         std::to_string(options.samples) +
                         " random scenes is accepted and there is no committed fit");
    return *best;
}

}  // namespace

std::vector<CaseFit> FitThesisCases(const std::vector<ThesisTable>& tables,
                                    const fs::path& casesDir, const FitThesisOptions& options,
                                    const std::function<void(const CaseFit&)>& onFitted) {
    const fs::path storedPath = casesDir / "fitted" / "parameters.json";
    const std::vector<StoredFit> stored = LoadStoredFits(storedPath);
    const bool randomStarts = options.samples > 0 && options.starts > 0;
    for (const ThesisTable& thesis : tables)
        if (!randomStarts && !FindStored(stored, FamilyOf(thesis).name))
            throw InputError("fit of '" + FamilyOf(thesis).name + "': no committed fit in " +
                             storedPath.string() + " and no random starts: nothing to start from");
    std::vector<CaseFit> fits;
    for (const ThesisTable& thesis : tables) {
        CaseFit fit;
        fit.thesis = thesis;
        fit.family = &FamilyOf(thesis);
        fit.table = ToPublishedTable(thesis);
        fit.reconstruction = MeasureThesisScene(casesDir / thesis.file, false, fit.table).agreement;
        const Stopwatch timer;
        fit.best = FitOneCase(*fit.family, fit.table, options, FindStored(stored, fit.family->name),
                              storedPath);
        fit.seconds = 1e-3 * timer.Ms();
        if (options.explain && !fit.best.agreement.accepted) {
            flatland::FitOptions refit;
            refit.minimaxRounds = options.minimaxRounds;
            refit.patternEvaluations = options.patternEvaluations;
            fit.dropped =
                flatland::DropOneAnalysis(*fit.family, fit.table, fit.best.parameters, refit);
        }
        if (onFitted) onFitted(fit);
        fits.push_back(std::move(fit));
    }
    return fits;
}

std::vector<StoredFit> MergeStoredFits(const fs::path& existingPath,
                                       const std::vector<CaseFit>& fits,
                                       const std::vector<ThesisTable>& tables) {
    std::vector<StoredFit> merged;
    for (const CaseFit& fit : fits)
        merged.push_back({fit.family->name, fit.best.parameters, fit.best.agreement.worstAngleDeg,
                          fit.best.agreement.worstFootprint});
    for (const StoredFit& s : LoadStoredFits(existingPath)) {
        if (FindStored(merged, s.caseName)) continue;
        const auto thesis = std::find_if(tables.begin(), tables.end(), [&](const ThesisTable& t) {
            return StemOf(t.file) == s.caseName;
        });
        if (thesis == tables.end()) continue;
        try {
            const FitResult now = flatland::EvaluateFamily(FamilyOf(*thesis),
                                                           ToPublishedTable(*thesis), s.parameters);
            merged.push_back({s.caseName, s.parameters, now.agreement.worstAngleDeg,
                              now.agreement.worstFootprint});
        } catch (const DomainError& e) {
            throw InputError(existingPath.string() + ": the fit of '" + s.caseName +
                             "' builds a scene lexel refuses: " + e.what());
        }
    }
    std::sort(merged.begin(), merged.end(),
              [](const StoredFit& a, const StoredFit& b) { return a.caseName < b.caseName; });
    return merged;
}

}  // namespace lexel::cases
