// lexel.DepthConvention, downsample_depth, make_readback, Readback, Shade, LightSamples
// (depth_buffer.h, readback.h, samples.h): Algorithm 1 steps 1-3 from a renderer's depth buffer.
#include <pybind11/stl.h>

#include "bindings.h"
#include "lexel/spatial/depth_buffer.h"
#include "lexel/spatial/readback.h"
#include "lexel/spatial/samples.h"
#include "numpy_convert.h"

namespace lexel::python {

using namespace spatial;

namespace {

// ---------------------------------------------------------------------------------------------
// Depth conventions and buffers

const char* Name(ClipDepth c) {
    return c == ClipDepth::kZeroToOne ? "ClipDepth.ZERO_TO_ONE" : "ClipDepth.MINUS_ONE_TO_ONE";
}
const char* Name(DepthDirection d) {
    return d == DepthDirection::kReversed ? "DepthDirection.REVERSED" : "DepthDirection.STANDARD";
}
const char* Name(FirstRow f) {
    return f == FirstRow::kAtNdcYMinusOne ? "FirstRow.AT_NDC_Y_MINUS_ONE"
                                          : "FirstRow.AT_NDC_Y_PLUS_ONE";
}

DepthDirection Direction(bool reversed) {
    return reversed ? DepthDirection::kReversed : DepthDirection::kStandard;
}

void BindConventions(py::module_& m) {
    py::enum_<DepthDirection>(m, "DepthDirection",
                              "Which way stored depth runs: STANDARD (0 at the near plane, "
                              "cleared to 1) or REVERSED (reversed-Z: 1 at the near plane, 0 at "
                              "the far plane or infinity, cleared to 0).")
        .value("STANDARD", DepthDirection::kStandard)
        .value("REVERSED", DepthDirection::kReversed);
    py::enum_<FirstRow>(m, "FirstRow",
                        "Which NDC y the array's row 0 lies at: AT_NDC_Y_PLUS_ONE (Direct3D's "
                        "framebuffer, lexel's images) or AT_NDC_Y_MINUS_ONE (OpenGL's "
                        "glReadPixels, bottom row first; Vulkan, whose NDC y points down).")
        .value("AT_NDC_Y_PLUS_ONE", FirstRow::kAtNdcYPlusOne)
        .value("AT_NDC_Y_MINUS_ONE", FirstRow::kAtNdcYMinusOne);

    py::class_<DepthConvention>(
        m, "DepthConvention",
        "How a renderer stored its depth buffer: clip depth, direction and row order. The "
        "presets: DepthConvention.opengl() (glReadPixels of a default GL context), direct3d(), "
        "vulkan(); each takes reversed=True for reversed-Z (a finite or infinite far plane).")
        .def(py::init([](ClipDepth clipDepth, DepthDirection direction, FirstRow firstRow) {
                 return DepthConvention{clipDepth, direction, firstRow};
             }),
             py::kw_only(), py::arg("clip_depth") = ClipDepth::kMinusOneToOne,
             py::arg("direction") = DepthDirection::kStandard,
             py::arg("first_row") = FirstRow::kAtNdcYPlusOne,
             "DepthConvention(*, clip_depth, direction, first_row); the default is lexel's own "
             "(OpenGL's clip depth, standard, row 0 at the top).")
        .def_static(
            "opengl",
            [](bool reversed) {
                return DepthConvention{ClipDepth::kMinusOneToOne, Direction(reversed),
                                       FirstRow::kAtNdcYMinusOne};
            },
            py::arg("reversed") = false,
            "OpenGL: clip depth [-1, 1], bottom row first (glReadPixels).")
        .def_static(
            "direct3d",
            [](bool reversed) {
                return DepthConvention{ClipDepth::kZeroToOne, Direction(reversed),
                                       FirstRow::kAtNdcYPlusOne};
            },
            py::arg("reversed") = false, "Direct3D: clip depth [0, 1], top row first.")
        .def_static(
            "vulkan",
            [](bool reversed) {
                return DepthConvention{ClipDepth::kZeroToOne, Direction(reversed),
                                       FirstRow::kAtNdcYMinusOne};
            },
            py::arg("reversed") = false,
            "Vulkan: clip depth [0, 1], row 0 at NDC y = -1 (its NDC y points down).")
        .def_readonly("clip_depth", &DepthConvention::clipDepth, "A ClipDepth.")
        .def_readonly("direction", &DepthConvention::direction, "A DepthDirection.")
        .def_readonly("first_row", &DepthConvention::firstRow, "A FirstRow.")
        .def("__eq__",
             [](const DepthConvention& a, const DepthConvention& b) {
                 return a.clipDepth == b.clipDepth && a.direction == b.direction &&
                        a.firstRow == b.firstRow;
             })
        .def("__repr__", [](const DepthConvention& c) {
            return std::string("lexel.DepthConvention(clip_depth=") + Name(c.clipDepth) +
                   ", direction=" + Name(c.direction) + ", first_row=" + Name(c.firstRow) + ")";
        });
    m.attr("DepthConvention").attr("__hash__") = py::none();
}

// A depth array and its matrix as lexel's DepthBuffer; `storage` keeps the values alive.
DepthBuffer ToDepthBuffer(const py::object& depth, const py::object& clipFromWorld,
                          const DepthConvention& convention, FloatArray* storage) {
    DepthBuffer buffer;
    *storage = ToDepthImage(depth, "depth", &buffer.resolution);
    buffer.depth = std::span<const float>(storage->data(), buffer.resolution.Count());
    buffer.clipFromWorld = ToMatrix4(clipFromWorld, "clip_from_world");
    buffer.convention = convention;
    return buffer;
}

void BindDepthBuffers(py::module_& m) {
    py::class_<DepthImage>(m, "DepthImage",
                           "A depth buffer sampled down by downsample_depth: .depth (H, W) "
                           "float32, .clip_from_world (4, 4) under which its samples are the "
                           "pixel centres, .convention, and which source pixels it holds "
                           "(.step, .offset).")
        .def_property_readonly(
            "depth", [](const DepthImage& d) { return FromFloatImage(d.resolution, d.depth); },
            "(H, W) float32, as the renderer stored it (a copy).")
        .def_property_readonly(
            "clip_from_world", [](const DepthImage& d) { return FromMatrix4(d.clipFromWorld); },
            "(4, 4): the projection under which the samples are the small image's pixel "
            "centres.")
        .def_readonly("convention", &DepthImage::convention, "The source's DepthConvention.")
        .def_readonly("step", &DepthImage::step, "Every step-th source pixel is kept.")
        .def_property_readonly(
            "offset", [](const DepthImage& d) { return py::make_tuple(d.offset.x, d.offset.y); },
            "(x, y) of the first kept source pixel: sample (i, j) is source pixel "
            "(step i + x, step j + y).");

    m.def(
        "downsample_depth",
        [](const py::object& depth, const py::object& clip, const DepthConvention& convention,
           int maxSide) {
            FloatArray storage;
            const DepthBuffer buffer = ToDepthBuffer(depth, clip, convention, &storage);
            if (maxSide < 1) throw py::value_error("max_side: must be at least 1");
            return DownsampleDepth(buffer, maxSide);
        },
        py::arg("depth"), py::arg("clip_from_world"), py::arg("convention") = DepthConvention{},
        py::arg("max_side") = kReadbackSide,
        "Algorithm 1's low-resolution readback from a full-size buffer: every step-th pixel of "
        "each row and column (step = ceil(max(W, H) / max_side)), no filtering (which would "
        "invent points between a silhouette and what lies behind it). depth: (H, W), converted "
        "to float32; clip_from_world: the projection @ view that drew it, (4, 4). Returns a "
        "DepthImage; make_readback takes it. The report found 180 a side enough for 1150^2 "
        "frames (§2.4), the default.");
    m.def(
        "screen_from_world",
        [](const py::object& resolution, const py::object& clip,
           const DepthConvention& convention) {
            DepthBuffer buffer;
            buffer.resolution = ToResolution(resolution, "resolution");
            buffer.clipFromWorld = ToMatrix4(clip, "clip_from_world");
            buffer.convention = convention;
            return FromMatrix4(ScreenFromWorld(buffer));
        },
        py::arg("resolution"), py::arg("clip_from_world"),
        py::arg("convention") = DepthConvention{},
        "Q for a depth buffer of (width, height): world -> (x1 w, x2 w, x3 w, w) with pixel "
        "(x, y) of the array (y its row) at x1 in [x, x + 1], x2 in [y, y + 1], and x3 the value "
        "stored there.");
}

// ---------------------------------------------------------------------------------------------
// The readback

std::vector<bool> CoveredPixels(const CameraBuffer& b) {
    std::vector<bool> covered(b.triangle.size());
    for (std::size_t i = 0; i < covered.size(); ++i) covered[i] = b.Covered(i);
    return covered;
}

void BindReadbackClass(py::module_& m) {
    py::class_<Readback>(
        m, "Readback",
        "What the low-resolution camera pass sees per pixel (report §2.3 steps 1-2, Appendix A). "
        "Per-pixel arrays are (H, W) or (H, W, 3) and indexed [row, column] exactly as the depth "
        "array given to make_readback; a shadow mask for make_light_samples uses the same order. "
        "Every property returns a new array.")
        .def_property_readonly(
            "resolution", [](const Readback& r) { return FromResolution(r.buffer.resolution); },
            "(width, height).")
        .def_property_readonly(
            "covered",
            [](const Readback& r) {
                return FromMask(r.buffer.resolution, CoveredPixels(r.buffer));
            },
            "(H, W) bool: the pixel sees something.")
        .def_property_readonly(
            "window_depth",
            [](const Readback& r) { return FromImage(r.buffer.resolution, r.buffer.windowDepth); },
            "(H, W) float64: lexel's window depth x3 in [0, 1] (affine in 1/z_view); 1 where "
            "empty.")
        .def_property_readonly(
            "ws_position",
            [](const Readback& r) { return FromImage3(r.buffer.resolution, r.buffer.wsPosition); },
            "(H, W, 3): the world point each pixel sees (the unprojected depth at its centre; "
            "meaningless where not covered).")
        .def_property_readonly(
            "dwdx1", [](const Readback& r) { return FromImage3(r.buffer.resolution, r.dWdx1); },
            "(H, W, 3): dW/dx1, world units per readback pixel to the right (eq. 7; 0 where not "
            "smooth).")
        .def_property_readonly(
            "dwdx2", [](const Readback& r) { return FromImage3(r.buffer.resolution, r.dWdx2); },
            "(H, W, 3): dW/dx2, world units per readback pixel down the array.")
        .def_property_readonly(
            "smooth",
            [](const Readback& r) {
                return FromMask(r.buffer.resolution,
                                std::vector<bool>(r.smooth.begin(), r.smooth.end()));
            },
            "(H, W) bool: the derivatives are reliable there (report §2.4: the depth's second "
            "difference is small); boundary samples elsewhere are dropped.")
        .def_property_readonly(
            "ws_relevant", [](const Readback& r) { return FromPoints(r.wsRelevant); },
            "(N, 3): every visible point, in pixel order (ws_position[covered]).")
        .def_property_readonly(
            "ws_relevant_hull", [](const Readback& r) { return FromPoints(r.wsRelevantHull); },
            "(M, 3): the vertices of the visible points' 3D convex hull, in pixel order.")
        .def_readonly("relevant_hull_ms", &Readback::relevantHullMs, "Wall time of that hull, ms.");

    m.def(
        "make_readback",
        [](const DepthImage& image) {
            py::gil_scoped_release release;
            return MakeReadback(image.View());
        },
        py::arg("image"), "The readback of a DepthImage (downsample_depth's result).");
    m.def(
        "make_readback",
        [](const py::object& depth, const py::object& clip, const DepthConvention& convention) {
            FloatArray storage;
            const DepthBuffer buffer = ToDepthBuffer(depth, clip, convention, &storage);
            py::gil_scoped_release release;
            return MakeReadback(buffer);
        },
        py::arg("depth"), py::arg("clip_from_world"), py::arg("convention") = DepthConvention{},
        "The readback of a depth buffer: depth (H, W) as the renderer stored it (converted to "
        "float32; covered where finite and nearer than the cleared value), clip_from_world the "
        "projection @ view that drew it, (4, 4), in `convention`. Its time grows with the "
        "pixels (every one is a candidate for the visible points' hull): pass about 180 a side, "
        "or a buffer through downsample_depth. ValueError when the matrix is singular or not "
        "finite, or its depth runs the other way than convention.direction says (naming the "
        "one to use).");
}

// ---------------------------------------------------------------------------------------------
// Shades and light samples

std::vector<Shade> ToShades(const py::object& obj, Resolution expected) {
    const py::array a = py::array::ensure(obj);
    if (!a) {
        PyErr_Clear();
        throw py::type_error("shades: expected a (H, W) array of lexel.Shade values");
    }
    const char kind = a.dtype().kind();
    if (kind != 'i' && kind != 'u' && kind != 'b')
        throw py::type_error("shades: expected integers (lexel.Shade values), got dtype " +
                             std::string(py::str(a.dtype())));
    if (a.ndim() != 2 || a.shape(0) != expected.height || a.shape(1) != expected.width)
        throw py::value_error("shades: expected shape (" + std::to_string(expected.height) + ", " +
                              std::to_string(expected.width) + "), the readback's, got " +
                              ShapeText(a));
    const auto values =
        py::array_t<long long, py::array::c_style | py::array::forcecast>::ensure(a);
    std::vector<Shade> shades(expected.Count());
    for (std::size_t i = 0; i < shades.size(); ++i) {
        const long long v = values.data()[i];
        if (v < 0 || v > 3)
            throw py::value_error("shades: entry [" + std::to_string(i / expected.width) + ", " +
                                  std::to_string(i % expected.width) + "] is " + std::to_string(v) +
                                  ", not a lexel.Shade (0 to 3)");
        shades[i] = static_cast<Shade>(v);
    }
    return shades;
}

std::vector<std::uint32_t> ToPixels(const py::object& obj) {
    const py::array a = py::array::ensure(obj);
    if (!a || (a.dtype().kind() != 'i' && a.dtype().kind() != 'u')) {
        PyErr_Clear();
        throw py::type_error("pixels: expected a (K,) array of integer pixel indices");
    }
    if (a.ndim() != 1) throw py::value_error("pixels: expected (K,), got " + ShapeText(a));
    const auto values =
        py::array_t<long long, py::array::c_style | py::array::forcecast>::ensure(a);
    std::vector<std::uint32_t> pixels(static_cast<std::size_t>(a.shape(0)));
    for (std::size_t k = 0; k < pixels.size(); ++k) {
        const long long v = values.data()[k];
        if (v < 0 || v > 0xffffffffLL)
            throw py::value_error("pixels: entry " + std::to_string(k) + " is " +
                                  std::to_string(v) + ", not a pixel index");
        pixels[k] = static_cast<std::uint32_t>(v);
    }
    return pixels;
}

py::array_t<long long> FromPixels(std::span<const std::uint32_t> pixels) {
    py::array_t<long long> a(static_cast<py::ssize_t>(pixels.size()));
    std::copy(pixels.begin(), pixels.end(), a.mutable_data());
    return a;
}

LightSamples MakeSamples(const py::object& lsX, const py::object& d1, const py::object& d2,
                         const py::object& wsX, const py::object& lsRelevant,
                         const py::object& lsRelevantHull, const py::object& pixel) {
    LightSamples s;
    s.lsX = ToPoints(lsX, "ls_x");
    s.dXdx1 = ToPoints(d1, "dxdx1");
    s.dXdx2 = ToPoints(d2, "dxdx2");
    s.wsX = ToPoints(wsX, "ws_x");
    s.lsRelevant = ToPoints(lsRelevant, "ls_relevant");
    if (!lsRelevantHull.is_none()) s.lsRelevantHull = ToPoints(lsRelevantHull, "ls_relevant_hull");
    s.pixel = pixel.is_none() ? std::vector<std::uint32_t>(s.lsX.size(), 0) : ToPixels(pixel);
    const std::size_t n = s.lsX.size();
    if (s.dXdx1.size() != n || s.dXdx2.size() != n || s.wsX.size() != n || s.pixel.size() != n)
        throw py::value_error(
            "ls_x, dxdx1, dxdx2, ws_x, pixel: need one row per sample each, got " +
            std::to_string(n) + ", " + std::to_string(s.dXdx1.size()) + ", " +
            std::to_string(s.dXdx2.size()) + ", " + std::to_string(s.wsX.size()) + ", " +
            std::to_string(s.pixel.size()));
    s.boundaryPixels = n;
    return s;
}

void BindSamples(py::module_& m) {
    // lexel.Shade is a Python enum.IntEnum built from these (lexel/__init__.py): its members are
    // ints, so a numpy mask compares with them (mask == lexel.Shade.LIT) and stores them as uint8.
    py::dict shadeValues;
    shadeValues["EMPTY"] = static_cast<int>(Shade::kEmpty);
    shadeValues["LIT"] = static_cast<int>(Shade::kLit);
    shadeValues["SHADOWED"] = static_cast<int>(Shade::kShadowed);
    shadeValues["FACING_AWAY"] = static_cast<int>(Shade::kFacingAway);
    m.attr("_SHADE_VALUES") = shadeValues;
    m.attr("_SHADE_DOC") =
        "A readback pixel's shadow decision under one light's map (an IntEnum; a shadow mask "
        "holds its values as integers, uint8 say): EMPTY 0 (sees nothing), LIT 1, SHADOWED 2, "
        "FACING_AWAY 3 (its normal faces away from the light, n . l <= 0).";

    py::class_<LightSamples>(
        m, "LightSamples",
        "One light's optimization samples (report §2.3 step 3): the readback pixels at shadow "
        "boundaries with their light-space points and derivatives, and every visible point in "
        "light space. make_light_samples builds them; LightSamples(...) takes your own.")
        .def(py::init(&MakeSamples), py::kw_only(), py::arg("ls_x"), py::arg("dxdx1"),
             py::arg("dxdx2"), py::arg("ws_x"), py::arg("ls_relevant"),
             py::arg("ls_relevant_hull") = py::none(), py::arg("pixel") = py::none(),
             "Samples of your own: (N, 3) each of ls_x, dxdx1, dxdx2 (dX/dx1, dX/dx2 per readback "
             "pixel) and ws_x (their world points), (M, 3) ls_relevant (every visible point in "
             "light space, in the order of the context's relevant points), optionally the light-"
             "space hull vertices and (N,) readback pixels.")
        .def(
            "__len__", [](const LightSamples& s) { return s.lsX.size(); },
            "The number of boundary samples h sums over.")
        .def_property_readonly(
            "ls_x", [](const LightSamples& s) { return FromPoints(s.lsX); },
            "(N, 3): the samples in light space.")
        .def_property_readonly(
            "dxdx1", [](const LightSamples& s) { return FromPoints(s.dXdx1); },
            "(N, 3): dX/dx1 at each (light-space units per readback pixel).")
        .def_property_readonly(
            "dxdx2", [](const LightSamples& s) { return FromPoints(s.dXdx2); },
            "(N, 3): dX/dx2 at each.")
        .def_property_readonly(
            "pixel", [](const LightSamples& s) { return FromPixels(s.pixel); },
            "(N,) int64: the readback pixel of each, row * W + column.")
        .def_property_readonly(
            "ws_x", [](const LightSamples& s) { return FromPoints(s.wsX); },
            "(N, 3): the world point of each.")
        .def_property_readonly(
            "ls_relevant", [](const LightSamples& s) { return FromPoints(s.lsRelevant); },
            "(M, 3): every visible point in light space.")
        .def_property_readonly(
            "ls_relevant_hull", [](const LightSamples& s) { return FromPoints(s.lsRelevantHull); },
            "(K, 3): the readback's hull vertices in light space (the optimizer's cone).")
        .def_readonly("boundary_pixels", &LightSamples::boundaryPixels,
                      "Boundary pixels before the non-smooth ones were dropped.")
        .def_readonly("contact_samples", &LightSamples::contactSamples,
                      "How many of the samples, the last ones, are thin-shadow contacts (a "
                      "shadowed receiver beside a facing-away surface the light grazes) rather "
                      "than boundary pixels.");

    m.def(
        "boundary_pixels",
        [](const py::object& shades) {
            const py::array a = py::array::ensure(shades);
            if (!a || a.ndim() != 2) {
                PyErr_Clear();
                throw py::value_error("shades: expected a (H, W) array of lexel.Shade values");
            }
            const Resolution r{static_cast<int>(a.shape(1)), static_cast<int>(a.shape(0))};
            return FromPixels(BoundaryPixels(r, ToShades(shades, r)));
        },
        py::arg("shades"),
        "The boundary pixels of a (H, W) shadow mask, ascending, as row * W + column (int64): a "
        "LIT or SHADOWED pixel with an 8-neighbour that is SHADOWED or LIT the other way.");
    m.def(
        "make_light_samples",
        [](const Readback& readback, const LightSpace& lightSpace, const py::object& shades) {
            const std::vector<Shade> mask = ToShades(shades, readback.buffer.resolution);
            return MakeLightSamples(readback, lightSpace, mask);
        },
        py::arg("readback"), py::arg("light_space"), py::arg("shades"),
        "Boundary samples from the readback's shadow mask under a standard map: shades (H, W) of "
        "lexel.Shade values (uint8 or any integers), in the readback's order, from your shadow "
        "test of readback.ws_position against a map rendered through the standard map's "
        "clip_from_world.");
    m.def(
        "light_samples_at_pixels",
        [](const Readback& readback, const LightSpace& lightSpace, const py::object& pixels) {
            return LightSamplesAtPixels(readback, lightSpace, ToPixels(pixels));
        },
        py::arg("readback"), py::arg("light_space"), py::arg("pixels"),
        "The samples at boundary pixels found elsewhere (a GPU pass): (K,) ascending indices "
        "row * W + column inside the readback; non-smooth ones are dropped as "
        "make_light_samples does (the same samples, bit for bit, from the same pixels).");
}

}  // namespace

void BindReadback(py::module_& m) {
    BindConventions(m);
    BindDepthBuffers(m);
    BindReadbackClass(m);
    BindSamples(m);
}

}  // namespace lexel::python
