// lexel.Light, Bounds, Camera, LightSpace, LightMatrix and the clip matrices (light_space.h,
// bounds.h, camera.h, light_matrix.h, clip_matrix.h).
#include <pybind11/stl.h>

#include <cmath>
#include <sstream>

#include "bindings.h"
#include "lexel/spatial/baselines.h"
#include "lexel/spatial/bounds.h"
#include "lexel/spatial/camera.h"
#include "lexel/spatial/clip_matrix.h"
#include "lexel/spatial/light_matrix.h"
#include "lexel/spatial/light_space.h"
#include "numpy_convert.h"

namespace lexel::python {

using namespace spatial;

namespace {

std::string VecText(const glm::dvec3& v) {
    std::ostringstream text;
    text.precision(17);
    text << "(" << v.x << ", " << v.y << ", " << v.z << ")";
    return text.str();
}

// ---------------------------------------------------------------------------------------------
// Light, Bounds

void BindLight(py::module_& m) {
    py::class_<Light>(m, "Light",
                      "A light: Light.point(position) or Light.directional(direction) (world "
                      "units; a direction is where the light travels, any length > 0).")
        .def_static(
            "point",
            [](const py::object& position) {
                Light light;
                light.type = Light::Type::kPoint;
                light.position = ToVec3(position, "position");
                return light;
            },
            py::arg("position"), "A point light at `position` (3 numbers, world units).")
        .def_static(
            "directional",
            [](const py::object& direction) {
                Light light;
                light.type = Light::Type::kDirectional;
                light.direction = ToVec3(direction, "direction");
                if (!(glm::length(light.direction) > 0.0))
                    throw py::value_error("direction: must not be zero");
                return light;
            },
            py::arg("direction"),
            "A directional light whose light travels along `direction` (3 numbers, not zero).")
        .def_property_readonly(
            "kind",
            [](const Light& l) { return l.type == Light::Type::kPoint ? "point" : "directional"; },
            "'point' or 'directional'.")
        .def_property_readonly(
            "position", [](const Light& l) { return FromVec3(l.position); },
            "A point light's position, (3,) (a copy).")
        .def_property_readonly(
            "direction", [](const Light& l) { return FromVec3(l.direction); },
            "A directional light's direction of travel, (3,) (a copy).")
        .def("__repr__", [](const Light& l) {
            return l.type == Light::Type::kPoint
                       ? "lexel.Light.point(" + VecText(l.position) + ")"
                       : "lexel.Light.directional(" + VecText(l.direction) + ")";
        });
}

Bounds MakeBounds(const py::object& lo, const py::object& hi) {
    Bounds b;
    b.lo = ToVec3(lo, "lo");
    b.hi = ToVec3(hi, "hi");
    for (int k = 0; k < 3; ++k)
        if (b.lo[k] > b.hi[k])
            throw py::value_error("lo, hi: lo must not exceed hi, got lo " + VecText(b.lo) +
                                  " and hi " + VecText(b.hi));
    return b;
}

void BindBounds(py::module_& m) {
    py::class_<Bounds>(m, "Bounds",
                       "Axis-aligned bounds of world points (world units): Bounds(lo, hi), or "
                       "Bounds.around(points). The light space and the depth ranges take the "
                       "bounds of everything that casts or receives shadows.")
        .def(py::init(&MakeBounds), py::arg("lo"), py::arg("hi"),
             "The box [lo, hi] (3 numbers each, lo <= hi).")
        .def_static(
            "around",
            [](const py::object& points) {
                const std::vector<glm::dvec3> ws = ToPoints(points, "points");
                if (ws.empty()) throw py::value_error("points: needs at least one point");
                Bounds b;
                for (const glm::dvec3& p : ws) b.Add(p);
                return b;
            },
            py::arg("points"), "The smallest box around (N, 3) points, N >= 1.")
        .def_property_readonly(
            "lo", [](const Bounds& b) { return FromVec3(b.lo); }, "The low corner, (3,).")
        .def_property_readonly(
            "hi", [](const Bounds& b) { return FromVec3(b.hi); }, "The high corner, (3,).")
        .def(
            "center", [](const Bounds& b) { return FromVec3(b.Center()); }, "The centre, (3,).")
        .def("radius", &Bounds::Radius, "The radius of the enclosing sphere (half the diagonal).")
        .def(
            "corners",
            [](const Bounds& b) {
                const std::array<glm::dvec3, 8> c = b.Corners();
                return FromPoints(c);
            },
            "The 8 corners, (8, 3): corner i has coordinate k at hi when bit k of i is set.")
        .def("__repr__", [](const Bounds& b) {
            return "lexel.Bounds(" + VecText(b.lo) + ", " + VecText(b.hi) + ")";
        });
}

// ---------------------------------------------------------------------------------------------
// Camera

void CheckCamera(const Camera& c) {
    if (!(c.fovYDeg > 0.0 && c.fovYDeg < 180.0))
        throw py::value_error("fov_y_deg: must be in (0, 180), got " + std::to_string(c.fovYDeg));
    if (!(c.nearPlane > 0.0 && c.nearPlane < c.farPlane && std::isfinite(c.farPlane)))
        throw py::value_error("near, far: need 0 < near < far, both finite, got " +
                              std::to_string(c.nearPlane) + " and " + std::to_string(c.farPlane));
    const glm::dvec3 view = c.target - c.position;
    if (!(glm::length(view) > 0.0))
        throw py::value_error("position, target: the camera must not look at its own position");
    if (!(glm::length(glm::cross(view, c.up)) > 1e-12 * glm::length(view) * glm::length(c.up)))
        throw py::value_error("up: must not be zero or parallel to the view direction");
}

Camera MakeCamera(const py::object& position, const py::object& target, const py::object& up,
                  const py::object& fovYDeg, const py::object& resolution, const py::object& near,
                  const py::object& far) {
    Camera c;
    c.position = ToVec3(position, "position");
    c.target = ToVec3(target, "target");
    c.up = ToVec3(up, "up");
    c.fovYDeg = ToFinite(fovYDeg, "fov_y_deg");
    c.resolution = ToResolution(resolution, "resolution");
    c.nearPlane = ToFinite(near, "near");
    c.farPlane = ToFinite(far, "far");
    CheckCamera(c);
    return c;
}

void BindCamera(py::module_& m) {
    const Camera d;
    py::class_<Camera>(m, "Camera",
                       "A pinhole camera looking from `position` at `target` with OpenGL's "
                       "projection (lengths in world units, the vertical field of view in "
                       "degrees). The baselines take one: the viewer whose frame is rendered.")
        .def(py::init(&MakeCamera), py::kw_only(), py::arg("position") = FromVec3(d.position),
             py::arg("target") = FromVec3(d.target), py::arg("up") = FromVec3(d.up),
             py::arg("fov_y_deg") = d.fovYDeg,
             py::arg("resolution") = py::make_tuple(d.resolution.width, d.resolution.height),
             py::arg("near") = d.nearPlane, py::arg("far") = d.farPlane,
             "Camera(*, position, target, up, fov_y_deg, resolution=(width, height), near, far); "
             "0 < fov_y_deg < 180, 0 < near < far. ValueError naming the argument otherwise.")
        .def_property_readonly(
            "position", [](const Camera& c) { return FromVec3(c.position); }, "(3,)")
        .def_property_readonly(
            "target", [](const Camera& c) { return FromVec3(c.target); }, "(3,)")
        .def_property_readonly(
            "up", [](const Camera& c) { return FromVec3(c.up); }, "(3,)")
        .def_property_readonly(
            "fov_y_deg", [](const Camera& c) { return c.fovYDeg; },
            "The full vertical field of view, degrees.")
        .def_property_readonly(
            "resolution", [](const Camera& c) { return FromResolution(c.resolution); },
            "(width, height) of the final frame; it sets the aspect ratio.")
        .def_property_readonly(
            "near", [](const Camera& c) { return c.nearPlane; }, "The near plane, world units.")
        .def_property_readonly(
            "far", [](const Camera& c) { return c.farPlane; }, "The far plane, world units.")
        .def("aspect_ratio", &Camera::AspectRatio, "width / height of `resolution`.")
        .def(
            "view_from_world", [](const Camera& c) { return FromMatrix4(c.ViewFromWorld()); },
            "The view matrix (glm::lookAt), (4, 4).")
        .def(
            "clip_from_view", [](const Camera& c) { return FromMatrix4(c.ClipFromView()); },
            "OpenGL's projection (glm::perspective: NDC z in [-1, 1], -1 at near), (4, 4).")
        .def(
            "clip_from_world",
            [](const Camera& c) { return FromMatrix4(c.ClipFromView() * c.ViewFromWorld()); },
            "clip_from_view() @ view_from_world(): the matrix of a depth buffer in "
            "DepthConvention.opengl().")
        .def(
            "screen_from_world",
            [](const Camera& c, const py::object& at) {
                return FromMatrix4(c.ScreenFromWorld(
                    at.is_none() ? c.resolution : ToResolution(at, "resolution")));
            },
            py::arg("resolution") = py::none(),
            "Report eq. 1's Q for an image of `resolution` (default: the camera's): world -> "
            "(x1 w, x2 w, x3 w, w), x1, x2 in pixels (x2 down), x3 the window depth in [0, 1].")
        .def(
            "frustum_corners",
            [](const Camera& c) {
                const std::array<glm::dvec3, 8> corners = c.FrustumCorners();
                return FromPoints(corners);
            },
            "The view frustum's 8 corners, (8, 3): the near face, then the far face.")
        .def("__repr__", [](const Camera& c) {
            std::ostringstream text;
            text << "lexel.Camera(position=" << VecText(c.position)
                 << ", target=" << VecText(c.target) << ", up=" << VecText(c.up)
                 << ", fov_y_deg=" << c.fovYDeg << ", resolution=(" << c.resolution.width << ", "
                 << c.resolution.height << "), near=" << c.nearPlane << ", far=" << c.farPlane
                 << ")";
            return text.str();
        });
}

// ---------------------------------------------------------------------------------------------
// LightSpace, LightMatrix

void BindLightSpace(py::module_& m) {
    py::class_<LightSpace>(m, "LightSpace",
                           "Chong & Gortler's light space (report §2.1): an orthonormal frame at "
                           "the light whose +z points at the centre of the scene's bounds; a "
                           "world point x becomes X, and the map u^i = (p_i . X) / (p4 . X).")
        .def(py::init<const Light&, const Bounds&>(), py::arg("light"), py::arg("bounds"),
             "LightSpace(light, bounds). DomainError when the bounds are empty, a point light is "
             "inside them, or a direction is zero or not finite.")
        .def_property_readonly(
            "light", [](const LightSpace& s) { return s.light(); },
            "The light (a directional one's direction normalized).")
        .def_property_readonly("is_point", &LightSpace::IsPoint, "True for a point light.")
        .def(
            "to_light",
            [](const LightSpace& s, const py::object& points) {
                std::vector<glm::dvec3> ls = ToPoints(points, "points");
                for (glm::dvec3& p : ls) p = s.ToLight(p);
                return FromPoints(ls);
            },
            py::arg("points"), "X for (N, 3) world points, (N, 3).")
        .def(
            "depth",
            [](const LightSpace& s, const py::object& points) {
                const std::vector<glm::dvec3> ws = ToPoints(points, "points");
                std::vector<double> depth(ws.size());
                for (std::size_t i = 0; i < ws.size(); ++i) depth[i] = s.Depth(ws[i]);
                return FromVector<double>(depth);
            },
            py::arg("points"),
            "Linear depth of (N, 3) world points, (N,): the distance from a point light, the "
            "distance along the direction (plus a positive constant) for a directional one.")
        .def(
            "light_from_world_linear",
            [](const LightSpace& s) { return FromMatrix3(s.LsFromWsLinear()); },
            "dX/dx, (3, 3): rows e1, e2 and e3 (point light) or 0 (directional).");
}

std::vector<glm::dvec2> ToMapPoints(const py::handle& obj, const std::string& name) {
    const DoubleArray a = AsDoubles(obj, name);
    if (a.ndim() != 2 || a.shape(1) != 2)
        throw py::value_error(name + ": expected (N, 2) map points, got shape " + ShapeText(a));
    std::vector<glm::dvec2> u(static_cast<std::size_t>(a.shape(0)));
    for (std::size_t i = 0; i < u.size(); ++i) {
        u[i] = {a.data()[2 * i], a.data()[2 * i + 1]};
        if (!std::isfinite(u[i].x) || !std::isfinite(u[i].y))
            throw py::value_error(name + ": row " + std::to_string(i) + " is not finite");
    }
    return u;
}

void CheckInFront(const LightMatrix& matrix, std::span<const glm::dvec3> ls,
                  const std::string& name) {
    for (std::size_t i = 0; i < ls.size(); ++i)
        if (!InFront(matrix.p4, ls[i]))
            throw py::value_error(name + ": row " + std::to_string(i) +
                                  " is not in front of the map's plane (p4 . X <= 1e-9 |X|)");
}

void BindLightMatrix(py::module_& m) {
    py::class_<LightMatrix>(
        m, "LightMatrix",
        "The light matrix P of Chong & Gortler (report §2.1, Fig. 1): rows p1, p2 (the affine "
        "part, texels) and the optical axis p4 (unit), acting on light-space X: u^i = (p_i . X) / "
        "(p4 . X). clip_from_world() turns it into the 4x4 a rasterizer takes.")
        .def(py::init([](const py::object& p1, const py::object& p2, const py::object& p4) {
                 return LightMatrix{ToVec3(p1, "p1"), ToVec3(p2, "p2"), ToVec3(p4, "p4")};
             }),
             py::arg("p1") = FromVec3({1, 0, 0}), py::arg("p2") = FromVec3({0, 1, 0}),
             py::arg("p4") = FromVec3({0, 0, 1}), "LightMatrix(p1, p2, p4), 3 numbers each.")
        .def_property_readonly(
            "p1", [](const LightMatrix& l) { return FromVec3(l.p1); }, "Row 1, (3,).")
        .def_property_readonly(
            "p2", [](const LightMatrix& l) { return FromVec3(l.p2); }, "Row 2, (3,).")
        .def_property_readonly(
            "p4", [](const LightMatrix& l) { return FromVec3(l.p4); }, "The optical axis, (3,).")
        .def(
            "rows", [](const LightMatrix& l) { return FromMatrix3(l.Rows()); },
            "[p1; p2; p4] as a (3, 3) array, one row each.")
        .def(
            "map",
            [](const LightMatrix& l, const py::object& points) {
                const std::vector<glm::dvec3> ls = ToPoints(points, "ls_points");
                CheckInFront(l, ls, "ls_points");
                std::vector<glm::dvec2> u(ls.size());
                for (std::size_t i = 0; i < ls.size(); ++i) u[i] = l.Map(ls[i]);
                return FromMapPoints(u);
            },
            py::arg("ls_points"),
            "u for (N, 3) light-space points, (N, 2) texels. ValueError for a point not in "
            "front of the plane p4 . X = 0 (it maps through infinity).")
        .def(
            "unmap",
            [](const LightMatrix& l, const py::object& u) {
                const std::vector<glm::dvec2> map = ToMapPoints(u, "u");
                std::vector<glm::dvec3> ls(map.size());
                for (std::size_t i = 0; i < map.size(); ++i) ls[i] = l.Unmap(map[i]);
                return FromPoints(ls);
            },
            py::arg("u"), "The light-space X with map(X) = u and p4 . X = 1, for (N, 2) texels.")
        .def(
            "then_affine",
            [](const LightMatrix& l, const py::object& a) {
                const glm::dmat3 affine = ToMatrix3(a, "a");
                if (affine[0][2] != 0.0 || affine[1][2] != 0.0 || affine[2][2] != 1.0)
                    throw py::value_error("a: its last row must be (0, 0, 1)");
                return l.ThenAffine(affine);
            },
            py::arg("a"),
            "The same map followed by the 2D affine change u' = a @ (u, 1) (a: (3, 3), last row "
            "(0, 0, 1)).")
        .def("__eq__",
             [](const LightMatrix& a, const LightMatrix& b) {
                 return a.p1 == b.p1 && a.p2 == b.p2 && a.p4 == b.p4;
             })
        .def("__copy__", [](const LightMatrix& l) { return l; })
        .def("__deepcopy__", [](const LightMatrix& l, const py::dict&) { return l; })
        .def("__repr__", [](const LightMatrix& l) {
            return "lexel.LightMatrix(p1=" + VecText(l.p1) + ", p2=" + VecText(l.p2) +
                   ", p4=" + VecText(l.p4) + ")";
        });
    m.attr("LightMatrix").attr("__hash__") = py::none();
}

// ---------------------------------------------------------------------------------------------
// Light matrices from world matrices, fits, clip matrices

DepthRange ToDepthRange(const LightSpace& s, const py::object& obj) {
    if (!py::isinstance<py::sequence>(obj) || py::len(obj) != 2)
        throw py::type_error("depth_range: expected (near, far)");
    const py::sequence range = py::reinterpret_borrow<py::sequence>(obj);
    const DepthRange r{ToFinite(range[0], "depth_range[0]"), ToFinite(range[1], "depth_range[1]")};
    if (!(r.near < r.far) || (s.IsPoint() && !(r.near > 0.0)))
        throw py::value_error(std::string("depth_range: needs ") +
                              (s.IsPoint() ? "0 < near < far" : "near < far") + ", got (" +
                              std::to_string(r.near) + ", " + std::to_string(r.far) + ")");
    return r;
}

// The clip matrices a rasterizer renders a light matrix with, and their depth range.
void BindClipMatrices(py::module_& m) {
    py::enum_<ClipDepth>(m, "ClipDepth",
                         "A projection's clip depth: MINUS_ONE_TO_ONE (OpenGL's default) or "
                         "ZERO_TO_ONE (Direct3D, Vulkan, glClipControl GL_ZERO_TO_ONE).")
        .value("MINUS_ONE_TO_ONE", ClipDepth::kMinusOneToOne)
        .value("ZERO_TO_ONE", ClipDepth::kZeroToOne);

    m.def(
        "map_from_world",
        [](const LightSpace& s, const LightMatrix& l) { return FromMatrix4(MapFromWorld(s, l)); },
        py::arg("light_space"), py::arg("matrix"),
        "P.A in world form, (4, 4): rows (p1 A, p2 A, 0, p4 A), so a world point x lands on texel "
        "u^i = row_i . (x, 1) / row_4 . (x, 1).");
    m.def(
        "clip_from_world",
        [](const LightSpace& s, const LightMatrix& l, const py::object& map,
           const py::object& range, ClipDepth convention) {
            return FromMatrix4(
                ClipFromWorld(s, l, ToResolution(map, "map"), ToDepthRange(s, range), convention));
        },
        py::arg("light_space"), py::arg("matrix"), py::arg("map"), py::arg("depth_range"),
        py::arg("clip_depth") = ClipDepth::kZeroToOne,
        "The (4, 4) a rasterizer renders the shadow map with: x_ndc = 2 u1 / W - 1, y_ndc = "
        "2 u2 / H - 1 (texel row 0 at y_ndc = -1), w_clip = p4 . X, and z_ndc running from the "
        "near to the far end of clip_depth (ClipDepth.ZERO_TO_ONE: [0, 1], the default; "
        "MINUS_ONE_TO_ONE: [-1, 1]) over depth_range = (near, far), world units (see "
        "light_depth_range). map = (W, H) texels.");
    m.def(
        "clip_depth_quantity",
        [](const LightSpace& s, const LightMatrix& l, const py::object& points) {
            const std::vector<glm::dvec3> ws = ToPoints(points, "points");
            std::vector<double> q(ws.size());
            for (std::size_t i = 0; i < ws.size(); ++i) q[i] = ClipDepthQuantity(s, l, ws[i]);
            return FromVector<double>(q);
        },
        py::arg("light_space"), py::arg("matrix"), py::arg("points"),
        "clip_from_world's depth quantity at (N, 3) world points, (N,): p4 . X for a point light, "
        "d (s / w) for a directional one; +inf behind the map's plane.");
    m.def(
        "light_depth_range",
        [](const LightSpace& s, const LightMatrix& l, const py::object& map, const Bounds& casters,
           const py::object& receivers, const py::object& margin) {
            const std::vector<glm::dvec3> ws = ToPoints(receivers, "receivers");
            const double fraction = ToFinite(margin, "margin");
            if (fraction < 0.0) throw py::value_error("margin: must be >= 0");
            const DepthRange r =
                LightDepthRange(s, l, ToResolution(map, "map"), casters, ws, fraction);
            return py::make_tuple(r.near, r.far);
        },
        py::arg("light_space"), py::arg("matrix"), py::arg("map"), py::arg("caster_bounds"),
        py::arg("receivers"), py::arg("margin") = 0.02,
        "The tightest (near, far) that loses no shadow: far from the receivers ((N, 3), the "
        "readback's visible points), near from caster_bounds inside the map's frustum, each end "
        "moved out by margin x (far - near). ValueError when there are no receivers or one is "
        "behind the map's plane.");
}

// Light matrices from elsewhere: a world 4×4, a fit of the affine part, Algorithm 1's first axis.
void BindMatrixFits(py::module_& m) {
    m.def(
        "from_screen_rows",
        [](const LightSpace& s, const py::object& screen, const py::object& center) {
            std::string failure;
            const std::optional<LightMatrix> l = FromScreenRows(
                s, ToMatrix4(screen, "screen_from_world"), ToVec3(center, "ws_center"), &failure);
            if (!l) throw py::value_error("screen_from_world: " + failure);
            return *l;
        },
        py::arg("light_space"), py::arg("screen_from_world"), py::arg("ws_center"),
        "The LightMatrix of a world (4, 4) whose rows 1, 2 and 4 send world points to texels "
        "(row 3 ignored): your own light matrix, to measure it with lexel's energies. The rows "
        "must send the light to infinity (ValueError with the reason otherwise); the result has "
        "|p4| = 1 and p4 . X > 0 at ws_center.");
    m.def(
        "fit_map_to_points",
        [](const py::object& p4, const py::object& points, const py::object& map,
           const py::object& margin, bool shear) {
            const std::vector<glm::dvec3> ls = ToPoints(points, "ls_points");
            FitOptions options;
            options.margin = ToFinite(margin, "margin");
            options.shear = shear;
            const std::optional<LightMatrix> l =
                FitMapToPoints(ToVec3(p4, "p4"), ls, ToResolution(map, "map"), options);
            if (!l)
                throw py::value_error(
                    "ls_points: empty, a point not in front of the plane p4 . X = 0, or a fit "
                    "whose rows are not finite");
            return *l;
        },
        py::arg("p4"), py::arg("ls_points"), py::arg("map"), py::arg("margin") = 0.0,
        py::arg("shear") = false,
        "The affine part for axis p4 (Algorithm 1 step 4b-ii): the minimum-area rectangle (or "
        "with shear=True the minimum-area parallelogram) around the (N, 3) light-space points "
        "projected on p4 . X = 1, grown by margin, onto [0, W] x [0, H] texels.");
    m.def(
        "initial_light_axis",
        [](const LightSpace& s, const Bounds& bounds, const py::object& relevant) {
            const std::vector<glm::dvec3> ws = ToPoints(relevant, "relevant");
            return FromVec3(InitialLightAxis(s, bounds, ws));
        },
        py::arg("light_space"), py::arg("bounds"), py::arg("relevant"),
        "The optical axis Algorithm 1 starts from (focused's): toward the bounds' centre, or "
        "normal's fallbacks. (3,), unit. DomainError when no axis sees every visible point.");
}

}  // namespace

void BindGeometry(py::module_& m) {
    BindLight(m);
    BindBounds(m);
    BindCamera(m);
    BindLightSpace(m);
    BindLightMatrix(m);
    BindClipMatrices(m);
    BindMatrixFits(m);
}

}  // namespace lexel::python
