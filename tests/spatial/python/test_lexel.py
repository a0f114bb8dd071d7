"""Tests of lexel's Python module (spatial/python), run by CTest with the interpreter CMake found.

ReferenceTest runs the C++ core (python_reference, reference.cpp) on the embedding guide's toy scene and the
module on the same inputs, and compares every result bit for bit: the same code on the same
numbers gives the same doubles. ConventionsTest renders one floor in every depth convention and
checks that each readback finds the same world points. ArraysTest checks the numpy conventions
(row-major matrices, copies, any dtype and memory order), ErrorsTest the exceptions and their
one-line messages, DocumentationTest that help() has something to say about everything.

Environment (set by tests/spatial/python/CMakeLists.txt): PYTHONPATH holds the built package,
LEXEL_PYTHON_REFERENCE the reference program, LEXEL_PYTHON_WORK a scratch directory.
"""

import json
import math
import os
import pydoc
import subprocess
import unittest

import numpy as np

import lexel


def _number(v):
    """A number of reference.json (non-finite ones are written as strings)."""
    return float(v)  # float("inf"), float("nan") read the strings too


def _numbers(values):
    return np.array([_number(v) for v in values])


def _assert_matrix(test, matrix, reference, msg=""):
    """A LightMatrix equals reference.json's {p1, p2, p4}, to the last bit."""
    for row in ("p1", "p2", "p4"):
        np.testing.assert_array_equal(getattr(matrix, row), np.array(reference[row]),
                                      err_msg=f"{msg} {row}")


class _Reference:
    """The C++ core's results on the embedding guide's toy scene (python_reference), loaded once."""

    loaded = None

    @classmethod
    def get(cls):
        if cls.loaded is None:
            work = os.environ.get("LEXEL_PYTHON_WORK", "python-work")
            os.makedirs(work, exist_ok=True)
            program = os.environ["LEXEL_PYTHON_REFERENCE"]
            subprocess.run([program, work], check=True, stdout=subprocess.DEVNULL)
            with open(os.path.join(work, "reference.json")) as f:
                data = json.load(f)
            width, height = data["inputs"]["camera"]["resolution"]
            data["depth"] = np.fromfile(os.path.join(work, "depth.f32"),
                                        dtype=np.float32).reshape(height, width)
            low_width, low_height = data["low_res"]["resolution"]

            def raw(name, dtype, *shape):
                return np.fromfile(os.path.join(work, name), dtype=dtype).reshape(
                    low_height, low_width, *shape)

            data["low_depth"] = raw("low_depth.f32", np.float32)
            data["ws_position"] = raw("ws_position.f64", np.float64, 3)
            data["dwdx1"] = raw("dwdx1.f64", np.float64, 3)
            data["dwdx2"] = raw("dwdx2.f64", np.float64, 3)
            data["smooth"] = raw("smooth.u8", np.uint8).astype(bool)
            data["masks"] = [raw(f"mask_{l}.u8", np.uint8)
                             for l in range(len(data["inputs"]["lights"]))]
            cls.loaded = data
        return cls.loaded


