// lexel.standard_light_matrix, BaselineContext, baseline, optimize_light_matrix, optimal and the
// partitions (standard_map.h, baselines.h, optimizer.h, multi_start.h, partitions.h).
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <list>
#include <optional>
#include <string>
#include <tuple>

#include "bindings.h"
#include "lexel/spatial/baselines.h"
#include "lexel/spatial/methods/registry.h"
#include "lexel/spatial/multi_start.h"
#include "lexel/spatial/optimizer.h"
#include "lexel/spatial/partitions.h"
#include "lexel/spatial/standard_map.h"
#include "numpy_convert.h"

namespace lexel::python {

using namespace spatial;

namespace {

// ---------------------------------------------------------------------------------------------
// The baselines' context, owning what BaselineContext only points to

struct Context {
    LightSpace lightSpace;
    Camera camera;
    Resolution map;
    Bounds bounds;
    std::vector<glm::dvec3> relevant, relevantHull;
    std::optional<glm::dvec4> floorPlane;
    std::optional<LightSamples> samples;
    double margin = 0.02;

    BaselineContext View() const {
        BaselineContext c;
        c.lightSpace = &lightSpace;
        c.camera = camera;
        c.map = map;
        c.wsBounds = bounds;
        c.wsRelevant = relevant;
        c.wsRelevantHull = relevantHull;
        c.floorPlane = floorPlane;
        c.samples = samples ? &*samples : nullptr;
        c.margin = margin;
        return c;
    }
    // The registry's context (ComputeLightMatrix): the baselines' context and the samples, if any.
    MethodContext Method() const {
        MethodContext method;
        method.baseline = View();
        method.samples = samples ? &*samples : nullptr;
        return method;
    }
    const LightSamples& Samples(const char* who) const {
        if (!samples)
            throw py::value_error(std::string("context: ") + who +
                                  " needs the light's samples (BaselineContext(..., samples=))");
        return *samples;
    }
};

Context MakeContext(const LightSpace& lightSpace, const Camera& camera, const py::object& map,
                    const Bounds& bounds, const py::object& relevant,
                    const py::object& relevantHull, const py::object& floorPlane,
                    const std::optional<LightSamples>& samples, const py::object& margin) {
    Context c{lightSpace,
              camera,
              ToResolution(map, "map"),
              bounds,
              ToPoints(relevant, "relevant"),
              {},
              {},
              std::nullopt};
    if (c.relevant.empty()) throw py::value_error("relevant: needs at least one visible point");
    if (!relevantHull.is_none()) c.relevantHull = ToPoints(relevantHull, "relevant_hull");
    if (!floorPlane.is_none()) {
        const glm::dvec4 plane = ToVec4(floorPlane, "floor_plane");
        const double n = glm::length(glm::dvec3(plane));
        if (!(n > 0.0)) throw py::value_error("floor_plane: (a, b, c, d) needs a normal (a, b, c)");
        c.floorPlane = plane / n;
    }
    if (samples && samples->lsRelevant.size() != c.relevant.size())
        throw py::value_error("samples: its ls_relevant has " +
                              std::to_string(samples->lsRelevant.size()) +
                              " points, relevant has " + std::to_string(c.relevant.size()) +
                              " (they must be the same points, in the same order)");
    c.samples = samples;
    c.margin = ToFinite(margin, "margin");
    if (c.margin < 0.0) throw py::value_error("margin: must be >= 0");
    return c;
}

void BindContext(py::module_& m) {
    py::class_<Context>(
        m, "BaselineContext",
        "What every baseline and `optimal` is built from, the information Algorithm 1 gets: "
        "the light space, the camera, the map's (W, H) texels, the scene's bounds, the visible "
        "points (readback.ws_relevant) and their hull (readback.ws_relevant_hull), the floor "
        "plane (plane-optimal) and the light's samples (optimal and the partitions need them; "
        "plane-optimal picks its fallback by them). Holds copies.")
        .def(py::init(&MakeContext), py::arg("light_space"), py::arg("camera"), py::arg("map"),
             py::arg("bounds"), py::arg("relevant"), py::kw_only(),
             py::arg("relevant_hull") = py::none(), py::arg("floor_plane") = py::none(),
             py::arg("samples") = py::none(), py::arg("margin") = 0.02,
             "BaselineContext(light_space, camera, map, bounds, relevant, *, relevant_hull, "
             "floor_plane=(a, b, c, d) with a x + b y + c z + d = 0 (normalized here), samples, "
             "margin=0.02: Algorithm 1's, added to each half extent of the tight fits).")
        .def_property_readonly(
            "light_space", [](const Context& c) { return c.lightSpace; }, "The LightSpace.")
        .def_property_readonly(
            "camera", [](const Context& c) { return c.camera; }, "The Camera.")
        .def_property_readonly(
            "map", [](const Context& c) { return FromResolution(c.map); }, "(W, H) texels.")
        .def_property_readonly(
            "bounds", [](const Context& c) { return c.bounds; }, "The scene's Bounds.")
        .def_property_readonly(
            "relevant", [](const Context& c) { return FromPoints(c.relevant); }, "(N, 3).")
        .def_property_readonly(
            "relevant_hull", [](const Context& c) { return FromPoints(c.relevantHull); }, "(M, 3).")
        .def_property_readonly(
            "floor_plane",
            [](const Context& c) -> py::object {
                if (!c.floorPlane) return py::none();
                return FromVec4(*c.floorPlane);
            },
            "(4,) with a unit normal, or None.")
        .def_property_readonly(
            "samples", [](const Context& c) { return c.samples; }, "The LightSamples, or None.")
        .def_readonly("margin", &Context::margin, "The tight fits' margin.");
}

// ---------------------------------------------------------------------------------------------
// The baselines

// {name: description} of one family's default methods, in registry order.
py::dict FamilyDescriptions(MethodFamily family) {
    py::dict out;
    for (const std::string& name : MethodNamesOf(family))
        out[py::str(name)] = std::string(SpatialMethodDescription(name));
    return out;
}

// The method `name` of `family` (a default one), or ValueError naming the family's methods:
// "ARGUMENT: unknown NOUN 'name' (lexel has ...)".
void CheckFamily(const std::string& name, MethodFamily family, const char* argument,
                 const char* noun) {
    const std::vector<std::string> names = MethodNamesOf(family);
    if (std::find(names.begin(), names.end(), name) == names.end())
        throw py::value_error(std::string(argument) + ": unknown " + noun + " '" + name +
                              "' (lexel has " + NameList(names) + ")");
}

py::dict Diagnostics(const BaselineDiagnostics& d) {
    py::dict out;
    out["fallback"] = d.fallback;
    out["sin_gamma"] = d.sinGamma;
    out["z_near"] = d.zNear;
    out["z_far"] = d.zFar;
    out["n_opt"] = d.nOpt;
    out["warp_depth"] = d.warpDepth;
    out["clip_light"] = FromVec4(d.clipLight);
    out["slide_back"] = d.slideBack;
    out["rotation_fraction"] = d.rotationFraction;
    return out;
}

void BindBaselines(py::module_& m) {
    m.attr("BASELINES") = FamilyDescriptions(MethodFamily::kBaseline);
    m.def(
        "baseline",
        [](const std::string& name, const Context& context, bool diagnostics) -> py::object {
            CheckFamily(name, MethodFamily::kBaseline, "name", "baseline");
            const MethodMatrix result = ComputeLightMatrix(name, context.Method());
            if (!diagnostics) return py::cast(result.matrix);
            return py::make_tuple(result.matrix, Diagnostics(result.diagnostics));
        },
        py::arg("name"), py::arg("context"), py::arg("return_diagnostics") = false,
        "The light matrix of a published baseline (lexel.BASELINES names them; report §3 and "
        "the tight versions that get exactly what Algorithm 1 gets). Every visible point lands "
        "in the map; where a method's construction cannot promise that, it falls back "
        "(diagnostics['fallback'] says why). With return_diagnostics, (matrix, dict). "
        "DomainError when no light matrix sees every visible point.");
    m.def(
        "standard_light_matrix",
        [](const Readback& readback, const LightSpace& lightSpace, const Bounds& bounds,
           const py::object& map) {
            return StandardLightMatrix(readback, lightSpace, bounds, ToResolution(map, "map"));
        },
        py::arg("readback"), py::arg("light_space"), py::arg("scene_bounds"), py::arg("map"),
        "Algorithm 1 step 1's standard map (Brabec et al. 2002: the focused map fitted to the "
        "visible points, grown by 2%), the map to shade the readback with and where Algorithm 1 "
        "starts. DomainError when the readback sees nothing or no axis sees every visible point.");
}

// ---------------------------------------------------------------------------------------------
// Algorithm 1 and `optimal`

OptimizerOptions ToOptions(int iterations, const std::vector<double>& anglesDeg, double margin,
                           bool refine, int refineIterations, bool shear, bool hullOnce,
                           const py::object& energy) {
    OptimizerOptions o;
    if (iterations < 0 || iterations > 1000)
        throw py::value_error("iterations: must be in [0, 1000], got " +
                              std::to_string(iterations));
    if (anglesDeg.empty()) throw py::value_error("angles_deg: needs at least one angle");
    for (double a : anglesDeg)
        if (!std::isfinite(a)) throw py::value_error("angles_deg: every angle must be finite");
    if (!(margin >= 0.0 && std::isfinite(margin)))
        throw py::value_error("margin: must be finite and >= 0");
    if (refineIterations < 1 || refineIterations > 10000)
        throw py::value_error("refine_iterations: must be in [1, 10000]");
    o.iterations = iterations;
    o.anglesDeg = anglesDeg;
    o.margin = margin;
    o.refine = refine;
    o.refineIterations = refineIterations;
    o.shear = shear;
    o.hullOnce = hullOnce;
    SelectOptimizerEnergy(energy, &o);
    return o;
}

// The options every optimizing function takes, keyword-only after its own arguments.
template <typename F, typename... Extra>
void DefOptimizing(py::module_& m, const char* name, F&& f, const std::string& doc,
                   const Extra&... extra) {
    static const OptimizerOptions d;
    static const std::string options =
        "\n\nOptions (keyword-only): iterations=3 (k, report §2.4), angles_deg (the candidate "
        "rotations, report §2.4's), margin=0.02 (added to each half extent of the fitted "
        "rectangle), refine=False (Ceres refinement of p4 on the unit sphere: optimal-refined), "
        "refine_iterations=40, shear=False (the report's Fig. 3 affine shear, optimized "
        "exactly), hull_once=True (fit from the visible points' hull once per light; False: the "
        "reference path over every point), energy=None (the optimizer's own: 'h', eq. 6; 'e': "
        "`optimal`'s edge energy with its collapse and view guards; lexel.ENERGIES).";
    static std::list<std::string> docs;  // pybind11 keeps the pointer: never moved
    docs.push_back(doc + options);
    m.def(name, std::forward<F>(f), extra..., py::kw_only(), py::arg("iterations") = d.iterations,
          py::arg("angles_deg") = d.anglesDeg, py::arg("margin") = d.margin,
          py::arg("refine") = d.refine, py::arg("refine_iterations") = d.refineIterations,
          py::arg("shear") = d.shear, py::arg("hull_once") = d.hullOnce,
          py::arg("energy") = py::none(), docs.back().c_str());
}

std::vector<OptimizerStart> ToStarts(const py::object& obj) {
    std::vector<OptimizerStart> starts;
    for (const py::handle item : py::iter(obj)) {
        const auto tuple = item.cast<py::tuple>();
        if (tuple.size() != 2 && tuple.size() != 3)
            throw py::value_error("starts: each is (name, matrix) or (name, matrix, map_competes)");
        OptimizerStart start{tuple[0].cast<std::string>(), tuple[1].cast<LightMatrix>()};
        if (tuple.size() == 3) start.mapCompetes = tuple[2].cast<bool>();
        starts.push_back(std::move(start));
    }
    if (starts.empty()) throw py::value_error("starts: needs at least one (name, matrix)");
    return starts;
}

void BindResults(py::module_& m) {
    py::class_<OptimizerResult>(m, "OptimizerResult",
                                "Algorithm 1's result: the matrix, its h, and the search's trace.")
        .def_readonly("matrix", &OptimizerResult::matrix, "The optimized LightMatrix.")
        .def_readonly("h", &OptimizerResult::h, "Its energy over the samples (eq. 6).")
        .def_readonly("h_after_iteration", &OptimizerResult::hAfterIteration,
                      "[0] the initial axis's, then after each iteration.")
        .def_readonly("h_before_refine", &OptimizerResult::hBeforeRefine,
                      "h before the Ceres refinement (refine=True).")
        .def_readonly("candidates_tried", &OptimizerResult::candidatesTried,
                      "Candidate axes whose fit was evaluated.")
        .def_readonly("candidates_rejected", &OptimizerResult::candidatesRejected,
                      "Candidates with a visible point behind the map's plane.")
        .def_readonly("hull_vertices", &OptimizerResult::hullVertices,
                      "Vertices of the per-light 2D hull the rectangles were fitted to.")
        .def_readonly("cone_generators", &OptimizerResult::coneGenerators,
                      "Points the per-light hull started from (the 3D hull's vertices).")
        .def_readonly("used_fallback", &OptimizerResult::usedFallback,
                      "No valid candidate: the initial (focused) fit was returned.")
        .def_readonly("hull_ms", &OptimizerResult::hullMs,
                      "Wall time of the per-light 2D hull, ms (report Table 3).")
        .def_readonly("search_ms", &OptimizerResult::searchMs, "Wall time of the search, ms.")
        .def_readonly("refine_ms", &OptimizerResult::refineMs,
                      "Wall time of the Ceres refinement, ms.");

    py::class_<MultiStartResult>(m, "MultiStartResult",
                                 "`optimal`'s result: the winner among the competing starts' "
                                 "maps and Algorithm 1 from every start's axis.")
        .def_readonly("result", &MultiStartResult::result, "The winner's OptimizerResult.")
        .def_property_readonly(
            "matrix", [](const MultiStartResult& r) { return r.result.matrix; },
            "The winning LightMatrix.")
        .def_property_readonly(
            "h", [](const MultiStartResult& r) { return r.result.h; }, "Its energy.")
        .def_readonly("winner", &MultiStartResult::winner, "The start whose map or search won.")
        .def_readonly("start_map_won", &MultiStartResult::startMapWon,
                      "A competing start's own map, not a search, had the least energy.")
        .def_readonly("start_h", &MultiStartResult::startH, "Per start: its own map's energy.")
        .def_readonly("search_h", &MultiStartResult::searchH,
                      "Per start: after Algorithm 1 from its axis (inf: skipped, the axis "
                      "repeats an earlier start's).")
        .def_readonly("starving", &MultiStartResult::starving,
                      "Candidates the view guard passed over: their mean footprint over the "
                      "view exceeded 4x the best-fitted start's (energy 'e' only).");
}

void BindOptimizer(py::module_& m) {
    DefOptimizing(
        m, "optimize_light_matrix",
        [](const LightSamples& samples, const py::object& p4, const py::object& map, int iterations,
           const std::vector<double>& angles, double margin, bool refine, int refineIterations,
           bool shear, bool hullOnce, const py::object& energy) {
            const OptimizerOptions o = ToOptions(iterations, angles, margin, refine,
                                                 refineIterations, shear, hullOnce, energy);
            const glm::dvec3 axis = ToVec3(p4, "initial_p4");
            const Resolution r = ToResolution(map, "map");
            py::gil_scoped_release release;
            return OptimizeLightMatrix(samples, axis, r, o);
        },
        "Chong & Gortler's Algorithm 1 (report §2.3-2.4) from one optical axis (the standard "
        "map's p4, or initial_light_axis: `optimal-report`). Returns an OptimizerResult. "
        "DomainError when the samples have no visible points, or not even the initial axis "
        "sees them all.",
        py::arg("samples"), py::arg("initial_p4"), py::arg("map"));
    m.def(
        "standard_starts",
        [](const Context& context) {
            std::vector<std::tuple<std::string, LightMatrix, bool>> out;
            for (const OptimizerStart& s : StandardStarts(context.View()))
                out.emplace_back(s.name, s.matrix, s.mapCompetes);
            return out;
        },
        py::arg("context"),
        "`optimal`'s starts, [(name, LightMatrix, map_competes)]: focused-tight, lispsm-tight, "
        "lispsm-engine, psm-tight, normal, and plane-optimal when the context has a floor plane "
        "(its search competes, its own map does not: map_competes is False).");
    DefOptimizing(
        m, "optimize_from_starts",
        [](const LightSamples& samples, const py::object& startsObj, const py::object& map,
           int iterations, const std::vector<double>& angles, double margin, bool refine,
           int refineIterations, bool shear, bool hullOnce, const py::object& energy) {
            const OptimizerOptions o = ToOptions(iterations, angles, margin, refine,
                                                 refineIterations, shear, hullOnce, energy);
            const std::vector<OptimizerStart> starts = ToStarts(startsObj);
            const Resolution r = ToResolution(map, "map");
            py::gil_scoped_release release;
            return OptimizeFromStarts(samples, starts, r, o);
        },
        "Algorithm 1 from each start's axis, [(name, LightMatrix)] or [(name, LightMatrix, "
        "map_competes)] (standard_starts, or your own); the least energy among the competing "
        "starts' maps and the searches wins. Returns a MultiStartResult.",
        py::arg("samples"), py::arg("starts"), py::arg("map"));
    DefOptimizing(
        m, "optimal",
        [](const Context& context, int iterations, const std::vector<double>& angles, double margin,
           bool refine, int refineIterations, bool shear, bool hullOnce, const py::object& energy) {
            const OptimizerOptions o = ToOptions(iterations, angles, margin, refine,
                                                 refineIterations, shear, hullOnce, energy);
            const LightSamples& samples = context.Samples("optimal");
            py::gil_scoped_release release;
            const BaselineContext view = context.View();
            return OptimizeFromStarts(samples, StandardStarts(view), view.map, o);
        },
        "lexel's `optimal` (`optimal-refined` with refine=True): Algorithm 1 from every "
        "baseline's start (standard_starts), the least energy wins, so on its own energy it "
        "never loses to a baseline whose map competes. The context must hold the light's samples. "
        "Returns a MultiStartResult.",
        py::arg("context"));
}

// ---------------------------------------------------------------------------------------------
// Partitioned maps

std::vector<Cascade> ToCascades(const py::object& obj) {
    std::vector<Cascade> cascades;
    for (const py::handle item : py::iter(obj)) cascades.push_back(item.cast<Cascade>());
    if (cascades.empty()) throw py::value_error("cascades: needs at least one Cascade");
    return cascades;
}

void BindPartitions(py::module_& m) {
    m.attr("PARTITION_SCHEMES") = FamilyDescriptions(MethodFamily::kPartitioned);

    py::class_<Cascade>(m, "Cascade",
                        "One map of a partitioned method: it serves the pixels whose planar eye "
                        "depth lies in [z_near, z_far) (and inside ws_half_spaces).")
        .def_readonly("matrix", &Cascade::matrix, "Its LightMatrix.")
        .def_property_readonly(
            "map", [](const Cascade& c) { return FromResolution(c.map); }, "(W, H) texels.")
        .def_readonly("z_near", &Cascade::zNear, "World units along the view direction.")
        .def_readonly("z_far", &Cascade::zFar, "The far end of its eye-depth range, world units.")
        .def_property_readonly(
            "ws_half_spaces", [](const Cascade& c) { return FromVec4s(c.wsHalfSpaces); },
            "(K, 4): further half-spaces n . x + d >= 0 (face partitioning's wedges).")
        .def_readonly("visible_points", &Cascade::visiblePoints,
                      "Readback points it serves; 0: an empty partition.");

    m.def(
        "partitioned_light_matrices",
        [](const std::string& name, const Context& context, int count, double lambda,
           const std::string& allocation, bool snap, const std::string& energy) {
            PartitionOptions o;
            o.count = count;
            o.lambda = lambda;
            o.snap = snap;
            OptimizerOptions energyOnly;  // h unless the name selects another (lexel.ENERGIES)
            SelectOptimizerEnergy(py::str(energy), &energyOnly);
            o.energy = energyOnly.energy;
            if (count < 1 || count > kMaxCascades)
                throw py::value_error("count: must be in [1, " + std::to_string(kMaxCascades) +
                                      "], got " + std::to_string(count));
            if (!(lambda >= 0.0 && lambda <= 1.0))
                throw py::value_error("pssm_lambda: must be in [0, 1]");
            if (allocation == "equal")
                o.allocation = CascadeAllocation::kEqual;
            else if (allocation == "lagrange")
                o.allocation = CascadeAllocation::kLagrange;
            else
                throw py::value_error("allocation: expected 'equal' or 'lagrange', got '" +
                                      allocation + "'");
            CheckFamily(name, MethodFamily::kPartitioned, "scheme", "partition scheme");
            context.Samples(name.c_str());  // ValueError without them, naming the scheme
            MethodContext method = context.Method();
            method.partitions = o;
            py::gil_scoped_release release;
            return ComputeLightMatrix(name, method).cascades;
        },
        py::arg("scheme"), py::arg("context"), py::kw_only(), py::arg("count") = 4,
        py::arg("pssm_lambda") = 0.5, py::arg("allocation") = "equal", py::arg("snap") = false,
        py::arg("energy") = "e",
        "k cascades of a partitioned method (lexel.PARTITION_SCHEMES) whose texels add up to "
        "context.map's: 'equal' allocation (k maps of (W/sqrt k) x (H/sqrt k)) or 'lagrange' "
        "(texels moved toward the partitions with the larger cost). count: k in [1, 16]; "
        "pssm_lambda: PSSM's blend of the logarithmic and uniform splits; snap: SDSM's texel "
        "snapping (directional lights); energy: what sdsm-optimal's searches minimize and the "
        "Lagrange allocation's cost, 'e' (as optimal) or 'h' (eq. 6, as sdsm-optimal-h). The "
        "context must hold the light's samples.");
    m.def(
        "partitioned_energy",
        [](const py::object& cascadesObj, const Context& context) {
            const std::vector<Cascade> cascades = ToCascades(cascadesObj);
            return PartitionedEnergy(cascades, context.Samples("partitioned_energy"),
                                     context.relevant, context.camera);
        },
        py::arg("cascades"), py::arg("context"),
        "h (eq. 6) of a partitioned method: the sum over cascades of h of its matrix over the "
        "samples it serves.");
    m.def(
        "samples_of_cascade",
        [](const py::object& cascadesObj, std::size_t index, const Context& context) {
            const std::vector<Cascade> cascades = ToCascades(cascadesObj);
            if (index >= cascades.size())
                throw py::value_error("index: " + std::to_string(index) + " of " +
                                      std::to_string(cascades.size()) + " cascades");
            return SamplesOfCascade(context.Samples("samples_of_cascade"), context.relevant,
                                    context.camera, cascades, index);
        },
        py::arg("cascades"), py::arg("index"), py::arg("context"),
        "The LightSamples cascade `index` serves, with the visible points it serves.");
}

// ---------------------------------------------------------------------------------------------
// The registry: every method's record, and any method that returns light matrices by name

py::dict MethodRecord(const MethodInfo& info) {
    const MethodTraits& t = info.traits;
    py::dict traits;
    traits["fair_table"] = t.fairTable;
    traits["report_table"] = t.reportTable;
    traits["frustum_fitted"] = t.frustumFitted;
    traits["optimizer"] = t.optimizer;
    traits["partitioned"] = t.partitioned;
    traits["virtual_map"] = t.virtualMap;
    traits["warped"] = t.warped;
    traits["gpu_map"] = t.gpuMap;
    py::dict out;
    out["name"] = info.name;
    out["description"] = info.description;
    out["citation"] = info.citation;
    out["family"] = std::string(MethodFamilyName(info.family));
    out["default"] = !t.optIn;
    out["storage_model"] = std::string(StorageModelName(info.storage));
    out["traits"] = traits;
    return out;
}

// compute's answer: the matrix, the cascades, the optimizer's trace and which start won.
py::dict ComputedRecord(const MethodMatrix& result) {
    py::dict out;
    out["matrix"] = result.matrix;
    out["cascades"] = result.cascades;
    out["optimizer"] = result.optimizer ? py::cast(*result.optimizer) : py::none();
    out["winner"] = result.winner;
    out["fallback"] = result.diagnostics.fallback;
    return out;
}

void BindRegistry(py::module_& m) {
    m.attr("OPTIMAL_METHOD") = kOptimalMethod;  // the fair comparison's reference
    m.attr("ORACLE_METHOD") = kOracleMethod;    // the bound: the best single matrix measured
    m.def(
        "methods",
        [] {
            py::list out;
            for (const MethodInfo& info : MethodInfos()) out.append(MethodRecord(info));
            return out;
        },
        "Every 3D method lexel knows, in the order its reports keep (the list `lexel methods "
        "--format json` prints): dicts of name, description, citation, family, default (False: "
        "run only when named), storage_model and traits (fair_table, report_table, "
        "frustum_fitted, optimizer, partitioned, virtual_map, warped, gpu_map).");
    m.def(
        "compute",
        [](const std::string& name, const Context& context, int count) {
            const MethodInfo* info = FindMethodInfo(name);
            if (!info) throw py::value_error("name: unknown 3D method '" + name + "'");
            if (info->traits.warped || info->traits.virtualMap)
                throw py::value_error("name: " + name +
                                      "'s map is not a light matrix (warped or "
                                      "virtual): lexel run measures it");
            if (count < 1 || count > kMaxCascades)
                throw py::value_error("count: must be in [1, " + std::to_string(kMaxCascades) +
                                      "], got " + std::to_string(count));
            MethodContext method = context.Method();
            method.partitions.count = count;
            MethodMatrix result;
            {
                py::gil_scoped_release release;
                result = ComputeLightMatrix(name, method);
            }
            return ComputedRecord(result);
        },
        py::arg("name"), py::arg("context"), py::kw_only(), py::arg("count") = 4,
        "A method's light matrix by its name in lexel.methods(), computed as `lexel run` "
        "computes it from the context: a dict of matrix (LightMatrix), cascades (a partitioned "
        "method's k = count, else empty), optimizer (an optimizer method's OptimizerResult, "
        "else None), winner (the start that won, for optimal and optimal-refined) and fallback "
        "(a baseline's fallback, empty when its own construction was used). ValueError for an "
        "unknown name, a warped or virtual method (their maps are no light matrix), or a method "
        "that needs the context's samples without them.");
}

}  // namespace

void BindMethods(py::module_& m) {
    BindRegistry(m);
    BindContext(m);
    BindBaselines(m);
    BindResults(m);
    BindOptimizer(m);
    BindPartitions(m);
}

}  // namespace lexel::python
