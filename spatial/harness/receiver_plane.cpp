#include "lexel/spatial/harness/receiver_plane.h"

#include <cmath>

namespace lexel::spatial {

double ReceiverPlaneDepth(const LightSpace& lightSpace, const glm::dvec3& lsTexelCentre,
                          const glm::dvec3& wsPoint, const glm::dvec3& wsNormal) {
    glm::dvec3 wsOrigin, wsDirection;
    lightSpace.Ray(lsTexelCentre, &wsOrigin, &wsDirection);
    const double facing = glm::dot(wsNormal, wsDirection);
    if (facing != 0.0) {
        const double t = glm::dot(wsNormal, wsPoint - wsOrigin) / facing;
        if (t > 0.0 && std::isfinite(t)) return t;
    }
    return lightSpace.Depth(wsPoint);
}

}  // namespace lexel::spatial
