// numpy arrays ↔ lexel's glm values for the Python module (spatial/python/README.md).
//
// Conventions: a 4×4 matrix is a (4, 4) float64 array indexed [row, column] as printed (glm stores
// columns: a[r, c] = m[c][r]), so `m @ [x, y, z, 1]` is the C++ `m * glm::dvec4(x, y, z, 1)`; a
// vector is (3,); points are (N, 3); per-pixel images are (H, W) or (H, W, 3), indexed [row,
// column] in the order of the depth array they came from. Inputs are anything numpy converts to
// numbers (lists, tuples, arrays of any real dtype), copied; outputs are new arrays.
//
// Failure: every conversion names the argument: py::value_error (ValueError) "<name>: <reason>"
// for a wrong shape, a value that is not finite (where one must be) or out of range; py::type_error
// (TypeError) for an object that is not numbers at all.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <algorithm>
#include <cstdint>
#include <glm/glm.hpp>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "lexel/spatial/camera.h"

namespace lexel::python {

namespace py = pybind11;

using DoubleArray = py::array_t<double, py::array::c_style | py::array::forcecast>;
using FloatArray = py::array_t<float, py::array::c_style | py::array::forcecast>;

// `obj` as a C-contiguous float64 array; TypeError naming `name` when numpy cannot make one.
DoubleArray AsDoubles(const py::handle& obj, const std::string& name);

// A (4, 4) finite matrix.
glm::dmat4 ToMatrix4(const py::handle& obj, const std::string& name);
// A (3, 3) finite matrix.
glm::dmat3 ToMatrix3(const py::handle& obj, const std::string& name);
// A (3,) finite vector; a (4,) one.
glm::dvec3 ToVec3(const py::handle& obj, const std::string& name);
glm::dvec4 ToVec4(const py::handle& obj, const std::string& name);
// (N, 3) finite points (N may be 0); a single (3,) point is refused: pass it as [[x, y, z]].
std::vector<glm::dvec3> ToPoints(const py::handle& obj, const std::string& name);
// (width, height), both integers in [1, 2^24] (texel coordinates stay exact in double).
spatial::Resolution ToResolution(const py::handle& obj, const std::string& name);
// A finite float, or a finite float ≥ 0.
double ToFinite(const py::handle& obj, const std::string& name);
// A (H, W) image of numbers as float32 (a depth buffer: not-finite values allowed, they mean
// "nothing drawn" where lexel's conventions say so); its resolution is (W, H).
FloatArray ToDepthImage(const py::handle& obj, const std::string& name,
                        spatial::Resolution* resolution);

py::array_t<double> FromMatrix4(const glm::dmat4& m);
py::array_t<double> FromMatrix3(const glm::dmat3& m);
py::array_t<double> FromVec3(const glm::dvec3& v);
py::array_t<double> FromVec4(const glm::dvec4& v);
py::array_t<double> FromPoints(std::span<const glm::dvec3> points);
py::array_t<double> FromMapPoints(std::span<const glm::dvec2> points);  // (N, 2)
py::array_t<double> FromVec4s(std::span<const glm::dvec4> rows);
py::tuple FromResolution(spatial::Resolution r);
// Per-pixel values (row-major, resolution.Count() of them) as (H, W) or (H, W, 3).
py::array_t<double> FromImage(spatial::Resolution r, std::span<const double> values);
py::array_t<double> FromImage3(spatial::Resolution r, std::span<const glm::dvec3> values);
py::array_t<float> FromFloatImage(spatial::Resolution r, std::span<const float> values);
template <typename T>
py::array_t<T> FromVector(std::span<const T> values) {
    py::array_t<T> a(static_cast<py::ssize_t>(values.size()));
    std::copy(values.begin(), values.end(), a.mutable_data());
    return a;
}
// (H, W) bool from per-pixel flags.
py::array_t<bool> FromMask(spatial::Resolution r, const std::vector<bool>& flags);

// "(3, 3)" for error messages.
std::string ShapeText(const py::array& a);

}  // namespace lexel::python