class ReferenceTest(unittest.TestCase):
    """The module against the C++ core on the same inputs: every number equal."""

    @classmethod
    def setUpClass(cls):
        cls.ref = _Reference.get()
        inputs = cls.ref["inputs"]
        cls.convention = lexel.DepthConvention.vulkan(reversed=True)
        cls.low = lexel.downsample_depth(cls.ref["depth"], np.array(cls.ref["clip_from_world"]),
                                         cls.convention)
        cls.readback = lexel.make_readback(cls.low)
        cls.bounds = lexel.Bounds(*inputs["bounds"])
        cls.map = tuple(inputs["map"])
        cam = inputs["camera"]
        cls.camera = lexel.Camera(position=cam["position"], target=cam["target"],
                                  resolution=tuple(cam["resolution"]))

    def light(self, l):
        spec = self.ref["inputs"]["lights"][l]
        if spec["kind"] == "point":
            return lexel.Light.point(spec["vector"])
        return lexel.Light.directional(spec["vector"])

    def context(self, l, samples):
        light_space = lexel.LightSpace(self.light(l), self.bounds)
        return lexel.BaselineContext(light_space, self.camera, self.map, self.bounds,
                                     self.readback.ws_relevant,
                                     relevant_hull=self.readback.ws_relevant_hull,
                                     floor_plane=self.ref["inputs"]["floor_plane"],
                                     samples=samples)

    def samples(self, l):
        light_space = lexel.LightSpace(self.light(l), self.bounds)
        return light_space, lexel.make_light_samples(self.readback, light_space,
                                                     self.ref["masks"][l])

    def test_downsample_depth(self):
        low = self.ref["low_res"]
        self.assertEqual(self.low.step, low["step"])
        self.assertEqual(self.low.offset, tuple(low["offset"]))
        self.assertEqual(self.low.convention, self.convention)
        np.testing.assert_array_equal(self.low.clip_from_world, np.array(low["clip_from_world"]))
        np.testing.assert_array_equal(self.low.depth, self.ref["low_depth"])
        self.assertEqual(self.low.depth.dtype, np.float32)

    def test_readback(self):
        r = self.readback
        self.assertEqual(r.resolution, tuple(self.ref["low_res"]["resolution"]))
        covered = r.covered
        self.assertEqual(covered.shape, self.ref["low_depth"].shape)
        np.testing.assert_array_equal(r.ws_position[covered], self.ref["ws_position"][covered])
        np.testing.assert_array_equal(r.dwdx1, self.ref["dwdx1"])
        np.testing.assert_array_equal(r.dwdx2, self.ref["dwdx2"])
        np.testing.assert_array_equal(r.smooth, self.ref["smooth"])
        self.assertEqual(len(r.ws_relevant), self.ref["readback"]["relevant"])
        np.testing.assert_array_equal(r.ws_relevant, r.ws_position[covered])
        np.testing.assert_array_equal(r.ws_relevant_hull, np.array(self.ref["readback"]["hull"]))
        # The readback straight from the full buffer finds the same visible points' world
        # positions at the kept pixels (the small image's matrix is exact, not resampled).
        self.assertEqual(len(r.ws_relevant), 8316)

    def test_standard_map_depth_range_and_clip_matrices(self):
        for l, ref in enumerate(self.ref["lights"]):
            with self.subTest(light=l):
                light_space = lexel.LightSpace(self.light(l), self.bounds)
                standard = lexel.standard_light_matrix(self.readback, light_space, self.bounds,
                                                       self.map)
                _assert_matrix(self, standard, ref["standard"], "standard")
                near_far = lexel.light_depth_range(light_space, standard, self.map, self.bounds,
                                                   self.readback.ws_relevant)
                self.assertEqual(near_far, tuple(ref["depth_range"]))
                for clip_depth, key in ((lexel.ClipDepth.ZERO_TO_ONE, "clip_zero_to_one"),
                                        (lexel.ClipDepth.MINUS_ONE_TO_ONE,
                                         "clip_minus_one_to_one")):
                    np.testing.assert_array_equal(
                        lexel.clip_from_world(light_space, standard, self.map, near_far,
                                              clip_depth), np.array(ref[key]), err_msg=key)
                np.testing.assert_array_equal(lexel.map_from_world(light_space, standard),
                                              np.array(ref["map_from_world"]))
                np.testing.assert_array_equal(
                    lexel.initial_light_axis(light_space, self.bounds, self.readback.ws_relevant),
                    np.array(ref["initial_axis"]))

    def test_samples_and_energies(self):
        for l, ref in enumerate(self.ref["lights"]):
            with self.subTest(light=l):
                light_space, samples = self.samples(l)
                s = ref["samples"]
                self.assertEqual(len(samples), len(s["ls_x"]))
                self.assertGreater(len(samples), 10)
                np.testing.assert_array_equal(samples.ls_x, np.array(s["ls_x"]))
                np.testing.assert_array_equal(samples.dxdx1, np.array(s["dxdx1"]))
                np.testing.assert_array_equal(samples.dxdx2, np.array(s["dxdx2"]))
                np.testing.assert_array_equal(samples.pixel, np.array(s["pixel"]))
                self.assertEqual(samples.boundary_pixels, s["boundary_pixels"])
                # The GPU path: the same samples from the same boundary pixels.
                boundary = lexel.boundary_pixels(self.ref["masks"][l])
                again = lexel.light_samples_at_pixels(self.readback, light_space, boundary)
                np.testing.assert_array_equal(again.ls_x, samples.ls_x)

                standard = lexel.standard_light_matrix(self.readback, light_space, self.bounds,
                                                       self.map)
                self.assertEqual(lexel.energy(standard, samples), _number(ref["h_standard"]))
                np.testing.assert_array_equal(lexel.energy_gradient(standard, samples),
                                              np.array(ref["gradient"]))
                np.testing.assert_array_equal(
                    lexel.energy_gradient(standard, samples, method="jets"),
                    np.array(ref["gradient_jets"]))
                np.testing.assert_array_equal(
                    lexel.sample_badness(standard, samples, "largest_singular_value"),
                    _numbers(ref["largest_singular_value"]))
                # eq. 6 is the sum of its summands.
                self.assertAlmostEqual(
                    float(np.sum(lexel.sample_badness(standard, samples))),
                    lexel.energy(standard, samples), delta=1e-12 * lexel.energy(standard, samples))

    def _assert_result(self, result, ref, msg):
        _assert_matrix(self, result.matrix, ref["matrix"], msg)
        self.assertEqual(result.h, _number(ref["h"]), msg)
        self.assertEqual(result.h_after_iteration, list(_numbers(ref["h_after_iteration"])), msg)
        self.assertEqual(result.candidates_tried, ref["candidates_tried"], msg)
        self.assertEqual(result.candidates_rejected, ref["candidates_rejected"], msg)
        self.assertEqual(result.used_fallback, ref["used_fallback"], msg)

    def test_optimize_light_matrix(self):
        for l, ref in enumerate(self.ref["lights"]):
            with self.subTest(light=l):
                light_space, samples = self.samples(l)
                standard = lexel.standard_light_matrix(self.readback, light_space, self.bounds,
                                                       self.map)
                result = lexel.optimize_light_matrix(samples, standard.p4, self.map)
                self._assert_result(result, ref["optimize"], "optimize")
                self.assertLess(result.h, result.h_after_iteration[0])

    def test_baselines(self):
        for l, ref in enumerate(self.ref["lights"]):
            with self.subTest(light=l):
                _, samples = self.samples(l)
                context = self.context(l, samples)
                self.assertEqual(sorted(lexel.BASELINES), sorted(ref["baselines"]))
                for name, b in ref["baselines"].items():
                    matrix, diagnostics = lexel.baseline(name, context, return_diagnostics=True)
                    _assert_matrix(self, matrix, b["matrix"], name)
                    self.assertEqual(diagnostics["fallback"], b["fallback"], name)
                    self.assertEqual(lexel.energy(matrix, samples), _number(b["h"]), name)

    def test_methods_are_the_registry(self):
        methods = lexel.methods()
        self.assertEqual([(m["name"], m["family"]) for m in methods],
                         [(m["name"], m["family"]) for m in self.ref["methods"]])
        self.assertEqual(sorted(lexel.BASELINES),
                         sorted(m["name"] for m in methods
                                if m["family"] == "baseline" and m["default"]))
        fair = [m["name"] for m in methods if m["traits"]["fair_table"]]
        self.assertEqual(fair[0], "optimal")
        self.assertEqual(lexel.OPTIMAL_METHOD, fair[0])
        self.assertEqual([m["name"] for m in methods if m["family"] == "bound"],
                         [lexel.ORACLE_METHOD])
        for l, ref in enumerate(self.ref["lights"]):
            _, samples = self.samples(l)
            context = self.context(l, samples)
            for name, b in ref["baselines"].items():
                with self.subTest(light=l, method=name):
                    computed = lexel.compute(name, context)
                    _assert_matrix(self, computed["matrix"], b["matrix"], name)
                    self.assertEqual(computed["fallback"], b["fallback"], name)
                    self.assertEqual(computed["cascades"], [])
            count = self.ref["inputs"]["partition_count"]
            cascades = lexel.compute("pssm", context, count=count)["cascades"]
            same = lexel.partitioned_light_matrices("pssm", context, count=count)
            self.assertEqual([(c.z_near, c.z_far, c.map) for c in cascades],
                             [(c.z_near, c.z_far, c.map) for c in same])
            self.assertEqual(lexel.partitioned_energy(cascades, context),
                             lexel.partitioned_energy(same, context))
            with self.assertRaisesRegex(ValueError, r"^name: unknown 3D method 'nope'"):
                lexel.compute("nope", context)
            with self.assertRaisesRegex(ValueError, r"^name: rtw's map is not a light matrix"):
                lexel.compute("rtw", context)

    def test_optimal(self):
        for l, ref in enumerate(self.ref["lights"]):
            with self.subTest(light=l):
                _, samples = self.samples(l)
                context = self.context(l, samples)
                starts = lexel.standard_starts(context)
                self.assertEqual([n for n, _, _ in starts], ref["start_names"])
                # plane-optimal's search competes, its own map does not.
                self.assertEqual([c for _, _, c in starts],
                                 [n != "plane-optimal" for n in ref["start_names"]])
                for refine, key in ((False, "optimal"), (True, "optimal_refined")):
                    best = lexel.optimal(context, refine=refine)
                    self._assert_result(best.result, ref[key]["result"], key)
                    self.assertEqual(best.winner, ref[key]["winner"], key)
                    self.assertEqual(best.start_map_won, ref[key]["start_map_won"], key)
                    self.assertEqual(best.start_h, list(_numbers(ref[key]["start_h"])), key)
                    self.assertEqual(best.search_h, list(_numbers(ref[key]["search_h"])), key)
                    # `optimal` never loses to a competing start's map, on its own energy.
                    competing = [h for h, (_, _, c) in zip(best.start_h, starts) if c]
                    self.assertLessEqual(best.h, min(competing), key)
                # optimize_from_starts on the same starts, as triples, is `optimal` itself; as
                # pairs every map competes, so plane-optimal's may win and h can only fall.
                same = lexel.optimize_from_starts(samples, starts, self.map)
                self.assertEqual(same.h, lexel.optimal(context).h)
                self.assertEqual(same.winner, lexel.optimal(context).winner)
                pairs = lexel.optimize_from_starts(samples, [(n, m) for n, m, _ in starts],
                                                   self.map)
                self.assertLessEqual(pairs.h, same.h)
                self.assertEqual(pairs.h, min(same.h, min(pairs.start_h)))
                with self.assertRaisesRegex(ValueError, r"^starts: each is \(name, matrix\)"):
                    lexel.optimize_from_starts(samples, [("a", starts[0][1], True, 1)], self.map)

    def test_partitions(self):
        count = self.ref["inputs"]["partition_count"]
        for l, ref in enumerate(self.ref["lights"]):
            _, samples = self.samples(l)
            context = self.context(l, samples)
            self.assertEqual(sorted(lexel.PARTITION_SCHEMES), sorted(ref["partitions"]))
            for name, p in ref["partitions"].items():
                with self.subTest(light=l, scheme=name):
                    cascades = lexel.partitioned_light_matrices(name, context, count=count,
                                                                allocation="lagrange")
                    self.assertEqual(len(cascades), len(p["cascades"]))
                    for c, cref in zip(cascades, p["cascades"]):
                        _assert_matrix(self, c.matrix, cref["matrix"], name)
                        self.assertEqual(c.map, tuple(cref["map"]))
                        self.assertEqual(c.z_near, _number(cref["z_near"]))
                        self.assertEqual(c.z_far, _number(cref["z_far"]))
                        self.assertEqual(c.visible_points, cref["visible_points"])
                    self.assertEqual(lexel.partitioned_energy(cascades, context),
                                     _number(p["h"]))
                    served = sum(len(lexel.samples_of_cascade(cascades, k, context))
                                 for k in range(len(cascades)))
                    self.assertLessEqual(served, len(samples))
            # On h (sdsm-optimal-h) each cascade starts from SDSM's box: h at most SDSM's.
            on_h = {name: lexel.partitioned_light_matrices(name, context, count=count, energy="h")
                    for name in ("sdsm", "sdsm-optimal")}
            self.assertLessEqual(lexel.partitioned_energy(on_h["sdsm-optimal"], context),
                                 lexel.partitioned_energy(on_h["sdsm"], context), l)
            on_e = lexel.partitioned_light_matrices("sdsm-optimal", context, count=count)
            self.assertTrue(any(not np.array_equal(a.matrix.p4, b.matrix.p4)
                                for a, b in zip(on_e, on_h["sdsm-optimal"])), l)  # energy used
            with self.assertRaisesRegex(ValueError, r"^energy: unknown energy 'L2'"):
                lexel.partitioned_light_matrices("sdsm", context, energy="L2")


