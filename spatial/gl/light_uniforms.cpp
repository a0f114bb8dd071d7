#include "lexel/spatial/gl/light_uniforms.h"

#include <glm/gtc/type_ptr.hpp>

namespace lexel::spatial::gl {

void SetLightUniforms(GLuint program, const LightSpace& lightSpace, const LightMatrix& matrix,
                      const UnitFrame& frame) {
    const bool point = lightSpace.IsPoint();
    glm::dvec3 rayBase, unused;
    lightSpace.Ray(glm::dvec3(0.0, 0.0, 1.0), &rayBase, &unused);  // directional: o - s e3
    const glm::dvec3 wsLight = point ? lightSpace.light().position : rayBase;
    const glm::dmat3 lsFromWs = lightSpace.LsFromWsLinear();
    const glm::dvec3 lsOffset = lightSpace.ToLight(glm::dvec3(0.0));
    const glm::dmat3 mapFromLs = matrix.Rows();
    const glm::dmat3 lsFromMap = glm::inverse(mapFromLs);
    const glm::dmat3 wsFromLs = glm::transpose(lsFromWs);
    glProgramUniform1i(program, 10, point ? 1 : 0);
    glProgramUniformMatrix3dv(program, 11, 1, GL_FALSE, glm::value_ptr(lsFromWs));
    glProgramUniform3dv(program, 12, 1, glm::value_ptr(lsOffset));
    glProgramUniformMatrix3dv(program, 13, 1, GL_FALSE, glm::value_ptr(mapFromLs));
    glProgramUniformMatrix3dv(program, 14, 1, GL_FALSE, glm::value_ptr(lsFromMap));
    glProgramUniformMatrix3dv(program, 15, 1, GL_FALSE, glm::value_ptr(wsFromLs));
    glProgramUniform3dv(program, 16, 1, glm::value_ptr(wsLight));
    glProgramUniform3dv(program, 17, 1, glm::value_ptr(lightSpace.light().direction));
    glProgramUniform1d(program, 18, lsOffset.z);
    glProgramUniform1d(program, 19, lightSpace.Depth(glm::dvec3(0.0)));
    glProgramUniform3dv(program, 20, 1, glm::value_ptr(frame.wsOrigin));
    glProgramUniform1d(program, 21, frame.wsScale);
}

}  // namespace lexel::spatial::gl
