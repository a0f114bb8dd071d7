// Axis-aligned bounds of world points (world units).
#pragma once

#include <array>
#include <glm/glm.hpp>
#include <limits>

namespace lexel::spatial {

// Empty until a point is added.
struct Bounds {
    glm::dvec3 lo{std::numeric_limits<double>::infinity()};
    glm::dvec3 hi{-std::numeric_limits<double>::infinity()};

    bool Empty() const { return !(lo.x <= hi.x); }
    void Add(const glm::dvec3& p) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    glm::dvec3 Center() const { return 0.5 * (lo + hi); }
    double Radius() const { return 0.5 * glm::length(hi - lo); }  // of the enclosing sphere
    // Strictly inside (not on the boundary).
    bool Contains(const glm::dvec3& p) const {
        return glm::all(glm::lessThan(lo, p)) && glm::all(glm::lessThan(p, hi));
    }
    // Corner i has coordinate k at hi when bit k of i is set, else at lo.
    std::array<glm::dvec3, 8> Corners() const {
        std::array<glm::dvec3, 8> corners;
        for (int i = 0; i < 8; ++i)
            corners[i] = {(i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z};
        return corners;
    }
};

}  // namespace lexel::spatial