# ---------------------------------------------------------------------------------------------
# One floor in every depth convention

FLOOR_CAMERA = dict(position=(0.0, 3.0, 8.0), target=(0.0, 0.0, -4.0), resolution=(120, 80),
                    near=0.5, far=100.0)


def _floor_points(camera):
    """The world point each pixel of a (H, W) image (row 0 at NDC y = +1) sees on the floor
    y = 0, |x|, |z| <= 20; NaN where the sky is seen."""
    width, height = camera.resolution
    rows, columns = np.mgrid[0:height, 0:width]
    ndc = np.stack([2.0 * (columns + 0.5) / width - 1.0, 1.0 - 2.0 * (rows + 0.5) / height,
                    np.ones((height, width)), np.ones((height, width))], axis=-1)
    far = ndc @ np.linalg.inv(camera.clip_from_world()).T
    far = far[..., :3] / far[..., 3:]
    direction = far - camera.position
    with np.errstate(divide="ignore", invalid="ignore"):
        t = -camera.position[1] / direction[..., 1]
    p = camera.position + t[..., None] * direction
    seen = (t > 0) & (np.abs(p[..., 0]) <= 20.0) & (np.abs(p[..., 2]) <= 20.0)
    p[~seen] = np.nan
    return p


def _convention_projection(gl_clip_from_world, convention, y_down):
    """OpenGL's clip_from_world re-expressed in `convention`'s clip depth and direction, with
    NDC y pointing down when y_down (Vulkan)."""
    m = gl_clip_from_world.copy()
    zero_to_one = convention.clip_depth == lexel.ClipDepth.ZERO_TO_ONE
    reversed_z = convention.direction == lexel.DepthDirection.REVERSED
    if zero_to_one:
        m[2] = 0.5 * m[2] + 0.5 * m[3]            # z_ndc in [0, 1]
        if reversed_z:
            m[2] = m[3] - m[2]                    # 1 at near, 0 at far
    elif reversed_z:
        m[2] = -m[2]                              # 1 at near, -1 at far
    if y_down:
        m[1] = -m[1]
    return m


