// lexel's 3D core in one include, installed as <lexel/spatial.h>: the scene-optimized light
// matrix of Chong & Gortler (report §2–3) for a renderer's own buffers. The usual path:
//   1. a low-resolution camera pass → CameraBuffer (your G-buffer, or a depth buffer of any
//      convention: DepthBuffer, DownsampleDepth, depth_buffer.h) → MakeReadback (readback.h);
//   2. per light: LightSpace (light_space.h), the standard map StandardLightMatrix
//      (standard_map.h) rendered through ClipFromWorld with LightDepthRange (clip_matrix.h), the
//      readback's shadow mask under it → MakeLightSamples (samples.h);
//   3. OptimizeLightMatrix (optimizer.h) from the standard map's axis → LightMatrix →
//      ClipFromWorld with LightDepthRange, the 4×4 to render the shadow map with.
// Every named method (optimal, the baselines, the cascades) is also one call by name:
// ComputeLightMatrix (methods/registry.h; MethodInfos lists them).
// spatial/README.md, the embedding guide, has the whole of it, compiled by the test suite.
#pragma once

#include "lexel/spatial/baselines.h"
#include "lexel/spatial/bounds.h"
#include "lexel/spatial/camera.h"
#include "lexel/spatial/cascades.h"
#include "lexel/spatial/clip_matrix.h"
#include "lexel/spatial/depth_buffer.h"
#include "lexel/spatial/energy_gradient.h"
#include "lexel/spatial/light_matrix.h"
#include "lexel/spatial/light_space.h"
#include "lexel/spatial/methods/registry.h"
#include "lexel/spatial/multi_start.h"
#include "lexel/spatial/optimizer.h"
#include "lexel/spatial/partitions.h"
#include "lexel/spatial/perspective_aliasing.h"
#include "lexel/spatial/readback.h"
#include "lexel/spatial/samples.h"
#include "lexel/spatial/standard_map.h"
#include "lexel/spatial/temporal.h"
#include "lexel/spatial/tsm.h"
#include "lexel/spatial/virtual_shadow_map.h"
