#include "numpy_convert.h"

#include <cmath>
#include <sstream>

namespace lexel::python {

namespace {

// Texel and pixel coordinates stay exact integers in double far beyond this; larger sizes are
// typing errors.
constexpr py::ssize_t kMaxSide = py::ssize_t{1} << 24;

std::string Reason(const std::string& name, const std::string& reason) {
    return name + ": " + reason;
}

void CheckShape(const py::array& a, std::initializer_list<py::ssize_t> shape,
                const std::string& name, const std::string& expected) {
    bool ok = a.ndim() == static_cast<py::ssize_t>(shape.size());
    py::ssize_t k = 0;
    for (py::ssize_t extent : shape) {
        if (!ok) break;
        ok = extent < 0 || a.shape(k) == extent;  // -1: any extent
        ++k;
    }
    if (!ok)
        throw py::value_error(Reason(name, "expected " + expected + ", got shape " + ShapeText(a)));
}

void CheckFinite(const DoubleArray& a, const std::string& name, py::ssize_t perRow) {
    const double* data = a.data();
    for (py::ssize_t i = 0; i < a.size(); ++i)
        if (!std::isfinite(data[i])) {
            std::ostringstream what;
            if (a.ndim() == 2 && perRow > 0)
                what << "entry [" << i / perRow << ", " << i % perRow << "] is " << data[i]
                     << " (must be finite)";
            else
                what << "entry " << i << " is " << data[i] << " (must be finite)";
            throw py::value_error(Reason(name, what.str()));
        }
}

DoubleArray Checked(const py::handle& obj, const std::string& name,
                    std::initializer_list<py::ssize_t> shape, const std::string& expected) {
    DoubleArray a = AsDoubles(obj, name);
    CheckShape(a, shape, name, expected);
    CheckFinite(a, name, a.ndim() == 2 ? a.shape(1) : 0);
    return a;
}

}  // namespace

std::string ShapeText(const py::array& a) {
    std::string text = "(";
    for (py::ssize_t k = 0; k < a.ndim(); ++k) {
        if (k > 0) text += ", ";
        text += std::to_string(a.shape(k));
    }
    return text + (a.ndim() == 1 ? ",)" : ")");
}

DoubleArray AsDoubles(const py::handle& obj, const std::string& name) {
    if (obj.is_none()) throw py::type_error(Reason(name, "expected an array of numbers, got None"));
    DoubleArray a = DoubleArray::ensure(obj);
    if (!a) {
        PyErr_Clear();
        throw py::type_error(Reason(
            name, "expected an array of numbers, got " + std::string(py::str(py::type::of(obj)))));
    }
    return a;
}

glm::dmat4 ToMatrix4(const py::handle& obj, const std::string& name) {
    const DoubleArray a = Checked(obj, name, {4, 4}, "a (4, 4) matrix");
    glm::dmat4 m;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) m[c][r] = a.at(r, c);
    return m;
}

glm::dmat3 ToMatrix3(const py::handle& obj, const std::string& name) {
    const DoubleArray a = Checked(obj, name, {3, 3}, "a (3, 3) matrix");
    glm::dmat3 m;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) m[c][r] = a.at(r, c);
    return m;
}

glm::dvec3 ToVec3(const py::handle& obj, const std::string& name) {
    const DoubleArray a = Checked(obj, name, {3}, "a vector of 3 numbers");
    return {a.at(0), a.at(1), a.at(2)};
}

glm::dvec4 ToVec4(const py::handle& obj, const std::string& name) {
    const DoubleArray a = Checked(obj, name, {4}, "a vector of 4 numbers");
    return {a.at(0), a.at(1), a.at(2), a.at(3)};
}

std::vector<glm::dvec3> ToPoints(const py::handle& obj, const std::string& name) {
    const DoubleArray a = Checked(obj, name, {-1, 3}, "(N, 3) points");
    std::vector<glm::dvec3> points(static_cast<std::size_t>(a.shape(0)));
    const double* data = a.data();
    for (std::size_t i = 0; i < points.size(); ++i)
        points[i] = {data[3 * i], data[3 * i + 1], data[3 * i + 2]};
    return points;
}

spatial::Resolution ToResolution(const py::handle& obj, const std::string& name) {
    py::ssize_t side[2] = {0, 0};
    bool ok =
        py::isinstance<py::sequence>(obj) && !py::isinstance<py::str>(obj) && py::len(obj) == 2;
    for (int k = 0; ok && k < 2; ++k) {
        const py::object v = py::reinterpret_borrow<py::sequence>(obj)[k];
        // Integers only (Python int or a numpy integer); a float size is a mistake.
        ok = py::isinstance<py::int_>(v) ||
             py::isinstance(v, py::module_::import("numpy").attr("integer"));
        if (ok) side[k] = v.cast<py::ssize_t>();
    }
    if (!ok)
        throw py::type_error(Reason(
            name, "expected (width, height) as two integers, got " + std::string(py::repr(obj))));
    for (py::ssize_t s : side)
        if (s < 1 || s > kMaxSide)
            throw py::value_error(Reason(name, "width and height must be in [1, 2^24], got (" +
                                                   std::to_string(side[0]) + ", " +
                                                   std::to_string(side[1]) + ")"));
    return {static_cast<int>(side[0]), static_cast<int>(side[1])};
}

