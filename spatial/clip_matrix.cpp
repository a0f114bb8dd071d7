// Composition of the light matrix with the light frame, and the clip-space rows a rasterizer needs.
#include "lexel/spatial/clip_matrix.h"

#include <glm/gtc/matrix_access.hpp>

namespace lexel::spatial {

glm::dmat4 MapFromWorld(const LightSpace& lightSpace, const LightMatrix& matrix) {
    // X = L x + X(0) (L = LightFromWorldLinear, whose columns are the light-space images of the
    // world axes), so row_i = (p_i·L[0], p_i·L[1], p_i·L[2], p_i·X(0)).
    const glm::dvec3 lsOrigin = lightSpace.ToLight(glm::dvec3(0.0));
    const glm::dmat3 lsFromWs = lightSpace.LightFromWorldLinear();
    const glm::dmat3 rows = matrix.Rows();
    glm::dmat4 m(0.0);  // column-major: m[c][r]
    for (int c = 0; c < 4; ++c) {
        const glm::dvec3 column = rows * (c < 3 ? lsFromWs[c] : lsOrigin);
        m[c][0] = column[0];
        m[c][1] = column[1];
        m[c][3] = column[2];
    }
    return m;
}

glm::dmat4 ClipFromWorld(const LightSpace& lightSpace, const LightMatrix& matrix, Resolution map,
                         DepthRange range, ClipDepth convention) {
    const glm::dmat4 texel = MapFromWorld(lightSpace, matrix);
    const glm::dvec4 row1 = glm::row(texel, 0), row2 = glm::row(texel, 1),
                     rowW = glm::row(texel, 3);
    const double n = range.near, f = range.far;
    const bool zeroToOne = convention == ClipDepth::kZeroToOne;
    glm::dvec4 rowZ;
    if (lightSpace.IsPoint()) {
        // z_clip = a w + b: z_ndc = a + b / w is -1 (0) at w = n and 1 at w = f.
        const double a = zeroToOne ? f / (f - n) : (f + n) / (f - n);
        const double b = zeroToOne ? -f * n / (f - n) : -2.0 * f * n / (f - n);
        rowZ = a * rowW + glm::dvec4(0.0, 0.0, 0.0, b);
    } else {
        // d(x) = dir·x - dir·o + s is affine in x; z_clip = a s d(x) + b w gives z_ndc =
        // a d (s / w) + b.
        const glm::dvec3 dir = lightSpace.light().direction;
        const double s = lightSpace.ToLight(glm::dvec3(0.0)).z;
        const glm::dvec4 rowD(dir, lightSpace.Depth(glm::dvec3(0.0)));
        const double a = (zeroToOne ? 1.0 : 2.0) / (f - n);
        const double b = zeroToOne ? -n / (f - n) : -(f + n) / (f - n);
        rowZ = (a * s) * rowD + b * rowW;
    }
    const glm::dvec4 rowX = (2.0 / map.width) * row1 - rowW;
    const glm::dvec4 rowY = (2.0 / map.height) * row2 - rowW;
    return glm::transpose(glm::dmat4(rowX, rowY, rowZ, rowW));
}

}  // namespace lexel::spatial
