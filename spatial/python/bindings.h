// The parts of the Python module lexel._lexel (module.cpp), one per area of the 3D core:
//   BindGeometry  lights, bounds, cameras, light spaces, light matrices, clip matrices;
//   BindReadback  depth conventions, DownsampleDepth, the readback, shades and light samples;
//   BindEnergy    the energies (h of eq. 6 today; one table entry each, bind_energy.cpp);
//   BindMethods   the standard map, the baselines, Algorithm 1, `optimal`, the partitions.
// Docstrings are the user's reference (help(lexel.X)); spatial/python/README.md is the overview.
#pragma once

#include <pybind11/pybind11.h>

#include <string>
#include <string_view>
#include <vector>

#include "lexel/spatial/optimizer.h"

namespace lexel::python {

namespace py = pybind11;

void BindGeometry(py::module_& m);
void BindReadback(py::module_& m);
void BindEnergy(py::module_& m);
void BindMethods(py::module_& m);
void BindStatistics(py::module_& m);

// The energy `name` selects for Algorithm 1 (bind_energy.cpp's table): sets the optimizer's
// energy; ValueError listing the names for an unknown one. None keeps the optimizer's default.
void SelectOptimizerEnergy(const py::object& name, spatial::OptimizerOptions* options);
// "'a', 'b' or 'c'" for error messages.
template <typename Table>
std::string NameList(const Table& table) {
    std::string text;
    const std::size_t n = std::size(table);
    for (std::size_t i = 0; i < n; ++i) {
        if (i > 0) text += i + 1 == n ? " or " : ", ";
        // Appended piece by piece: GCC 12's false -Wrestrict fires on a "'" + name + "'" chain
        // (bug 105329, root CMakeLists.txt).
        text += '\'';
        text += table[i].name;
        text += '\'';
    }
    return text;
}
inline std::string NameList(const std::vector<std::string>& names) {
    struct Named {
        const std::string& name;
    };
    std::vector<Named> table;
    for (const std::string& n : names) table.push_back({n});
    return NameList(table);
}

}  // namespace lexel::python
