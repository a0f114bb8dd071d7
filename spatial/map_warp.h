// A shadow map's parameterization beyond a light matrix: where a light-space point lands on the
// map, and which light ray a texel stands for, for maps a 4×4 matrix cannot rasterize exactly.
//
// Both nonlinear warps lexel compares are separable after a light matrix B (light_matrix.h):
//   - rectilinear texture warping (P. Rosen, "Rectilinear Texture Warping for Fast Adaptive Shadow
//     Mapping", I3D 2012): B a focused map, then one monotone 1-D warp per map axis (rtw.h);
//   - logarithmic perspective shadow maps (D. B. Lloyd, N. K. Govindaraju, C. Quammen, S. E.
//     Molnar, D. Manocha, "Logarithmic Perspective Shadow Maps", ACM TOG 27(4), 2008): B a
//     perspective warp, then a logarithm of its depth coordinate (logpsm.h).
// So a MapWarp is B followed by a monotone increasing function φ of each of B's map coordinates,
// and a sub-texel phase δ (the grid shift of the phase averaging, in warped texels):
//     u = (φ_x(b_x), φ_y(b_y)) + δ,    b = (p1·X, p2·X) / (p4·X)    (texels),
// with its inverse (the texel's ray, X = B⁻¹(φ_x⁻¹(u_x − δ_x), φ_y⁻¹(u_y − δ_y), 1)) and its
// Jacobian ∂u/∂X = diag(φ_x'(b_x), φ_y'(b_y)) ∂b/∂X. With φ the identity and δ = 0 it is the
// light matrix itself (MapWarp::Linear), texel for texel.
#pragma once

#include <glm/glm.hpp>
#include <optional>
#include <span>
#include <vector>

#include "lexel/solvers/footprint_metrics.h"
#include "lexel/spatial/light_matrix.h"
#include "lexel/spatial/samples.h"

namespace lexel::spatial {

// A strictly increasing function φ: ℝ → ℝ of one map coordinate (texels of B to texels of the
// warped map), with its inverse and its slope. Four kinds:
//   identity        φ(b) = b;
//   affine          φ(b) = scale·b + offset, scale > 0;
//   piecewise       linear through knots (b_i, u_i), b_i equally spaced over [lo, hi], u_i
//                   strictly increasing; beyond the ends it continues with the end segments'
//                   slopes (so a point off the warped domain stays off the map);
//   logarithmic     φ(b) = sign·scale·ln(sign·(b − pole)) + offset, scale > 0, sign = ±1:
//                   defined for sign·(b − pole) > 0 (b above the pole for sign +1, below it for
//                   −1), −sign·∞ at and beyond the pole (off the map's low or high end).
// Where φ is infinite its slope is 0 and Invert never returns such b.
class AxisWarp {
  public:
    enum class Kind { kIdentity, kAffine, kPiecewise, kLogarithmic };

    AxisWarp() = default;  // the identity
    static AxisWarp Affine(double scale, double offset);
    // std::invalid_argument unless lo < hi, values has ≥ 2 finite entries, strictly increasing.
    static AxisWarp Piecewise(double lo, double hi, std::vector<double> values);
    // std::invalid_argument unless scale > 0, sign = ±1 and every parameter is finite.
    static AxisWarp Logarithmic(double pole, double sign, double scale, double offset);

    Kind kind() const { return kind_; }
    double Apply(double b) const;   // φ(b)
    double Invert(double u) const;  // φ⁻¹(u) (logarithmic: always on the pole's good side)
    double Slope(double b) const;   // φ'(b) (piecewise: the slope of the segment b lies in)
    // The piecewise kind's knots: b_i = lo + i (hi − lo) / (n − 1), u_i = values[i].
    double lo() const { return lo_; }
    double hi() const { return hi_; }
    const std::vector<double>& values() const { return values_; }
    // The logarithmic kind's parameters (0 otherwise).
    double pole() const { return pole_; }
    double sign() const { return sign_; }
    double scale() const { return scale_; }
    double offset() const { return offset_; }

  private:
    Kind kind_ = Kind::kIdentity;
    double scale_ = 1.0, offset_ = 0.0;  // affine, logarithmic
    double pole_ = 0.0, sign_ = 1.0;     // logarithmic
    double lo_ = 0.0, hi_ = 1.0;         // piecewise
    std::vector<double> values_;         // piecewise
};

// A light matrix followed by a separable warp and a phase (the header comment). Copyable value.
struct MapWarp {
    LightMatrix base;
    AxisWarp x, y;
    glm::dvec2 phase{0.0};  // δ, warped texels

    static MapWarp Linear(const LightMatrix& matrix) { return {matrix, {}, {}, glm::dvec2(0.0)}; }
    // Whether u = B(X) + δ (both axis warps the identity).
    bool IsLinear() const;
    // The same warp with its texel grid moved by `offset` texels: u' = u + offset.
    MapWarp Shifted(const glm::dvec2& offset) const;

    // u in texels; nullopt when X is not InFront of base.p4 or off a logarithmic axis's domain.
    std::optional<glm::dvec2> Forward(const glm::dvec3& lsX) const;
    // The light-space direction of the ray through texel coordinates u (p4·X = 1).
    glm::dvec3 Inverse(const glm::dvec2& u) const;
    // ∂u/∂X at X as two rows; false (rows untouched) where Forward is nullopt.
    bool Jacobian(const glm::dvec3& lsX, glm::dvec3* du1dX, glm::dvec3* du2dX) const;
};

// The badness of J⁻¹ at one readback sample (samples.h's SampleBadness for a warped map):
// J = (∂u/∂X)(∂X/∂x). +inf where Forward is nullopt or J is singular.
double WarpSampleBadness(const MapWarp& warp, const glm::dvec3& lsX, const glm::dvec3& dXdx1,
                         const glm::dvec3& dXdx2,
                         Badness badness = Badness::kFrobeniusInverseSquared);
// h (eq. 6) of a warped map over the samples: Σ WarpSampleBadness; +inf if any sample is off it.
double WarpEnergy(const MapWarp& warp, const LightSamples& samples);

}  // namespace lexel::spatial
