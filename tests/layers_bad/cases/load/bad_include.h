// A case loader that includes a runner: layers_test.cmake must refuse it.
#pragma once

#include "lexel/cases/run/sweep.h"