def _depth_buffer(points, clip, convention, y_down):
    """What a renderer with `convention` stores for the world points (row 0 at NDC y = +1 in
    `points`), in its own row order."""
    h = np.concatenate([points, np.ones(points.shape[:2] + (1,))], axis=-1) @ clip.T
    z_ndc = h[..., 2] / h[..., 3]
    stored = z_ndc if convention.clip_depth == lexel.ClipDepth.ZERO_TO_ONE else (z_ndc + 1) / 2
    cleared = 0.0 if convention.direction == lexel.DepthDirection.REVERSED else 1.0
    depth = np.where(np.isnan(points[..., 0]), cleared, stored).astype(np.float32)
    # Row 0 of the array lies at NDC y = -1: with y pointing down that is the top row.
    bottom_first = convention.first_row == lexel.FirstRow.AT_NDC_Y_MINUS_ONE
    return np.flipud(depth).copy() if bottom_first != y_down else depth


class ConventionsTest(unittest.TestCase):
    """Every depth convention of depth_buffer.h finds the floor where it is."""

    @classmethod
    def setUpClass(cls):
        cls.camera = lexel.Camera(**FLOOR_CAMERA)
        cls.points = _floor_points(cls.camera)
        cls.seen = ~np.isnan(cls.points[..., 0])

    def conventions(self):
        for clip_depth in lexel.ClipDepth.__members__.values():
            for direction in lexel.DepthDirection.__members__.values():
                for first_row in lexel.FirstRow.__members__.values():
                    yield lexel.DepthConvention(clip_depth=clip_depth, direction=direction,
                                                first_row=first_row), False
        for reversed_z in (False, True):
            yield lexel.DepthConvention.vulkan(reversed=reversed_z), True  # its projection flips y

    def readback_points(self, convention, y_down):
        clip = _convention_projection(self.camera.clip_from_world(), convention, y_down)
        depth = _depth_buffer(self.points, clip, convention, y_down)
        readback = lexel.make_readback(depth, clip, convention)
        ws = readback.ws_position
        covered = readback.covered
        bottom_first = convention.first_row == lexel.FirstRow.AT_NDC_Y_MINUS_ONE
        if bottom_first != y_down:  # back to row 0 at the top
            ws, covered = np.flipud(ws), np.flipud(covered)
        return ws, covered

    def test_every_convention_finds_the_floor(self):
        self.assertGreater(np.count_nonzero(self.seen), 0.3 * self.seen.size)
        self.assertGreater(np.count_nonzero(~self.seen), 0.05 * self.seen.size)
        for convention, y_down in self.conventions():
            with self.subTest(convention=repr(convention), y_down=y_down):
                ws, covered = self.readback_points(convention, y_down)
                np.testing.assert_array_equal(covered, self.seen)
                # float32 depth, 0.5 to 100 deep: relative world error 1.5e-6 standard (it grows
                # with z / near), 4.5e-8 reversed (measured); a wrong row order or clip depth
                # puts points metres away.
                reversed_z = convention.direction == lexel.DepthDirection.REVERSED
                bound = 2e-7 if reversed_z else 1e-5
                distance = np.linalg.norm(self.points[self.seen] - self.camera.position, axis=1)
                error = np.linalg.norm(ws[covered] - self.points[self.seen], axis=1)
                self.assertLess(float(np.max(error / distance)), bound)

    def test_wrong_direction_is_refused_naming_the_right_one(self):
        convention = lexel.DepthConvention.direct3d(reversed=True)
        clip = _convention_projection(self.camera.clip_from_world(), convention, False)
        depth = _depth_buffer(self.points, clip, convention, False)
        with self.assertRaisesRegex(ValueError, r"use DepthDirection\.REVERSED"):
            lexel.make_readback(depth, clip, lexel.DepthConvention.direct3d())

    def test_presets(self):
        c = lexel.DepthConvention.opengl()
        self.assertEqual((c.clip_depth, c.direction, c.first_row),
                         (lexel.ClipDepth.MINUS_ONE_TO_ONE, lexel.DepthDirection.STANDARD,
                          lexel.FirstRow.AT_NDC_Y_MINUS_ONE))
        c = lexel.DepthConvention.direct3d(reversed=True)
        self.assertEqual((c.clip_depth, c.direction, c.first_row),
                         (lexel.ClipDepth.ZERO_TO_ONE, lexel.DepthDirection.REVERSED,
                          lexel.FirstRow.AT_NDC_Y_PLUS_ONE))
        self.assertEqual(lexel.DepthConvention(), lexel.DepthConvention(
            clip_depth=lexel.ClipDepth.MINUS_ONE_TO_ONE))

    def test_downsample_depth_keeps_every_step_th_pixel(self):
        convention = lexel.DepthConvention.direct3d(reversed=True)
        clip = _convention_projection(self.camera.clip_from_world(), convention, False)
        depth = _depth_buffer(self.points, clip, convention, False)
        low = lexel.downsample_depth(depth, clip, convention, max_side=40)
        self.assertEqual(low.step, 3)  # ceil(120 / 40)
        x, y = low.offset
        # The sampled grid centred: (120 - (3 * 39 + 1)) / 2 and (80 - (3 * 25 + 1)) / 2.
        self.assertEqual((x, y), (1, 2))
        np.testing.assert_array_equal(low.depth, depth[2::3, 1::3])
        self.assertEqual(low.depth.shape, (26, 40))
        # Its matrix puts the kept pixels at the small image's pixel centres: the readback of
        # the small image sees the full one's points there.
        small = lexel.make_readback(low)
        full = lexel.make_readback(depth, clip, convention)
        kept = full.ws_position[2::3, 1::3]
        covered = small.covered
        np.testing.assert_allclose(small.ws_position[covered], kept[covered], rtol=0, atol=1e-9)

    def test_screen_from_world_is_the_cameras_for_lexels_convention(self):
        np.testing.assert_allclose(
            lexel.screen_from_world(self.camera.resolution, self.camera.clip_from_world()),
            self.camera.screen_from_world(), rtol=1e-15, atol=1e-12)