double ToFinite(const py::handle& obj, const std::string& name) {
    if (!py::isinstance<py::float_>(obj) && !py::isinstance<py::int_>(obj) &&
        !py::isinstance(obj, py::module_::import("numpy").attr("number")))
        throw py::type_error(Reason(name, "expected a number, got " + std::string(py::repr(obj))));
    const double v = obj.cast<double>();
    if (!std::isfinite(v))
        throw py::value_error(Reason(name, "must be finite, got " + std::string(py::repr(obj))));
    return v;
}

FloatArray ToDepthImage(const py::handle& obj, const std::string& name,
                        spatial::Resolution* resolution) {
    if (obj.is_none()) throw py::type_error(Reason(name, "expected a (H, W) array, got None"));
    FloatArray a = FloatArray::ensure(obj);
    if (!a) {
        PyErr_Clear();
        throw py::type_error(Reason(name, "expected a (H, W) array of numbers, got " +
                                              std::string(py::str(py::type::of(obj)))));
    }
    CheckShape(a, {-1, -1}, name, "a (H, W) image");
    if (a.shape(0) < 1 || a.shape(1) < 1 || a.shape(0) > kMaxSide || a.shape(1) > kMaxSide)
        throw py::value_error(
            Reason(name, "height and width must be in [1, 2^24], got shape " + ShapeText(a)));
    *resolution = {static_cast<int>(a.shape(1)), static_cast<int>(a.shape(0))};
    return a;
}

py::array_t<double> FromMatrix4(const glm::dmat4& m) {
    py::array_t<double> a({4, 4});
    auto out = a.mutable_unchecked<2>();
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) out(r, c) = m[c][r];
    return a;
}

py::array_t<double> FromMatrix3(const glm::dmat3& m) {
    py::array_t<double> a({3, 3});
    auto out = a.mutable_unchecked<2>();
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) out(r, c) = m[c][r];
    return a;
}

py::array_t<double> FromVec3(const glm::dvec3& v) {
    py::array_t<double> a(3);
    double* out = a.mutable_data();
    for (int k = 0; k < 3; ++k) out[k] = v[k];
    return a;
}

py::array_t<double> FromVec4(const glm::dvec4& v) {
    py::array_t<double> a(4);
    double* out = a.mutable_data();
    for (int k = 0; k < 4; ++k) out[k] = v[k];
    return a;
}

py::array_t<double> FromPoints(std::span<const glm::dvec3> points) {
    py::array_t<double> a({static_cast<py::ssize_t>(points.size()), py::ssize_t{3}});
    double* out = a.mutable_data();
    for (std::size_t i = 0; i < points.size(); ++i)
        for (int k = 0; k < 3; ++k) out[3 * i + k] = points[i][k];
    return a;
}

py::array_t<double> FromMapPoints(std::span<const glm::dvec2> points) {
    py::array_t<double> a({static_cast<py::ssize_t>(points.size()), py::ssize_t{2}});
    double* out = a.mutable_data();
    for (std::size_t i = 0; i < points.size(); ++i)
        for (int k = 0; k < 2; ++k) out[2 * i + k] = points[i][k];
    return a;
}

py::array_t<double> FromVec4s(std::span<const glm::dvec4> rows) {
    py::array_t<double> a({static_cast<py::ssize_t>(rows.size()), py::ssize_t{4}});
    double* out = a.mutable_data();
    for (std::size_t i = 0; i < rows.size(); ++i)
        for (int k = 0; k < 4; ++k) out[4 * i + k] = rows[i][k];
    return a;
}

py::tuple FromResolution(spatial::Resolution r) { return py::make_tuple(r.width, r.height); }

py::array_t<double> FromImage(spatial::Resolution r, std::span<const double> values) {
    py::array_t<double> a({py::ssize_t{r.height}, py::ssize_t{r.width}});
    std::copy(values.begin(), values.end(), a.mutable_data());
    return a;
}

py::array_t<double> FromImage3(spatial::Resolution r, std::span<const glm::dvec3> values) {
    py::array_t<double> a({py::ssize_t{r.height}, py::ssize_t{r.width}, py::ssize_t{3}});
    double* out = a.mutable_data();
    for (std::size_t i = 0; i < values.size(); ++i)
        for (int k = 0; k < 3; ++k) out[3 * i + k] = values[i][k];
    return a;
}

py::array_t<float> FromFloatImage(spatial::Resolution r, std::span<const float> values) {
    py::array_t<float> a({py::ssize_t{r.height}, py::ssize_t{r.width}});
    std::copy(values.begin(), values.end(), a.mutable_data());
    return a;
}

py::array_t<bool> FromMask(spatial::Resolution r, const std::vector<bool>& flags) {
    py::array_t<bool> a({py::ssize_t{r.height}, py::ssize_t{r.width}});
    bool* out = a.mutable_data();
    for (std::size_t i = 0; i < flags.size(); ++i) out[i] = flags[i];
    return a;
}

}  // namespace lexel::python
