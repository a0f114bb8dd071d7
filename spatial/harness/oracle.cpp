#include "lexel/spatial/harness/oracle.h"

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace lexel::spatial {

namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

// Two unit axes orthogonal to p4 (and to each other).
void OrthogonalAxes(const glm::dvec3& p4, glm::dvec3* a, glm::dvec3* b) {
    const glm::dvec3 n = glm::normalize(p4);
    const glm::dvec3 helper = std::abs(n.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    *a = glm::normalize(glm::cross(n, helper));
    *b = glm::cross(n, *a);
}

// The search's state: the best matrix so far and the budget left.
struct Search {
    const std::function<double(const LightMatrix&)>& score;
    int budget;
    OracleResult best;

    // Scores `m` when the budget allows; true when it is better than the best.
    bool Try(const LightMatrix& m) {
        if (best.scored >= budget) return false;
        ++best.scored;
        const double s = score(m);
        if (!(s < best.score)) return false;
        best.matrix = m;
        best.score = s;
        return true;
    }
};

}  // namespace

OracleResult SearchOracleMatrix(std::span<const OracleStart> starts, const RelevantHull& hull,
                                Resolution map,
                                const std::function<double(const LightMatrix&)>& score,
                                const OracleOptions& options) {
    if (starts.empty()) throw std::invalid_argument("SearchOracleMatrix: no starts");
    Search search{score, options.budget, {}};
    search.best.score = std::numeric_limits<double>::infinity();
    FitOptions fit;
    fit.margin = options.margin;
    // The starts as they are and re-fitted for their own axes.
    for (const OracleStart& s : starts) {
        if (search.Try(s.matrix)) search.best.start = s.name;
        if (const std::optional<LightMatrix> refit = hull.Fit(s.matrix.p4, map, fit))
            if (search.Try(*refit)) search.best.start = s.name + "+fit";
    }
    search.best.startScore = search.best.score;
    if (!std::isfinite(search.best.score)) {
        search.best.matrix = starts.front().matrix;
        return search.best;
    }
    // The compass search on p4.
    for (double step = options.initialStepDeg; step >= options.finalStepDeg;) {
        glm::dvec3 a, b;
        OrthogonalAxes(search.best.matrix.p4, &a, &b);
        const glm::dvec3 p4 = search.best.matrix.p4;
        bool moved = false;
        for (const glm::dvec3& axis : {a, -a, b, -b}) {
            const std::optional<LightMatrix> m =
                hull.Fit(RotateAxis(p4, axis, step * kDegree), map, fit);
            if (m) moved = search.Try(*m) || moved;
        }
        if (search.best.scored >= options.budget) break;
        if (!moved) step *= 0.5;
    }
    return search.best;
}

}  // namespace lexel::spatial
