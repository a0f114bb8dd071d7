// Clipping convex polyhedra by planes (the view frustum ∩ scene bounds "body" of LiSPSM, Wimmer
// et al., EGSR 2004; the frustum-limiting step of Chong & Gortler report §3) and convex polygons
// by convex polygons (I. E. Sutherland, G. W. Hodgman, "Reentrant polygon clipping", CACM 17(1),
// 1974).
#include "lexel/solvers/clipping.h"

#include <algorithm>
#include <cmath>

#include "lexel/solvers/geometry.h"

namespace lexel {

std::vector<glm::dvec3> ConvexPolyhedron::Vertices() const {
    std::vector<glm::dvec3> out;
    for (const auto& face : faces) out.insert(out.end(), face.begin(), face.end());
    return out;
}

ConvexPolyhedron FrustumPolyhedron(const std::array<glm::dvec3, 8>& c) {
    ConvexPolyhedron p;
    p.faces = {{c[0], c[1], c[2], c[3]}, {c[4], c[5], c[6], c[7]}, {c[0], c[1], c[5], c[4]},
               {c[1], c[2], c[6], c[5]}, {c[2], c[3], c[7], c[6]}, {c[3], c[0], c[4], c[7]}};
    return p;
}

ConvexPolyhedron ClipPolyhedron(const ConvexPolyhedron& polyhedron, const glm::dvec4& plane) {
    const glm::dvec3 n(plane);
    auto distance = [&](const glm::dvec3& x) { return glm::dot(n, x) + plane.w; };
    ConvexPolyhedron out;
    std::vector<glm::dvec3> cap;  // the new face on the plane: crossings and vertices on it
    for (const auto& face : polyhedron.faces) {
        std::vector<glm::dvec3> kept;
        const std::size_t count = face.size();
        for (std::size_t i = 0; i < count; ++i) {
            const glm::dvec3& a = face[i];
            const glm::dvec3& b = face[(i + 1) % count];
            const double da = distance(a), db = distance(b);
            if (da >= 0.0) kept.push_back(a);
            if (da == 0.0) cap.push_back(a);
            if ((da > 0.0 && db < 0.0) || (da < 0.0 && db > 0.0)) {
                const glm::dvec3 x = a + (da / (da - db)) * (b - a);
                kept.push_back(x);
                cap.push_back(x);
            }
        }
        if (kept.size() >= 3) out.faces.push_back(std::move(kept));
    }
    if (out.faces.empty()) return out;
    if (cap.size() >= 3) {
        // Order the cap around its centroid: it is convex (a plane section of a convex body).
        glm::dvec3 centroid(0.0);
        for (const glm::dvec3& x : cap) centroid += x;
        centroid /= static_cast<double>(cap.size());
        glm::dvec3 b1, b2;
        const double len = glm::length(n);
        if (len > 0.0) {
            PlaneBasis(n / len, &b1, &b2);
            std::sort(cap.begin(), cap.end(), [&](const glm::dvec3& p, const glm::dvec3& q) {
                const glm::dvec3 dp = p - centroid, dq = q - centroid;
                return std::atan2(glm::dot(b2, dp), glm::dot(b1, dp)) <
                       std::atan2(glm::dot(b2, dq), glm::dot(b1, dq));
            });
            out.faces.push_back(std::move(cap));
        }
    }
    return out;
}

ConvexPolyhedron ClipToBox(const ConvexPolyhedron& polyhedron, const glm::dvec3& lo,
                           const glm::dvec3& hi) {
    ConvexPolyhedron p = polyhedron;
    for (int axis = 0; axis < 3 && !p.faces.empty(); ++axis) {
        glm::dvec4 lower(0.0), upper(0.0);
        lower[axis] = 1.0;  // x_axis - lo ≥ 0
        lower.w = -lo[axis];
        upper[axis] = -1.0;  // hi - x_axis ≥ 0
        upper.w = hi[axis];
        p = ClipPolyhedron(p, lower);
        if (!p.faces.empty()) p = ClipPolyhedron(p, upper);
    }
    return p;
}

std::vector<glm::dvec2> IntersectConvexPolygons(std::span<const glm::dvec2> subject,
                                                std::span<const glm::dvec2> clip) {
    std::vector<glm::dvec2> current(subject.begin(), subject.end());
    if (clip.size() < 3) return {};
    for (std::size_t e = 0; e < clip.size() && !current.empty(); ++e) {
        const glm::dvec2 a = clip[e], b = clip[(e + 1) % clip.size()];
        const glm::dvec2 edge = b - a;
        // Signed area × 2: ≥ 0 on the left of a→b (inside a counter-clockwise polygon).
        auto side = [&](const glm::dvec2& p) { return Cross(edge, p - a); };
        std::vector<glm::dvec2> next;
        const std::size_t count = current.size();
        for (std::size_t i = 0; i < count; ++i) {
            const glm::dvec2 p = current[i], q = current[(i + 1) % count];
            const double sp = side(p), sq = side(q);
            if (sp >= 0.0) next.push_back(p);
            if ((sp > 0.0 && sq < 0.0) || (sp < 0.0 && sq > 0.0))
                next.push_back(p + (sp / (sp - sq)) * (q - p));
        }
        current = std::move(next);
    }
    return current;
}

}  // namespace lexel
