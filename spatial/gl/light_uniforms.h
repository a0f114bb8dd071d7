// The light uniforms of shaders.h (LEXEL_LIGHT_UNIFORMS, locations 10–21) for one light, its
// matrix and the mesh's unit frame, in double: what every pass that casts the light ray through
// a texel centre (the shadow-map passes, shading, the receiver-plane test) reads. Needs the
// context current on the calling thread.
#pragma once

#include <epoxy/gl.h>

#include "lexel/spatial/harness/scene.h"
#include "lexel/spatial/light_matrix.h"
#include "lexel/spatial/light_space.h"

namespace lexel::spatial::gl {

void SetLightUniforms(GLuint program, const LightSpace& lightSpace, const LightMatrix& matrix,
                      const UnitFrame& frame);

}  // namespace lexel::spatial::gl
