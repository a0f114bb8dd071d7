#include "lexel/spatial/light_space.h"

#include <cmath>
#include <string>

#include "lexel/solvers/errors.h"
#include "lexel/spatial/light_matrix.h"

namespace lexel::spatial {
namespace {

std::string Vec(const glm::dvec3& v) {
    return "(" + std::to_string(v.x) + ", " + std::to_string(v.y) + ", " + std::to_string(v.z) +
           ")";
}

bool Finite(const glm::dvec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

}  // namespace

LightSpace::LightSpace(const Light& light, const Bounds& wsBounds) : light_(light) {
    if (wsBounds.Empty())
        throw DomainError(Subject::kGeometry, "the scene has no geometry to light");
    if (IsPoint()) {
        if (!Finite(light.position))
            throw DomainError(Subject::kLight, "the point light's position is not finite");
        if (wsBounds.Contains(light.position))
            throw DomainError(
                Subject::kLight,
                "point light at " + Vec(light.position) +
                    " is inside the geometry's bounds; no light matrix can see all of it");
        origin_ = light.position;
        const glm::dvec3 toCenter = wsBounds.Center() - light.position;
        if (!(glm::length(toCenter) > 0.0))
            throw DomainError(Subject::kLight, "point light sits at the centre of the geometry");
        e3_ = glm::normalize(toCenter);
    } else {
        const double len = glm::length(light.direction);
        if (!Finite(light.direction) || !(len > 0.0))
            throw DomainError(Subject::kLight,
                              "directional light needs a finite, non-zero direction");
        light_.direction = light.direction / len;
        e3_ = light_.direction;
        origin_ = wsBounds.Center();
        // Twice the radius, a length of the scene's own scale (any positive s serves one point).
        const double radius = wsBounds.Radius();
        s_ = radius > 0.0 ? 2.0 * radius : 1.0;
    }
    PlaneBasis(e3_, &e1_, &e2_);  // right-handed: e1 × e2 = e3
}

glm::dvec3 LightSpace::ToLight(const glm::dvec3& wsPoint) const {
    const glm::dvec3 v = wsPoint - origin_;
    if (IsPoint()) return {glm::dot(e1_, v), glm::dot(e2_, v), glm::dot(e3_, v)};
    return {glm::dot(e1_, v), glm::dot(e2_, v), s_};
}

glm::dmat3 LightSpace::LsFromWsLinear() const {
    // glm is column-major: m[c][r]. Rows are e1, e2, e3 (or 0).
    glm::dmat3 m(0.0);
    const glm::dvec3 third = IsPoint() ? e3_ : glm::dvec3(0.0);
    for (int c = 0; c < 3; ++c) {
        m[c][0] = e1_[c];
        m[c][1] = e2_[c];
        m[c][2] = third[c];
    }
    return m;
}

double LightSpace::Depth(const glm::dvec3& wsPoint) const {
    if (IsPoint()) return glm::length(wsPoint - origin_);
    return glm::dot(e3_, wsPoint - origin_) + s_;
}

void LightSpace::Ray(const glm::dvec3& lsX, glm::dvec3* wsOrigin, glm::dvec3* wsDirection) const {
    if (IsPoint()) {
        *wsOrigin = origin_;
        *wsDirection = glm::normalize(lsX.x * e1_ + lsX.y * e2_ + lsX.z * e3_);
    } else {
        const double k = s_ / lsX.z;
        *wsOrigin = origin_ + (k * lsX.x) * e1_ + (k * lsX.y) * e2_ - s_ * e3_;
        *wsDirection = e3_;
    }
}

glm::dvec3 LightSpace::PointAtDepth(const glm::dvec3& lsX, double depth) const {
    glm::dvec3 o, d;
    Ray(lsX, &o, &d);
    return o + depth * d;  // directional: the ray starts at depth 0 (s before the centre plane)
}

glm::dvec3 LightSpace::DirectionToLight(const glm::dvec3& wsPoint) const {
    if (IsPoint()) return glm::normalize(origin_ - wsPoint);
    return -e3_;
}

double LightSpace::DistanceToLight(const glm::dvec3& wsPoint) const {
    if (IsPoint()) return glm::length(origin_ - wsPoint);
    return std::numeric_limits<double>::infinity();
}

}  // namespace lexel::spatial
