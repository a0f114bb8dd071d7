#!/usr/bin/env python3
"""lexel from Python: Algorithm 1 (Chong & Gortler, report §2.3) on a renderer's own buffers.

The embedding guide's toy renderer (tests/install/consumer/main.cpp) in numpy: a floor and a box
traced exactly, a 1280x720 reversed-Z camera pass with Vulkan's conventions (clip depth [0, 1], NDC y
down, an infinite far plane), and per point light a real 512x512 shadow map rendered through the
4x4 lexel gives it, with the renderer's own shadow test. Per light it prints the boundary samples
and h (eq. 6) of the standard map and of the optimized one, then h of a few baselines and of
`optimal` (Algorithm 1 from every baseline's start). Exits 0 when its checks hold: the map-based
mask agrees with exact shadow rays on 99% of the readback, h does not grow, every visible point of
the readback lands in the optimized map at a depth in [0, 1], and `optimal`'s h is at most that of
every baseline whose map competes in it.

Run it after lexel's set-up:  python3 spatial/python/examples/optimize_shadows.py
"""

import sys

import numpy as np

import lexel

BOX_LO = np.array([-1.0, 0.0, -1.0])
BOX_HI = np.array([1.0, 2.0, 1.0])
FLOOR_HALF = 20.0
MAP = (512, 512)


def trace(origin, direction, t_min, t_max):
    """The nearest hit parameter t in (t_min, t_max) of origin + t direction with the floor
    (y = 0, |x|, |z| <= 20) or the box, per ray ((N, 3) arrays); inf where nothing is hit."""
    origin = np.broadcast_to(origin, direction.shape)
    t_max = np.broadcast_to(np.asarray(t_max, dtype=float), direction.shape[:1]).copy()
    hit = np.full(direction.shape[0], np.inf)
    with np.errstate(divide="ignore", invalid="ignore"):
        t = -origin[:, 1] / direction[:, 1]
        p = origin + t[:, None] * direction
        floor = ((t > t_min) & (t < t_max) & (np.abs(p[:, 0]) <= FLOOR_HALF)
                 & (np.abs(p[:, 2]) <= FLOOR_HALF))
        hit[floor] = t[floor]
        t_max[floor] = t[floor]
        ta = (BOX_LO - origin) / direction
        tb = (BOX_HI - origin) / direction
    t0 = np.maximum(np.max(np.minimum(ta, tb), axis=1), t_min)
    t1 = np.minimum(np.min(np.maximum(ta, tb), axis=1), t_max)
    box = (np.max(np.minimum(ta, tb), axis=1) > t_min) & (t0 <= t1)
    hit[box] = t0[box]
    return hit


def normals_at(points):
    """The surface normal at visible points (the renderer knows its G-buffer's), (N, 3)."""
    eps = 1e-4
    normals = np.tile([0.0, 1.0, 0.0], (len(points), 1))
    inside = np.all((BOX_LO - eps <= points) & (points <= BOX_HI + eps), axis=1)
    done = np.zeros(len(points), dtype=bool)
    for k in range(3):
        at_hi = np.abs(points[:, k] - BOX_HI[k]) < eps
        face = inside & ~done & (at_hi | (np.abs(points[:, k] - BOX_LO[k]) < eps))
        if k == 1:
            face &= points[:, 1] >= eps  # the box's bottom face lies on the floor
        normals[face] = 0.0
        normals[face, k] = np.where(at_hi[face], 1.0, -1.0)
        done |= face
    return normals


def unproject(world_from_clip, ndc):
    """World points of (N, 3) NDC points."""
    h = np.c_[ndc, np.ones(len(ndc))] @ world_from_clip.T
    return h[:, :3] / h[:, 3:]


def texel_rays(clip, tx, ty):
    """The ends (NDC z = 0 and 1) of the rays through texel centres (tx, ty) of a map drawn with
    `clip`."""
    x = 2.0 * (tx + 0.5) / MAP[0] - 1.0
    y = 2.0 * (ty + 0.5) / MAP[1] - 1.0
    world_from_clip = np.linalg.inv(clip)
    a = unproject(world_from_clip, np.c_[x, y, np.zeros_like(x)])
    b = unproject(world_from_clip, np.c_[x, y, np.ones_like(x)])
    return a, b