# ---------------------------------------------------------------------------------------------
# numpy conventions

class StatisticsTest(unittest.TestCase):
    """The scripts' intervals and noise rule are lexel's own (solvers/statistics.h)."""

    def test_student_t_and_intervals(self):
        self.assertAlmostEqual(lexel.student_t95(1), 12.7062, places=4)
        self.assertAlmostEqual(lexel.student_t95(99), 1.9842, places=4)
        mean, half = lexel.mean_interval95([1, 2, 3, 4])
        self.assertEqual(mean, 2.5)
        self.assertAlmostEqual(half, lexel.student_t95(3) * math.sqrt(5 / 3 / 4), places=12)
        self.assertTrue(math.isnan(lexel.mean_interval95([7.0])[1]))
        self.assertEqual(lexel.paired_difference95([10, 12, 9], [11, 15, 9])[0], -4 / 3)
        with self.assertRaisesRegex(ValueError, r"^theirs: has 1 values, ours has 3"):
            lexel.paired_difference95([10, 12, 9], [1])
        with self.assertRaisesRegex(ValueError, r"^dof: must be at least 1"):
            lexel.student_t95(0)

    def test_noise_rule(self):
        # Errors 3 and 4: the difference's is 5, the threshold 1.96 * 5 = 9.8.
        self.assertEqual(lexel.NORMAL95, 1.96)
        self.assertTrue(lexel.differ_beyond_noise(110, 3, 100, 4))
        self.assertFalse(lexel.differ_beyond_noise(109, 3, 100, 4))
        self.assertFalse(lexel.differ_beyond_noise(math.nan, 3, 100, 4))


