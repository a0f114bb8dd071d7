// `lexel fit-thesis`: recovers the thesis's four flatland scenes from its published tables
// (Chong 2003, ch. 4.1.3) by fitting each case's scene family (flatland/studies/scene_family.h)
// with flatland/studies/scene_fit.h, starting from the committed fits (cases/flatland/fitted/).
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <vector>

#include "lexel/cases/load/published.h"
#include "lexel/cases/load/stored_fits.h"
#include "lexel/flatland/studies/scene_fit.h"

namespace lexel::cases {

struct FitThesisOptions {
    std::uint64_t seed = 1;  // of the random starts
    int samples = 300;       // random starts screened per case (beyond the committed fit)
    int starts = 2;          // Levenberg–Marquardt runs from the best of them
    int minimaxRounds = 3;
    int patternEvaluations = 2000;  // compass search on the worst error (scene_fit.h)
    bool explain = false;           // for a table not met: refit with each number left out in turn
};

struct CaseFit {
    ThesisTable thesis;
    const flatland::SceneFamily* family = nullptr;
    flatland::PublishedTable table;  // ToPublishedTable(thesis)
    flatland::FitResult best;        // the best of the committed fit, its refinement, the starts
    double seconds = 0.0;            // wall time of the fit
    flatland::TableAgreement reconstruction;       // the hand reconstruction <dir>/<file>
    std::vector<flatland::DroppedNumber> dropped;  // options.explain and the table not met
};

// Fits each table's family (the one named by the case file's stem). For each case: the committed
// fit in <casesDir>/fitted/parameters.json as it stands and refined from there, then
// options.samples random starts of which the best options.starts are refined; the best by
// MatchesBetter (thesis_scene.h) is kept. `onFitted` is called after each case. Every case is
// checked before any is fitted: throws InputError when a table has no family or nothing to start
// from (no committed fit, and no random starts), and naming the parameters file when a committed
// fit's scene is refused.
std::vector<CaseFit> FitThesisCases(const std::vector<ThesisTable>& tables,
                                    const std::filesystem::path& casesDir,
                                    const FitThesisOptions& options,
                                    const std::function<void(const CaseFit&)>& onFitted = {});

// The parameters file to write beside the fitted case files: the entries of `existingPath` (a
// parameters file; none when it does not exist) for cases not in `fits` and with a table in
// `tables`, re-measured, and the new fits; sorted by case name. Throws InputError naming
// `existingPath` when it is malformed or an entry's scene is refused.
std::vector<StoredFit> MergeStoredFits(const std::filesystem::path& existingPath,
                                       const std::vector<CaseFit>& fits,
                                       const std::vector<ThesisTable>& tables);

}  // namespace lexel::cases
