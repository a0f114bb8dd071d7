// lexel.student_t95, mean_interval95, paired_difference95, differ_beyond_noise, NORMAL95
// (solvers/statistics.h): the intervals and the noise rule of lexel's reports, for the scripts
// (cases/scripts/) to use the same ones.
#include <pybind11/stl.h>

#include <string>
#include <vector>

#include "bindings.h"
#include "lexel/solvers/statistics.h"

namespace lexel::python {

namespace {

std::vector<double> Values(const py::object& obj, const char* name) {
    std::vector<double> values;
    for (const py::handle item : py::iter(obj)) {
        if (!py::isinstance<py::float_>(item) && !py::isinstance<py::int_>(item))
            throw py::type_error(std::string(name) + ": expected numbers");
        values.push_back(item.cast<double>());
    }
    return values;
}

}  // namespace

void BindStatistics(py::module_& m) {
    m.attr("NORMAL95") = kNormal95;
    m.def(
        "student_t95",
        [](long long dof) {
            if (dof < 1) throw py::value_error("dof: must be at least 1");
            return StudentT95(static_cast<std::size_t>(dof));
        },
        py::arg("dof"),
        "The two-sided 95% quantile of Student's t with dof degrees of freedom (12.706 for 1, "
        "1.984 for 99, to 1e-10).");
    m.def(
        "mean_interval95",
        [](const py::object& values) {
            const MeanInterval r = MeanInterval95(Values(values, "values"));
            return py::make_tuple(r.mean, r.halfWidth);
        },
        py::arg("values"),
        "(mean, 95% half-width t(n-1) s / sqrt(n)) of the values; the half-width is nan for fewer "
        "than two, the mean nan for none.");
    m.def(
        "paired_difference95",
        [](const py::object& ours, const py::object& theirs) {
            const std::vector<double> a = Values(ours, "ours"), b = Values(theirs, "theirs");
            if (a.size() != b.size())
                throw py::value_error("theirs: has " + std::to_string(b.size()) +
                                      " values, ours has " + std::to_string(a.size()));
            const MeanInterval r = PairedDifference95(a, b);
            return py::make_tuple(r.mean, r.halfWidth);
        },
        py::arg("ours"), py::arg("theirs"),
        "(mean, 95% half-width) of ours[i] - theirs[i]: a paired comparison over lights.");
    m.def("differ_beyond_noise", &DifferBeyondNoise, py::arg("mean_a"), py::arg("se_a"),
          py::arg("mean_b"), py::arg("se_b"),
          "Whether two independent means differ beyond their noise: |a - b| > NORMAL95 * "
          "sqrt(se_a^2 + se_b^2), as lexel sweep counts wins.");
}

}  // namespace lexel::python