class ArraysTest(unittest.TestCase):
    """Matrices are row-major (m @ [x, y, z, 1]); inputs of any dtype and order; outputs copies."""

    @classmethod
    def setUpClass(cls):
        ref = _Reference.get()
        cls.camera = lexel.Camera(**FLOOR_CAMERA)
        cls.bounds = lexel.Bounds(*ref["inputs"]["bounds"])
        cls.light_space = lexel.LightSpace(lexel.Light.point((10.0, 15.0, 6.0)), cls.bounds)
        cls.matrix = lexel.LightMatrix(*(np.array(ref["lights"][0]["standard"][k])
                                         for k in ("p1", "p2", "p4")))
        cls.points = np.array([[0.0, 0.0, 0.0], [3.0, 0.0, -2.0], [1.0, 2.0, 1.0],
                               [-5.0, 0.0, 4.0]])

    def test_matrices_are_row_major(self):
        view = self.camera.view_from_world()
        # glm::lookAt: the camera position goes to the origin, the target onto -z.
        np.testing.assert_allclose(view @ np.r_[self.camera.position, 1.0], [0, 0, 0, 1],
                                   atol=1e-12)
        target = view @ np.r_[self.camera.target, 1.0]
        self.assertAlmostEqual(target[2], -np.linalg.norm(self.camera.target
                                                          - self.camera.position), places=12)
        np.testing.assert_array_equal(self.camera.clip_from_world(),
                                      self.camera.clip_from_view() @ view)

    def test_map_from_world_is_the_light_matrix_in_world_form(self):
        m = lexel.map_from_world(self.light_space, self.matrix)
        h = np.c_[self.points, np.ones(len(self.points))] @ m.T
        np.testing.assert_array_equal(h[:, 2], 0.0)
        u = h[:, :2] / h[:, 3:]
        np.testing.assert_allclose(u, self.matrix.map(self.light_space.to_light(self.points)),
                                   rtol=1e-12)
        # And back: the rows give the same light matrix.
        again = lexel.from_screen_rows(self.light_space, m, self.bounds.center())
        for row in ("p1", "p2", "p4"):
            np.testing.assert_allclose(getattr(again, row), getattr(self.matrix, row),
                                       rtol=1e-12, atol=1e-12)

    def test_fit_to_one_point_is_finite(self):
        # One point, or several that coincide, have no extent: the fit gets a sliver of 1e-9 of
        # the point's distance from the plane's origin instead (before: p1, p2 of NaN and -inf,
        # and a NaN clip matrix). The point maps to the map's centre (to rounding: the rows are
        # about 1e11 texels a plane unit).
        p4 = self.matrix.p4
        ls = self.light_space.to_light(self.points[:1])
        for points in (ls, np.repeat(ls, 3, axis=0)):
            fit = lexel.fit_map_to_points(p4, points, (512, 512))
            for row in ("p1", "p2", "p4"):
                self.assertTrue(np.all(np.isfinite(getattr(fit, row))), row)
            np.testing.assert_allclose(fit.map(points), [[256.0, 256.0]] * len(points),
                                       atol=1e-3)
            clip = lexel.clip_from_world(self.light_space, fit, (512, 512), (1.0, 50.0))
            self.assertTrue(np.all(np.isfinite(clip)))

    def test_clip_depth_conventions(self):
        near_far = (5.0, 40.0)
        zo = lexel.clip_from_world(self.light_space, self.matrix, (512, 512), near_far)
        mo = lexel.clip_from_world(self.light_space, self.matrix, (512, 512), near_far,
                                   lexel.ClipDepth.MINUS_ONE_TO_ONE)
        np.testing.assert_array_equal(zo[[0, 1, 3]], mo[[0, 1, 3]])
        np.testing.assert_allclose(mo[2], 2.0 * zo[2] - zo[3], rtol=1e-12, atol=1e-12)
        # Texels: x_ndc = 2 u1 / W - 1.
        h = np.c_[self.points, np.ones(len(self.points))] @ zo.T
        u = self.matrix.map(self.light_space.to_light(self.points))
        np.testing.assert_allclose((h[:, :2] / h[:, 3:] + 1.0) * 256.0, u, rtol=1e-12)
        # Depth: a point light's p4 . X at near lands on 0, at far on 1.
        q = lexel.clip_depth_quantity(self.light_space, self.matrix, self.points)
        z = h[:, 2] / h[:, 3]
        np.testing.assert_allclose(z, (1.0 / near_far[0] - 1.0 / q)
                                   / (1.0 / near_far[0] - 1.0 / near_far[1]), rtol=1e-9)

    def test_inputs_of_any_dtype_and_order(self):
        clip = self.camera.clip_from_world()
        points = _floor_points(self.camera)
        depth = _depth_buffer(points, clip, lexel.DepthConvention(), False)
        a = lexel.make_readback(depth, clip)
        b = lexel.make_readback(np.asfortranarray(depth.astype(np.float64)),
                                np.asfortranarray(clip).tolist())
        np.testing.assert_array_equal(a.ws_position, b.ws_position)
        c = lexel.make_readback(depth[::-1][::-1], clip.T.copy().T)  # views, strides
        np.testing.assert_array_equal(a.ws_position, c.ws_position)
        self.assertEqual(a.ws_position.shape, depth.shape + (3,))
        self.assertEqual(a.covered.dtype, np.bool_)
        np.testing.assert_array_equal(self.matrix.map(self.light_space.to_light(
            self.points.astype(np.float32))), self.matrix.map(self.light_space.to_light(
                self.points.astype(np.float32).astype(np.float64))))

    def test_outputs_are_copies(self):
        p1 = self.matrix.p1
        p1[0] = 1e9
        self.assertNotEqual(self.matrix.p1[0], 1e9)
        lo = self.bounds.lo
        lo[:] = 0.0
        self.assertEqual(self.bounds.lo[0], -20.0)

    def test_light_matrix_map_and_unmap(self):
        ls = self.light_space.to_light(self.points)
        u = self.matrix.map(ls)
        back = self.matrix.unmap(u)
        np.testing.assert_allclose(back, ls / (ls @ self.matrix.p4)[:, None], rtol=1e-12)
        np.testing.assert_array_equal(self.matrix.rows(),
                                      np.array([self.matrix.p1, self.matrix.p2, self.matrix.p4]))
        shifted = self.matrix.then_affine([[1, 0, 5], [0, 2, 0], [0, 0, 1]])
        np.testing.assert_allclose(shifted.map(ls), u * [1, 2] + [5, 0], rtol=1e-12)

    def test_shade_is_an_int_enum(self):
        mask = np.array([[0, 1], [2, 3]], dtype=np.uint8)
        np.testing.assert_array_equal(mask == lexel.Shade.SHADOWED, [[False, False],
                                                                     [True, False]])
        self.assertEqual([int(s) for s in lexel.Shade], [0, 1, 2, 3])
        self.assertEqual(lexel.Shade(3), lexel.Shade.FACING_AWAY)
        # 8-neighbours of a SHADOWED pixel that are LIT, and it, are boundary pixels.
        shades = np.full((5, 5), lexel.Shade.LIT, dtype=np.uint8)
        shades[2, 2] = lexel.Shade.SHADOWED
        np.testing.assert_array_equal(lexel.boundary_pixels(shades),
                                      [6, 7, 8, 11, 12, 13, 16, 17, 18])

    def test_bounds_and_camera(self):
        b = lexel.Bounds.around([[1, 2, 3], [-1, 5, 0]])
        np.testing.assert_array_equal(b.lo, [-1, 2, 0])
        np.testing.assert_array_equal(b.hi, [1, 5, 3])
        self.assertEqual(b.radius(), math.sqrt(4 + 9 + 9) / 2)
        self.assertEqual(b.corners().shape, (8, 3))
        np.testing.assert_array_equal(b.corners()[7], b.hi)
        self.assertEqual(self.camera.aspect_ratio(), 1.5)
        self.assertEqual(self.camera.frustum_corners().shape, (8, 3))