def render_shadow_map(clip):
    """A shadow map drawn through `clip` ([0, 1] depth), one ray per texel centre: NDC z of the
    nearest surface, inf where nothing lies in the depth range; row 0 at NDC y = -1."""
    ty, tx = np.mgrid[0:MAP[1], 0:MAP[0]]
    a, b = texel_rays(clip, tx.ravel(), ty.ravel())
    t = trace(a, b - a, 0.0, 1.0)
    depth = np.full(len(t), np.inf, dtype=np.float32)
    hit = np.isfinite(t)
    p = a[hit] + t[hit, None] * (b[hit] - a[hit])
    h = np.c_[p, np.ones(len(p))] @ clip.T
    depth[hit] = (h[:, 2] / h[:, 3]).astype(np.float32)
    return depth.reshape(MAP[1], MAP[0])


def shade_readback(readback, clip, light_position):
    """The renderer's shadow test at the readback's points, (H, W) of lexel.Shade: the
    receiver's plane depth on the texel centre's ray against the stored depth (receiver-plane
    depth bias), less 1e-6."""
    shades = np.full(readback.covered.shape, lexel.Shade.EMPTY, dtype=np.uint8)
    covered = readback.covered
    ws = readback.ws_position[covered]
    n = normals_at(ws)
    facing = np.einsum("ij,ij->i", n, light_position - ws) > 0.0
    decision = np.where(facing, int(lexel.Shade.LIT), int(lexel.Shade.FACING_AWAY)).astype(np.uint8)
    h = np.c_[ws, np.ones(len(ws))] @ clip.T
    tx = np.floor((h[:, 0] / h[:, 3] + 1.0) * 0.5 * MAP[0]).astype(np.int64)
    ty = np.floor((h[:, 1] / h[:, 3] + 1.0) * 0.5 * MAP[1]).astype(np.int64)
    test = facing & (h[:, 3] > 0) & (tx >= 0) & (ty >= 0) & (tx < MAP[0]) & (ty < MAP[1])
    shadow_map = render_shadow_map(clip)
    a, b = texel_rays(clip, tx[test], ty[test])
    nt, wt = n[test], ws[test]
    s = np.einsum("ij,ij->i", nt, wt - a) / np.einsum("ij,ij->i", nt, b - a)
    on_plane = np.c_[a + s[:, None] * (b - a), np.ones(len(a))] @ clip.T
    stored = shadow_map[ty[test], tx[test]]
    shadowed = stored < on_plane[:, 2] / on_plane[:, 3] - 1e-6
    decision[np.flatnonzero(test)[shadowed]] = lexel.Shade.SHADOWED
    shades[covered] = decision
    return shades


def exactly_shadowed(points, light_position):
    """Exact shadow rays from the points: the mask a perfect shadow map would give."""
    return np.isfinite(trace(points, light_position - points, 1e-6, 1.0 - 1e-6))


def camera_pass(camera):
    """The 1280x720 camera pass: reversed-Z with an infinite far plane, NDC y down (Vulkan);
    the depth buffer (H, W) float32, cleared to 0, and its projection @ view."""
    projection = camera.clip_from_view()
    projection[1, 1] = -projection[1, 1]  # NDC y down
    projection[2, 2] = 0.0                # z_ndc = near / z_view
    projection[2, 3] = camera.near
    clip_from_world = projection @ camera.view_from_world()
    width, height = camera.resolution
    rows, columns = np.mgrid[0:height, 0:width]
    ndc = np.c_[2.0 * (columns.ravel() + 0.5) / width - 1.0,
                2.0 * (rows.ravel() + 0.5) / height - 1.0, np.ones(width * height)]
    near_points = unproject(np.linalg.inv(clip_from_world), ndc)  # row 0 at NDC y = -1
    t = trace(camera.position, near_points - camera.position, 0.0, 1e9)
    depth = np.zeros(width * height, dtype=np.float32)
    hit = np.isfinite(t)
    p = camera.position + t[hit, None] * (near_points[hit] - camera.position)
    h = np.c_[p, np.ones(len(p))] @ clip_from_world.T
    depth[hit] = (h[:, 2] / h[:, 3]).astype(np.float32)
    return depth.reshape(height, width), clip_from_world


