"""lexel: the light projection for a shadow map whose texels land evenly on what the camera sees.

The Python module of lexel's 3D core: Chong & Gortler's scene-optimized light matrix (report
§2-3) for a renderer's own buffers, with numpy arrays in and out. One frame, per light:

    readback = lexel.make_readback(lexel.downsample_depth(depth, clip_from_world, convention))
    light_space = lexel.LightSpace(light, scene_bounds)
    standard = lexel.standard_light_matrix(readback, light_space, scene_bounds, (512, 512))
    near_far = lexel.light_depth_range(light_space, standard, (512, 512), scene_bounds,
                                       readback.ws_relevant)
    clip = lexel.clip_from_world(light_space, standard, (512, 512), near_far)
    shades = your_shadow_test(readback.ws_position, clip)       # (H, W) of lexel.Shade
    samples = lexel.make_light_samples(readback, light_space, shades)
    context = lexel.BaselineContext(light_space, camera, (512, 512), scene_bounds,
                                    readback.ws_relevant, samples=samples,
                                    relevant_hull=readback.ws_relevant_hull)
    best = lexel.optimal(context)                               # or lexel.baseline("psm", context)
    clip = lexel.clip_from_world(light_space, best.matrix, ...)  # render the shadow map with it

Arrays: matrices are (4, 4) float64 indexed [row, column] (m @ [x, y, z, 1]), points (N, 3),
depth buffers (H, W) float32, per-pixel results (H, W) or (H, W, 3) in the depth array's order.
Bad input raises ValueError (or TypeError) naming the argument; input the algorithm cannot
serve raises lexel.DomainError (a ValueError) with lexel's one-line reason.
spatial/python/README.md in lexel's source says more; examples/optimize_shadows.py is the whole
of it on a toy scene.
"""

try:
    import numpy as _numpy  # noqa: F401  (the module's arrays are numpy's)
except ImportError as _error:  # pragma: no cover - depends on the interpreter
    import sys as _sys

    raise ImportError(
        "lexel needs numpy, which " + _sys.executable + " cannot import "
        "(Debian 12: apt-get install python3-numpy, and run Debian's /usr/bin/python3)"
    ) from _error

import enum as _enum

from . import _lexel
from ._lexel import *  # noqa: F401,F403
from ._lexel import __version__  # noqa: F401

Shade = _enum.IntEnum("Shade", dict(_lexel._SHADE_VALUES), module=__name__)
Shade.__doc__ = _lexel._SHADE_DOC

__all__ = sorted([name for name in dir(_lexel) if not name.startswith("_")] + ["Shade"])