# ---------------------------------------------------------------------------------------------
# Errors

class ErrorsTest(unittest.TestCase):
    """Bad input raises ValueError/TypeError naming the argument; the algorithm's refusals
    lexel.DomainError (a ValueError) with lexel's one-line reason."""

    def test_shapes_and_values_name_the_argument(self):
        depth = np.ones((4, 4), dtype=np.float32)
        with self.assertRaisesRegex(ValueError,
                                    r"^clip_from_world: expected a \(4, 4\) matrix, got shape "
                                    r"\(3, 3\)$"):
            lexel.make_readback(depth, np.eye(3))
        bad = np.eye(4)
        bad[1, 2] = np.nan
        with self.assertRaisesRegex(ValueError, r"^clip_from_world: entry \[1, 2\] is nan"):
            lexel.make_readback(depth, bad)
        with self.assertRaisesRegex(ValueError, r"^depth: expected a \(H, W\) image"):
            lexel.make_readback(np.ones(4), np.eye(4))
        with self.assertRaisesRegex(TypeError, r"^depth: expected a \(H, W\) array, got None"):
            lexel.make_readback(None, np.eye(4))
        with self.assertRaisesRegex(ValueError, r"^points: expected \(N, 3\) points"):
            lexel.Bounds.around([1.0, 2.0, 3.0])
        with self.assertRaisesRegex(TypeError, r"^resolution: expected \(width, height\) as two "
                                               r"integers"):
            lexel.Camera(resolution=(512.0, 512))
        with self.assertRaisesRegex(ValueError, r"^fov_y_deg: must be in \(0, 180\)"):
            lexel.Camera(fov_y_deg=180)
        with self.assertRaisesRegex(ValueError, r"^lo, hi: lo must not exceed hi"):
            lexel.Bounds((1, 0, 0), (0, 1, 1))
        with self.assertRaisesRegex(ValueError, r"^max_side: must be at least 1"):
            lexel.downsample_depth(depth, np.eye(4), max_side=0)

    def test_singular_matrix(self):
        with self.assertRaisesRegex(ValueError, r"^depth buffer: the screen-from-world matrix is "
                                                r"singular$"):
            lexel.make_readback(np.ones((4, 4), dtype=np.float32), np.zeros((4, 4)))

    def test_domain_error(self):
        bounds = lexel.Bounds((-1, 0, -1), (1, 2, 1))
        with self.assertRaises(lexel.DomainError) as caught:
            lexel.LightSpace(lexel.Light.point((0.0, 1.0, 0.0)), bounds)
        error = caught.exception
        self.assertIsInstance(error, ValueError)
        self.assertEqual(str(error), "point light at (0.000000, 1.000000, 0.000000) is inside "
                                     "the geometry's bounds; no light matrix can see all of it")
        self.assertEqual(error.subject, "light")
        self.assertEqual(error.index, (-1, -1))
        self.assertEqual(type(error).__module__, "lexel")
        self.assertTrue(issubclass(lexel.InputError, ValueError))

    def test_unknown_names_list_the_known_ones(self):
        ref = _Reference.get()
        camera = lexel.Camera(**FLOOR_CAMERA)
        bounds = lexel.Bounds(*ref["inputs"]["bounds"])
        light_space = lexel.LightSpace(lexel.Light.directional((0.0, -1.0, -0.2)), bounds)
        context = lexel.BaselineContext(light_space, camera, (256, 256), bounds,
                                        [[0.0, 0.0, 0.0], [1.0, 0.0, 1.0]])
        with self.assertRaisesRegex(ValueError, r"^name: unknown baseline 'tsm' \(lexel has "
                                                r"'focused-tight', 'lispsm-tight', .* or 'psm'\)$"):
            lexel.baseline("tsm", context)
        with self.assertRaisesRegex(ValueError, r"^context: optimal needs the light's samples"):
            lexel.optimal(context)
        matrix = lexel.baseline("normal", context)
        samples = lexel.LightSamples(ls_x=np.zeros((0, 3)), dxdx1=np.zeros((0, 3)),
                                     dxdx2=np.zeros((0, 3)), ws_x=np.zeros((0, 3)),
                                     ls_relevant=light_space.to_light(context.relevant))
        self.assertEqual(lexel.energy(matrix, samples), 0.0)
        with self.assertRaisesRegex(ValueError, r"^energy: unknown energy 'l9' \(lexel has 'h'"):
            lexel.energy(matrix, samples, "l9")
        with self.assertRaisesRegex(ValueError, r"^iterations: must be in \[0, 1000\]"):
            lexel.optimize_light_matrix(samples, (0, 0, 1), (256, 256), iterations=-1)
        with self.assertRaisesRegex(ValueError, r"^ls_x, dxdx1, dxdx2, ws_x, pixel: need one "
                                                r"row per sample each"):
            lexel.LightSamples(ls_x=np.zeros((2, 3)), dxdx1=np.zeros((1, 3)),
                               dxdx2=np.zeros((2, 3)), ws_x=np.zeros((2, 3)),
                               ls_relevant=np.zeros((1, 3)))
        with self.assertRaisesRegex(ValueError, r"^shades: entry \[0, 1\] is 7, not a "
                                                r"lexel.Shade"):
            lexel.boundary_pixels(np.array([[1, 7]], dtype=np.uint8))


