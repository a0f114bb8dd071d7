// `lexel fit-thesis` output: the fitted case files and their parameters file (schemas in
// cases/README.md), and the terminal report of a fit (parameters, every published number beside
// the fitted scene's, the agreement, and the left-out analysis of --explain).
#pragma once

#include <string>
#include <vector>

#include "lexel/cases/load/stored_fits.h"
#include "lexel/cases/studies/thesis/fit_thesis.h"

namespace lexel::cases {

// The fitted scene as a flatland case file, its description naming the family, the parameters
// and the agreement. Numbers are written so that they read back to the same doubles.
std::string FittedCaseJson(const CaseFit& fit);
// The parameters file (read back by LoadStoredFits).
std::string StoredFitsJson(const std::vector<StoredFit>& fits);
// The terminal report of one case's fit.
std::string FitText(const CaseFit& fit);

}  // namespace lexel::cases
