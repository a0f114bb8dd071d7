// lexel's flatland (Chong 2003) in one include, installed as <lexel/flatland.h>: the 2D world of
// the thesis — scene and sampling pass, the lexel remapping, the exact L1/L2/L∞ optimal lexel
// plane, frustum splitting with Lagrange lexel allocation, and the baselines. (The scene families
// of the thesis's four cases and their fit to its published tables are a study, flatland/studies,
// lexel::flatland_studies: built for lexel's own commands and tests, not installed.)
#pragma once

#include "lexel/flatland/angle_solvers.h"
#include "lexel/flatland/baselines.h"
#include "lexel/flatland/frustum_split.h"
#include "lexel/flatland/lexel_remap.h"
#include "lexel/flatland/memory.h"
#include "lexel/flatland/methods.h"
#include "lexel/flatland/sampling.h"
#include "lexel/flatland/scene.h"
