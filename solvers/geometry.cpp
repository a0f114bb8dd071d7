#include "lexel/solvers/geometry.h"

#include <stdexcept>
#include <string>

namespace lexel {

void RequireFinitePoints(std::span<const Eigen::Vector2d> points, const char* what) {
    if (points.empty()) throw std::invalid_argument(std::string(what) + ": no points");
    for (std::size_t k = 0; k < points.size(); ++k)
        if (!points[k].allFinite())
            throw std::invalid_argument(std::string(what) + ": point " + std::to_string(k) +
                                        " is not finite");
}

}  // namespace lexel
