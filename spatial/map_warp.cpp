#include "lexel/spatial/map_warp.h"

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace lexel::spatial {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

bool AllFinite(std::initializer_list<double> values) {
    return std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); });
}

}  // namespace

AxisWarp AxisWarp::Affine(double scale, double offset) {
    if (!(scale > 0.0) || !AllFinite({scale, offset}))
        throw std::invalid_argument("AxisWarp::Affine: the scale must be finite and > 0, got " +
                                    std::to_string(scale));
    AxisWarp w;
    w.kind_ = Kind::kAffine;
    w.scale_ = scale;
    w.offset_ = offset;
    return w;
}

AxisWarp AxisWarp::Piecewise(double lo, double hi, std::vector<double> values) {
    if (!(lo < hi) || !AllFinite({lo, hi}))
        throw std::invalid_argument("AxisWarp::Piecewise: the knots need lo < hi, both finite");
    if (values.size() < 2)
        throw std::invalid_argument("AxisWarp::Piecewise: at least two knots, got " +
                                    std::to_string(values.size()));
    for (std::size_t i = 0; i < values.size(); ++i)
        if (!std::isfinite(values[i]) || (i > 0 && !(values[i] > values[i - 1])))
            throw std::invalid_argument(
                "AxisWarp::Piecewise: values must be finite and strictly "
                "increasing (knot " +
                std::to_string(i) + ")");
    AxisWarp w;
    w.kind_ = Kind::kPiecewise;
    w.lo_ = lo;
    w.hi_ = hi;
    w.values_ = std::move(values);
    return w;
}

AxisWarp AxisWarp::Logarithmic(double pole, double sign, double scale, double offset) {
    if (!(scale > 0.0) || !(sign == 1.0 || sign == -1.0) || !AllFinite({pole, scale, offset}))
        throw std::invalid_argument(
            "AxisWarp::Logarithmic: needs a finite pole and offset, scale > 0 and sign ±1");
    AxisWarp w;
    w.kind_ = Kind::kLogarithmic;
    w.pole_ = pole;
    w.sign_ = sign;
    w.scale_ = scale;
    w.offset_ = offset;
    return w;
}

double AxisWarp::Apply(double b) const {
    switch (kind_) {
        case Kind::kIdentity:
            return b;
        case Kind::kAffine:
            return scale_ * b + offset_;
        case Kind::kLogarithmic: {
            const double r = sign_ * (b - pole_);
            return r > 0.0 ? sign_ * scale_ * std::log(r) + offset_ : -sign_ * kInf;
        }
        case Kind::kPiecewise: {
            const std::size_t segments = values_.size() - 1;
            const double step = (hi_ - lo_) / static_cast<double>(segments);
            const double t = (b - lo_) / step;
            // The segment holding b, the end segments extended beyond the knots.
            const double clamped =
                std::clamp(std::floor(t), 0.0, static_cast<double>(segments - 1));
            const auto i = static_cast<std::size_t>(clamped);
            return values_[i] + (t - clamped) * (values_[i + 1] - values_[i]);
        }
    }
    return b;
}

double AxisWarp::Invert(double u) const {
    switch (kind_) {
        case Kind::kIdentity:
            return u;
        case Kind::kAffine:
            return (u - offset_) / scale_;
        case Kind::kLogarithmic:
            return pole_ + sign_ * std::exp(sign_ * (u - offset_) / scale_);
        case Kind::kPiecewise: {
            const std::size_t segments = values_.size() - 1;
            const double step = (hi_ - lo_) / static_cast<double>(segments);
            // The last knot value ≤ u (the first or last segment beyond the ends).
            const auto upper = std::upper_bound(values_.begin(), values_.end(), u);
            const std::size_t i =
                std::clamp<std::size_t>(static_cast<std::size_t>(upper - values_.begin()), 1,
                                        segments) -
                1;
            const double t = (u - values_[i]) / (values_[i + 1] - values_[i]);
            return lo_ + (static_cast<double>(i) + t) * step;
        }
    }
    return u;
}

double AxisWarp::Slope(double b) const {
    switch (kind_) {
        case Kind::kIdentity:
            return 1.0;
        case Kind::kAffine:
            return scale_;
        case Kind::kLogarithmic: {
            const double r = sign_ * (b - pole_);
            return r > 0.0 ? scale_ / std::abs(b - pole_) : 0.0;
        }
        case Kind::kPiecewise: {
            const std::size_t segments = values_.size() - 1;
            const double step = (hi_ - lo_) / static_cast<double>(segments);
            const double clamped =
                std::clamp(std::floor((b - lo_) / step), 0.0, static_cast<double>(segments - 1));
            const auto i = static_cast<std::size_t>(clamped);
            return (values_[i + 1] - values_[i]) / step;
        }
    }
    return 1.0;
}

bool MapWarp::IsLinear() const {
    return x.kind() == AxisWarp::Kind::kIdentity && y.kind() == AxisWarp::Kind::kIdentity;
}

MapWarp MapWarp::Shifted(const glm::dvec2& offset) const {
    MapWarp out = *this;
    out.phase += offset;
    return out;
}

std::optional<glm::dvec2> MapWarp::Forward(const glm::dvec3& lsX) const {
    if (!InFront(base.p4, lsX)) return std::nullopt;
    const glm::dvec2 b = base.Map(lsX);
    const glm::dvec2 u(x.Apply(b.x), y.Apply(b.y));
    if (!std::isfinite(u.x) || !std::isfinite(u.y)) return std::nullopt;
    return u + phase;
}

glm::dvec3 MapWarp::Inverse(const glm::dvec2& u) const {
    const glm::dvec2 w = u - phase;
    return base.Unmap(glm::dvec2(x.Invert(w.x), y.Invert(w.y)));
}

bool MapWarp::Jacobian(const glm::dvec3& lsX, glm::dvec3* du1dX, glm::dvec3* du2dX) const {
    if (!Forward(lsX)) return false;
    const glm::dvec2 b = base.Map(lsX);
    glm::dvec3 db1dX, db2dX;
    base.MapJacobian(lsX, &db1dX, &db2dX);
    *du1dX = x.Slope(b.x) * db1dX;
    *du2dX = y.Slope(b.y) * db2dX;
    return true;
}

double WarpSampleBadness(const MapWarp& warp, const glm::dvec3& lsX, const glm::dvec3& dXdx1,
                         const glm::dvec3& dXdx2, Badness badness) {
    glm::dvec3 du1dX, du2dX;
    if (!warp.Jacobian(lsX, &du1dX, &du2dX)) return kInf;
    Eigen::Matrix2d j;
    j << glm::dot(du1dX, dXdx1), glm::dot(du1dX, dXdx2), glm::dot(du2dX, dXdx1),
        glm::dot(du2dX, dXdx2);
    return JacobianBadness(j, badness);
}

double WarpEnergy(const MapWarp& warp, const LightSamples& samples) {
    double h = 0.0;
    for (std::size_t k = 0; k < samples.lsX.size(); ++k)
        h += WarpSampleBadness(warp, samples.lsX[k], samples.dXdx1[k], samples.dXdx2[k]);
    return h;
}

}  // namespace lexel::spatial
