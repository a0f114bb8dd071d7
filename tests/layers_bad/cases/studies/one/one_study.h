// A study that includes another study: layers_test.cmake must refuse it.
#pragma once

#include "lexel/cases/studies/other/other_study.h"
