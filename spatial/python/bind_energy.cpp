// lexel.energy, energy_gradient, sample_badness, ENERGIES (samples.h, energy_gradient.h): the
// energies a light matrix is optimized for, one row of kEnergies each.
#include <pybind11/stl.h>

#include "bindings.h"
#include "lexel/solvers/footprint_metrics.h"
#include "lexel/spatial/energy.h"
#include "lexel/spatial/energy_gradient.h"
#include "lexel/spatial/samples.h"
#include "numpy_convert.h"

namespace lexel::python {

using namespace spatial;

namespace {

// An energy of the core: its value over the samples, ∂/∂p4 with the affine rows fixed in closed
// form and by automatic differentiation, and how Algorithm 1 is told to minimize it (nullptr:
// the optimizer's own energy, nothing to set). A new energy of the core is one row here.
struct NamedEnergy {
    const char* name;
    const char* description;
    double (*energy)(const LightMatrix&, const LightSamples&);
    glm::dvec3 (*gradient)(const LightMatrix&, const LightSamples&);
    glm::dvec3 (*gradientJets)(const LightMatrix&, const LightSamples&);
    void (*select)(OptimizerOptions*);
};

const NamedEnergy kEnergies[] = {
    {"h",
     "Chong & Gortler eq. (6): the sum over the boundary samples of ||J^-1||_F^2, J = du/dx "
     "in texels per readback pixel (dimensionless; +inf when a sample is behind the map's "
     "plane). What Algorithm 1 minimizes.",
     [](const LightMatrix& m, const LightSamples& s) { return Energy(m, s); },
     &EnergyGradientAnalytic, &EnergyGradientJets, nullptr},
    {"e",
     "The edge energy (energy.h), what optimal minimizes: the sum over the boundary samples of "
     "||n^T J^-1||_2^p, n the shadow edge's unit normal in readback pixels (||J^-1||_F/sqrt(2) "
     "where it has none) and p = 5/8, plus the footprint prior at weight 1 (one boundary "
     "sample's worth of the view's mean footprint). ||n^T J^-1||/4 is the misclassified band "
     "in pixels per pixel of edge; p < 1 credits the widest bands less, as measured.",
     [](const LightMatrix& m, const LightSamples& s) { return Energy(m, s, kEdgeEnergy); },
     [](const LightMatrix& m, const LightSamples& s) { return EnergyGradient(m, s, kEdgeEnergy); },
     [](const LightMatrix& m, const LightSamples& s) {
         return EnergyGradientJets(m, s, kEdgeEnergy);
     },
     [](OptimizerOptions* o) {  // `optimal`'s: its energy and its two guards
         const OptimizerOptions edge = EdgeOptimizerOptions();
         o->energy = edge.energy;
         o->collapseFactor = edge.collapseFactor;
         o->starveFactor = edge.starveFactor;
     }},
};

const NamedEnergy& FindEnergy(const std::string& name) {
    for (const NamedEnergy& e : kEnergies)
        if (name == e.name) return e;
    throw py::value_error("energy: unknown energy '" + name + "' (lexel has " +
                          NameList(kEnergies) + ")");
}

struct NamedBadness {
    const char* name;
    Badness badness;
};
const NamedBadness kBadnesses[] = {
    {"frobenius_inverse_squared", Badness::kFrobeniusInverseSquared},
    {"geometric_stretch", Badness::kGeometricStretch},
    {"largest_singular_value", Badness::kLargestSingularValue},
};

}  // namespace

void SelectOptimizerEnergy(const py::object& name, OptimizerOptions* options) {
    if (name.is_none()) return;
    if (!py::isinstance<py::str>(name)) throw py::type_error("energy: expected a name or None");
    const NamedEnergy& e = FindEnergy(name.cast<std::string>());
    if (e.select) e.select(options);
}

void BindEnergy(py::module_& m) {
    py::dict energies;
    for (const NamedEnergy& e : kEnergies) energies[e.name] = e.description;
    m.attr("ENERGIES") = energies;

    m.def(
        "energy",
        [](const LightMatrix& matrix, const LightSamples& samples, const std::string& kind) {
            return FindEnergy(kind).energy(matrix, samples);
        },
        py::arg("matrix"), py::arg("samples"), py::arg("energy") = "h",
        "The energy of a light matrix over a light's samples (lexel.ENERGIES names them and "
        "says what each is; 'h' is eq. 6).");
    m.def(
        "energy_gradient",
        [](const LightMatrix& matrix, const LightSamples& samples, const std::string& kind,
           const std::string& method) {
            const NamedEnergy& e = FindEnergy(kind);
            if (method == "closed_form") return FromVec3(e.gradient(matrix, samples));
            if (method == "jets") return FromVec3(e.gradientJets(matrix, samples));
            throw py::value_error("method: expected 'closed_form' or 'jets', got '" + method + "'");
        },
        py::arg("matrix"), py::arg("samples"), py::arg("energy") = "h",
        py::arg("method") = "closed_form",
        "d(energy)/d(p4) with p1, p2 fixed, (3,): in closed form (report Appendix A, eqs. 10-11) "
        "or by Ceres automatic differentiation (method='jets'). Samples behind the plane or with "
        "a singular J add nothing.");
    m.def(
        "sample_badness",
        [](const LightMatrix& matrix, const LightSamples& samples, const std::string& name) {
            for (const NamedBadness& b : kBadnesses)
                if (name == b.name) {
                    std::vector<double> values(samples.lsX.size());
                    for (std::size_t i = 0; i < values.size(); ++i)
                        values[i] = SampleBadness(matrix, samples.lsX[i], samples.dXdx1[i],
                                                  samples.dXdx2[i], b.badness);
                    return FromVector<double>(values);
                }
            throw py::value_error("badness: expected " + NameList(kBadnesses) + ", got '" + name +
                                  "'");
        },
        py::arg("matrix"), py::arg("samples"), py::arg("badness") = "frobenius_inverse_squared",
        "Per boundary sample, (N,): ||J^-1||_F^2 (eq. 6's summand, the default), "
        "'geometric_stretch' (Sander et al.'s L2 stretch of J^-1) or 'largest_singular_value' "
        "(the most pixels one texel spans); +inf where J is singular or the sample is behind "
        "the map's plane.");
}

}  // namespace lexel::python
