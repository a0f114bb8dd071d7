// The registry of 3D methods: the built-in families (spatial/methods/*_methods.cpp) and the
// methods a user adds with RegisterMethod (CONTRIBUTING.md, "Add a method in one file") take the
// same path, and every list of methods is a query of it (method_info.h).
#pragma once

#include <string_view>

#include "lexel/spatial/methods/method.h"

namespace lexel::spatial {

// Adds a method after every earlier one (its family is set to kRegistered); the built-in methods
// and their order are unchanged. Thread-safe; a method cannot be removed. Returns true (for
// `static const bool r = RegisterMethod(...)` at namespace scope). Throws std::invalid_argument
// for an invalid or taken name, an empty description or no compute function.
bool RegisterMethod(MethodDescriptor method);

// The method's map(s) for one light: a given matrix of context.given by that name first, then
// the registry's. std::invalid_argument for an unknown name, for what the method's compute
// refuses (an optimizer or partitioned method without samples, a vsm* method without the
// readback), for the bound (the Evaluator scores it against the truth), or for a given matrix
// that does not project from the light (LightMatrixFromClip, clip_matrix.h).
MethodMatrix ComputeLightMatrix(std::string_view name, const MethodContext& context);

}  // namespace lexel::spatial