# ---------------------------------------------------------------------------------------------
# Documentation

class DocumentationTest(unittest.TestCase):
    """help() has something to say about every name the module exports, and their members."""

    def test_every_public_name_has_a_docstring(self):
        missing = []
        for name in lexel.__all__:
            obj = getattr(lexel, name)
            if isinstance(obj, (dict, str)):
                continue  # BASELINES, ENERGIES, PARTITION_SCHEMES: their values describe
            if not (obj.__doc__ or "").strip():
                missing.append(name)
            if isinstance(obj, type):
                for member, value in vars(obj).items():
                    if member.startswith("_") or isinstance(value, obj):
                        continue
                    if hasattr(obj, "__members__") and member in ("name", "value"):
                        continue  # pybind11's own enum properties
                    if not (getattr(value, "__doc__", None) or "").strip():
                        missing.append(f"{name}.{member}")
        self.assertEqual(missing, [])

    def test_help_renders(self):
        text = pydoc.render_doc(lexel, renderer=pydoc.plaintext)
        for name in ("optimal", "make_readback", "DomainError", "Shade", "clip_from_world"):
            self.assertIn(name, text)
        self.assertIn("Algorithm 1", pydoc.render_doc(lexel.optimize_light_matrix,
                                                      renderer=pydoc.plaintext))
        self.assertRegex(lexel.__version__, r"^\d+\.\d+\.\d+$")

    def test_tables_describe_every_entry(self):
        for table in (lexel.BASELINES, lexel.ENERGIES, lexel.PARTITION_SCHEMES):
            for name, description in table.items():
                self.assertGreater(len(description), 10, name)
        self.assertIn("h", lexel.ENERGIES)


if __name__ == "__main__":
    unittest.main()
