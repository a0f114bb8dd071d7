// A core file that includes the test bench: layer_tests_catch_a_violation expects the layer
// check to fail on it.
#include "lexel/spatial/harness/scene.h"
