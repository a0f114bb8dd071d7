// The plotting module including the case loader: layers_test.cmake must refuse it.
#pragma once

#include "lexel/cases/load/spatial_case.h"
