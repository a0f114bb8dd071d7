// A teaching program that includes a report: layers_test.cmake must refuse it.
#include "lexel/cases/report/columns.h"