def in_map(clip, points):
    """Which world points land in the map drawn with `clip` at a depth in [0, 1]."""
    h = np.c_[points, np.ones(len(points))] @ clip.T
    w = h[:, 3]
    return ((w > 0) & (np.abs(h[:, 0]) <= w) & (np.abs(h[:, 1]) <= w) & (h[:, 2] >= 0)
            & (h[:, 2] <= w))


def main():
    camera = lexel.Camera(position=(0.0, 1.7, 12.0), target=(0.0, 0.0, 0.0),
                          resolution=(1280, 720))
    depth, clip_from_world = camera_pass(camera)
    convention = lexel.DepthConvention.vulkan(reversed=True)
    scene_bounds = lexel.Bounds((-FLOOR_HALF, 0.0, -FLOOR_HALF), (FLOOR_HALF, 2.0, FLOOR_HALF))

    # Steps 1-2: the low-resolution readback (at most 180 pixels a side), shared by every light.
    readback = lexel.make_readback(lexel.downsample_depth(depth, clip_from_world, convention))
    width, height = readback.resolution
    print(f"readback {width}x{height}: {len(readback.ws_relevant)} visible points")

    ok = True
    for index, position in enumerate([(10.0, 15.0, 6.0), (-12.0, 9.0, -4.0)]):
        light = lexel.Light.point(position)
        light_space = lexel.LightSpace(light, scene_bounds)
        # Step 1's standard map, its depth range fitted to the casters and the visible points.
        standard = lexel.standard_light_matrix(readback, light_space, scene_bounds, MAP)
        near_far = lexel.light_depth_range(light_space, standard, MAP, scene_bounds,
                                           readback.ws_relevant)
        standard_clip = lexel.clip_from_world(light_space, standard, MAP, near_far,
                                              lexel.ClipDepth.ZERO_TO_ONE)
        # Step 3: the pixels at shadow boundaries under the renderer's own shadow test.
        shades = shade_readback(readback, standard_clip, light.position)
        tested = (shades == lexel.Shade.LIT) | (shades == lexel.Shade.SHADOWED)
        exact = exactly_shadowed(readback.ws_position[tested], light.position)
        agree = np.count_nonzero((shades[tested] == lexel.Shade.SHADOWED) == exact)
        samples = lexel.make_light_samples(readback, light_space, shades)
        # Steps 4-5: Algorithm 1 from the standard map's axis, and the 4x4 of its result.
        result = lexel.optimize_light_matrix(samples, standard.p4, MAP)
        near_far = lexel.light_depth_range(light_space, result.matrix, MAP, scene_bounds,
                                           readback.ws_relevant)
        clip = lexel.clip_from_world(light_space, result.matrix, MAP, near_far)
        outside = np.count_nonzero(~in_map(clip, readback.ws_relevant))
        print(f"light {index}: {len(samples)} boundary samples; h {result.h_after_iteration[0]:.6g}"
              f" -> {result.h:.6g}; the mask agrees with exact rays on {agree} of "
              f"{np.count_nonzero(tested)} pixels; {outside} visible points outside the map")

        # The same light's baselines and `optimal`, on the same samples.
        context = lexel.BaselineContext(light_space, camera, MAP, scene_bounds,
                                        readback.ws_relevant,
                                        relevant_hull=readback.ws_relevant_hull,
                                        floor_plane=(0.0, 1.0, 0.0, 0.0), samples=samples)
        rows = [(name, lexel.energy(lexel.baseline(name, context), samples))
                for name in ("focused-tight", "lispsm-tight", "psm-tight", "plane-optimal")]
        best = lexel.optimal(context)
        # The baselines whose own maps compete in `optimal` (plane-optimal's search does, its map
        # does not), so `optimal`'s h is at most theirs.
        competing = [name for name, _, competes in lexel.standard_starts(context) if competes]
        bound = min(h for name, h in rows if name in competing)
        rows.append((f"optimal (from {best.winner})", best.h))
        print("  h: " + ", ".join(f"{name} {h:.6g}" for name, h in rows))

        ok = (ok and len(samples) > 0 and np.count_nonzero(tested) > 0
              and agree >= 0.99 * np.count_nonzero(tested)
              and result.h <= result.h_after_iteration[0] and outside == 0
              and best.h <= bound)
    print("checks hold" if ok else "a check failed")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
