// Which scene stands for a thesis case (Chong 2003, ch. 4.1.3): the hand reconstruction
// <dir>/<file>, or the scene `lexel fit-thesis` recovered from the published numbers,
// <dir>/fitted/<file>, whichever matches the published table better (flatland/studies/scene_fit.h).
#pragma once

#include <filesystem>
#include <optional>
#include <vector>

#include "lexel/cases/load/published.h"
#include "lexel/flatland/studies/scene_fit.h"

namespace lexel::cases {

// The table as the fit reads it: one PublishedRow per (row, method), in the file's order (the
// thesis's "Our Method (both)" becomes two rows); the two-frusta mean is measured by split-dp,
// as in `lexel tables`.
flatland::PublishedTable ToPublishedTable(const ThesisTable& thesis);

// The order candidates are ranked by: the acceptance criterion first (the worst number relative
// to its tolerance), then the RMS least-squares residual. True when `a` matches better.
bool MatchesBetter(const flatland::TableAgreement& a, const flatland::TableAgreement& b);

struct ThesisSceneChoice {
    std::filesystem::path path;  // the case file chosen
    bool fitted = false;         // true when it is <dir>/fitted/<file>
    flatland::FlatScene scene;
    std::vector<flatland::ComparedNumber> numbers;  // published beside ours on `scene`
    flatland::TableAgreement agreement;             // at the default tolerances (2°, 10%)
    // The candidate not chosen; set only when a fitted file exists.
    std::filesystem::path otherPath;
    std::optional<flatland::TableAgreement> otherAgreement;
};

// Measures <dir>/<file> and, when it exists, <dir>/fitted/<file> against the table and keeps the
// one that MatchesBetter (the reconstruction on a tie). Throws InputError naming the case file
// when one cannot be read or run.
ThesisSceneChoice ChooseThesisScene(const ThesisTable& thesis, const std::filesystem::path& dir);

// One case file measured against the table (the `fitted` flag as given). Throws like
// ChooseThesisScene.
ThesisSceneChoice MeasureThesisScene(const std::filesystem::path& path, bool fitted,
                                     const flatland::PublishedTable& table);

}  // namespace lexel::cases
