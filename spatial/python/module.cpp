// lexel._lexel: the Python module of lexel's 3D core (spatial/python/README.md). The package
// lexel/ re-exports it; this file makes the exceptions and calls each part's bindings.
#include <pybind11/pybind11.h>

#include <exception>
#include <string>

#include "bindings.h"
#include "lexel/solvers/errors.h"

namespace lexel::python {

namespace {

const char* SubjectName(Subject subject) {
    switch (subject) {
        case Subject::kCamera:
            return "camera";
        case Subject::kLight:
            return "light";
        case Subject::kGeometry:
            return "geometry";
        case Subject::kSegment:
            return "segment";
        case Subject::kLexels:
            return "lexels";
    }
    return "unknown";
}

// The C++ enumerators a message may name, as Python spells them.
std::string PythonNames(std::string message) {
    static const std::pair<const char*, const char*> kNames[] = {
        {"DepthDirection::kReversed", "DepthDirection.REVERSED"},
        {"DepthDirection::kStandard", "DepthDirection.STANDARD"},
        {"use kStandard", "use DepthDirection.STANDARD"},
        {"use kReversed", "use DepthDirection.REVERSED"},
    };
    for (const auto& [cpp, python] : kNames)
        for (std::size_t at; (at = message.find(cpp)) != std::string::npos;)
            message.replace(at, std::string(cpp).size(), python);
    return message;
}

PyObject* NewException(py::module_& m, const char* name, const char* doc) {
    PyObject* type = PyErr_NewExceptionWithDoc((std::string("lexel.") + name).c_str(), doc,
                                               PyExc_ValueError, nullptr);
    if (!type) throw py::error_already_set();
    m.add_object(name, py::handle(type));  // the module keeps it for the interpreter's life
    return type;
}

}  // namespace

}  // namespace lexel::python

PYBIND11_MODULE(_lexel, m) {
    namespace py = pybind11;
    using namespace lexel::python;
    m.doc() =
        "lexel's 3D core: the scene-optimized light matrix of Chong & Gortler for a renderer's "
        "own buffers, with numpy arrays in and out. See help(lexel).";
    m.attr("__version__") = LEXEL_VERSION;
    // Classes and functions defined while the module calls itself "lexel" are named lexel.X (in
    // help(), signatures and tracebacks), where the package lexel/ re-exports them.
    m.attr("__name__") = "lexel";

    static PyObject* domainError = NewException(
        m, "DomainError",
        "Input the algorithm cannot serve (a light inside the geometry, visible points that "
        "surround the light, a camera that sees nothing). str(error) is lexel's one-line "
        "reason; .subject names the input ('camera', 'light', 'geometry') and .index the "
        "element ((-1, -1): the whole). A ValueError.");
    static PyObject* inputError = NewException(
        m, "InputError",
        "Bad input in the user's terms (lexel's case layer). str(error) is lexel's one-line "
        "message. A ValueError.");
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const lexel::DomainError& e) {
            const py::object error =
                py::reinterpret_borrow<py::object>(domainError)(PythonNames(e.what()));
            error.attr("subject") = SubjectName(e.subject());
            error.attr("index") = py::make_tuple(e.index()[0], e.index()[1]);
            PyErr_SetObject(domainError, error.ptr());
        } catch (const lexel::InputError& e) {
            PyErr_SetString(inputError, PythonNames(e.what()).c_str());
        } catch (const std::invalid_argument& e) {
            // lexel's precondition failures (wrong sizes, singular matrices): ValueError.
            PyErr_SetString(PyExc_ValueError, PythonNames(e.what()).c_str());
        }
    });

    BindGeometry(m);
    BindReadback(m);
    BindEnergy(m);
    BindMethods(m);
    BindStatistics(m);
    m.attr("__name__") = "lexel._lexel";
}
