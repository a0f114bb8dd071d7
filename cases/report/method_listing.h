// `lexel methods`: every method lexel knows, read from the registries (spatial/methods/
// method_info.h for 3D, flatland/methods.h for flatland), as an aligned text table or as JSON
// for scripts (cases/scripts/ read the families and traits from it instead of listing names).
#pragma once

#include <string>

namespace lexel::cases {

// One left-aligned row per 3D method (name, family, default or opt-in, storage model,
// description), then one per flatland method (name, description).
std::string MethodListingText();

// {"spatial": [{"name", "description", "citation", "family", "default", "storage_model",
// "traits": {"fair_table", "report_table", "frustum_fitted", "optimizer", "partitioned",
// "virtual_map", "warped", "gpu_map"}}, ...], "flatland": [{"name", "description"}, ...]},
// in registry order (the order of every report), indented, newline-terminated.
std::string MethodListingJson();

}  // namespace lexel::cases
