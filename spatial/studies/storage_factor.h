// Lloyd's storage factor S̄: the texels a shadow-map scheme needs, relative to the image's pixels,
// to keep the perspective aliasing error w_l / w_i ≤ 1 everywhere in the view frustum (B. Lloyd,
// D. Tuft, S. Yoon, D. Manocha, "Warping and Partitioning for Low Error Shadow Maps", EGSR 2006,
// §3–§5 and Appendices A–C). Scene independent: only the view frustum and the light direction.
//
// Conventions of every function below:
//   - eye space: the eye at the origin looking along -z, +y up, +x right (OpenGL view space);
//     lengths in eye units. The view vector is v = (0, 0, -1) and a point's eye depth is p·v.
//   - resolution 1: the image is 1 pixel high and `aspect` pixels wide (square pixels), so
//     w_i(p) = 2 tanθ (p·v) (eq. 2), and the errors m_x, m_z, M_x, M_z are beam-width ratios at a
//     map resolution of 1 texel (multiply by res_y / res_s or res_y / res_t for other ones).
//   - storage factor: S̄ = Σ over the scheme's maps of M_x·M_z / aspect, i.e. the critical
//     storage S* (texels) divided by the image's pixel count. For aspect = 1 this is the paper's
//     S̄ = M_x·M_z (eq. 12).
//   - light direction: esToLight, the eye-space direction toward the directional light (the
//     light travels along -esToLight). γ is the angle between the light's travel direction and
//     the view direction: 0° the light behind the viewer, 90° overhead, 180° in front.
//   - warp parameter: n' (the distance from the warp's projection centre to the body's near face,
//     Fig. 3), +∞ for the unwarped (orthographic) map; or η ∈ [-1, 1] (eq. 11): -1 unwarped,
//     0 LiSPSM, 1 PSM.
// Failure: every function throws StorageFactorError (a std::invalid_argument: a caller such as
// the command line checks its input first) naming the quantity and the reason for input outside
// the stated domain; none returns NaN.
#pragma once

#include <functional>
#include <glm/glm.hpp>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace lexel::spatial {

// ---------------------------------------------------------------------------------------------
// Inputs and errors

// The view frustum. fovYDeg is the full vertical field of view 2θ in degrees, in (0, 180);
// aspect = image width / height, finite and > 0; 0 < nearPlane < farPlane, finite.
struct ViewFrustum {
    double fovYDeg = 60.0;
    double aspect = 1.0;
    double nearPlane = 1.0;
    double farPlane = 100.0;

    double TanHalfFovY() const;                                 // tan θ
    double DepthRatio() const { return farPlane / nearPlane; }  // f / n
};

// Bad input: quantity() names it ("far plane f", "warp parameter eta", ...), what() is the one
// line "<quantity>: <reason>".
class StorageFactorError : public std::invalid_argument {
  public:
    StorageFactorError(const std::string& quantity, const std::string& reason);
    const std::string& quantity() const { return quantity_; }

  private:
    std::string quantity_;
};

// Throws StorageFactorError unless the frustum is in the domain stated at ViewFrustum.
void ValidateFrustum(const ViewFrustum& frustum);

// Unit eye-space direction toward the light for γ (degrees, [0, 180], see above) and the azimuth
// φ about the view axis (degrees; 0 = the light on the +y side, 90 = on the +x side):
// -cosγ v + sinγ (cosφ up + sinφ right). γ = 90°, φ = 0 is Lloyd's "light overhead" (Fig. 3),
// γ = 0 "light behind" (Fig. 11).
glm::dvec3 DirectionToLight(double gammaDeg, double azimuthDeg = 0.0);

// A pair of errors (m_x, m_z) at a point, or of maxima (M_x, M_z) over a region.
struct ErrorPair {
    double x = 0.0;
    double z = 0.0;
};

// ---------------------------------------------------------------------------------------------
// Light overhead (γ = 90°, φ = 0): the closed forms of §4.1–§5.3. nPrime ∈ [n, +∞] (+∞ allowed);
// z ∈ [n, f]; k ≥ 1 partitions.

// n'_LSPSM = n + √(f n): where m_z(n) = m_z(f) (§4.1).
double LispsmWarpOffset(double nearPlane, double farPlane);
// Eq. 11 (corrected, Appendix B): η ∈ [-1, 1] → n' ∈ [n, +∞]; n'(-1) = +∞, n'(0) = n + √(fn),
// n'(1) = n. Throws for η outside [-1, 1] or a bad n, f.
double WarpOffsetFromEta(double eta, double nearPlane, double farPlane);
// Appendix B's definition of η: the inverse of WarpOffsetFromEta on n' ∈ [n, +∞].
double EtaFromWarpOffset(double nPrime, double nearPlane, double farPlane);

// Eqs. 7–8 at depth z (m_x includes the factor `aspect`, 1 in the paper).
ErrorPair OverheadErrors(const ViewFrustum& frustum, double nPrime, double z);
// Eqs. 9–10 (corrected for n ≠ 1): M_x = a f n' / (n (n'+f-n)); M_z = m_z(f) for n' ≤ n'_LSPSM,
// else m_z(n).
ErrorPair OverheadMaxErrors(const ViewFrustum& frustum, double nPrime);
// Eq. 12: S̄ = (f/n - 1) / (2 tanθ) · [1 if n' ≤ n'_LSPSM, else n'² f / (n (n'+f-n)²)].
double OverheadStorageFactor(const ViewFrustum& frustum, double nPrime);
// Appendix C: the logarithmic parameterization's S̄_opt = ln(f/n) / (2 tanθ).
double OptimalStorageFactor(const ViewFrustum& frustum);

// Eqs. 15–16: the k + 1 partition depths n_i = n (f/n)^(i/k), i = 0..k (first n, last f).
std::vector<double> ZPartitionDepths(double nearPlane, double farPlane, int k);
// Eq. 17, z-partitioning without warping, light overhead: k ρ (ρ - 1) / (2 tanθ), ρ = (f/n)^(1/k).
double ZpOverheadStorageFactor(const ViewFrustum& frustum, int k);
// Eqs. 18–19, ZP + W and FP + ZP + W (k partitions per face), light overhead: k (ρ - 1)/(2 tanθ).
double ZpWarpOverheadStorageFactor(const ViewFrustum& frustum, int k);
// Eq. 20, ZP and ZP + W with the light behind (no warp possible): k ρ².
double ZpBehindStorageFactor(const ViewFrustum& frustum, int k);
// Eq. 21, FP + ZP + W with the light behind, k partitions on each of the 4 side faces plus the
// near face: 4 · [eq. 18 at θ = 45°] + 1 = 2 k (ρ - 1) + 1. Ours: holds for every θ and aspect
// (each side face seen from behind is the overhead frustum of a 45° camera; see the .cpp).
double FpZpWarpBehindStorageFactor(const ViewFrustum& frustum, int k);
// Ours (Fig. 13): the depth ratio f/n at which ZP with j = 4m maps (eq. 20, k = 4m) and
// FP + ZP + W with m partitions per side face (eq. 21, 4m maps + the near face) need the same
// storage with the light behind: (1 + √(2 - 1/(2m)))^(2m). Below it FP + ZP + W needs less.
double ZpFpCrossoverDepthRatio(int facePartitions);

// ---------------------------------------------------------------------------------------------
// General light directions (§4.4): beam widths at the frustum's vertices.

// Lloyd's light space (Fig. 3) for a light and a "view" axis (the view vector, or a face's edge
// bisector for face partitioning, §5.1): y toward the light, z the axis made perpendicular to y,
// x = y × z. When the axis is within sinγ < 1e-9 of ±y, z is the eye's up vector made
// perpendicular to y (then ±y is the view axis, so up already is), and sinGamma is 0.
struct LightFrame {
    glm::dvec3 x{1.0, 0.0, 0.0}, y{0.0, 1.0, 0.0}, z{0.0, 0.0, 1.0};  // unit, eye space
    double sinGamma = 1.0;  // |axis × y|: sin of the angle between the axis and the light
    glm::dvec3 ToLight(const glm::dvec3& esPoint) const;  // (p·x, p·y, p·z)
};
LightFrame MakeLightFrame(const glm::dvec3& esToLight, const glm::dvec3& esAxis);

// A shadow map with a perspective warp along light-space z (§4.1, Fig. 3, eqs. 5–6 corrected):
// projection centre at light-space (x = 0, z = zLo - nPrime) — laterally at the eye, as LiSPSM —
// near face at zLo, far face at zHi; the map (s, t) ∈ [0, 1]² covers the fitted body exactly.
// nPrime = +∞ is the orthographic map with s along x and t along z.
struct WarpedMap {
    LightFrame frame;
    double nPrime = 0.0;
    double zLo = 0.0, zHi = 0.0;          // light-space z range of the body
    double slopeLo = 0.0, slopeHi = 0.0;  // range of x / (z - zc) (x itself when unwarped)

    // (s, t) of an eye-space point: s = (slope - slopeLo) / (slopeHi - slopeLo), t from eq. 6.
    glm::dvec2 Map(const glm::dvec3& esPoint) const;
    // Eqs. 3–4 at resolution 1: (w_lx, w_lz) = (dx/ds, dz/dt) at the point, eye units.
    ErrorPair BeamWidths(const glm::dvec3& esPoint) const;
};
// Fits a WarpedMap to the body (its vertices, eye space, in front of the centre). nPrime > 0 or
// +∞. Throws for an empty body or a bad nPrime.
WarpedMap FitWarpedMap(const LightFrame& frame, std::span<const glm::dvec3> esBody, double nPrime);

// Eq. 2 with z = p·v at resolution 1: 2 tanθ (p·v).
double ImageBeamWidth(const ViewFrustum& frustum, const glm::dvec3& esPoint);
// §4.4: M_x, M_z of a map over the given vertices (the maxima over a convex body lie at its
// vertices: m_x is linear-fractional, m_z quadratic-over-linear in the point; see the .cpp).
ErrorPair VertexMaxErrors(const ViewFrustum& frustum, const WarpedMap& map,
                          std::span<const glm::dvec3> esVertices);

// The dense numeric reference: M_x, M_z over arbitrary sample points of any map (s, t)(p), with
// w_lx = 1 / (∂s/∂x), w_lz = 1 / (∂t/∂z) from 5-point central differences of step `step` (eye
// units) along the frame's x and z. Throws for no samples, step ≤ 0, or a non-finite derivative.
ErrorPair SampledMaxErrors(const ViewFrustum& frustum, const LightFrame& frame,
                           const std::function<glm::dvec2(const glm::dvec3&)>& map,
                           std::span<const glm::dvec3> esSamples, double step);
// A lattice over the frustum: perAxis × perAxis screen positions over [-1, 1]² (corners
// included) at perAxis depths per z-partition (geometric, both ends included, eq. 15–16), so
// every partition's vertices are samples. perAxis ≥ 2, k ≥ 1.
std::vector<glm::dvec3> FrustumSamples(const ViewFrustum& frustum, int perAxis, int k = 1);

// LogPSM (D. B. Lloyd, N. K. Govindaraju, C. Quammen, S. E. Molnar, D. Manocha, "Logarithmic
// Perspective Shadow Maps", ACM TOG 2008) as a map of §4.4: a perspective warp of offset n'
// followed by the logarithm of ζ = n' + (z − zLo), the distance from its projection centre along
// the frame's z: s as the warp's, t = ln(ζ / n') / ln(1 + (zHi − zLo) / n'). Appendix C's
// derivation in general position: w_lz = dz/dt = ζ ln(1 + (zHi − zLo) / n'), w_lx the warp's;
// n' = +∞ is the orthographic map (t linear in z).
struct LogWarpedMap {
    WarpedMap perspective;

    glm::dvec2 Map(const glm::dvec3& esPoint) const;        // (s, t)
    ErrorPair BeamWidths(const glm::dvec3& esPoint) const;  // (w_lx, w_lz), resolution 1
};
LogWarpedMap FitLogWarpedMap(const LightFrame& frame, std::span<const glm::dvec3> esBody,
                             double nPrime);
// M_x, M_z of a LogWarpedMap over vertices: m_x and m_z = ζ ln(·) / (2 tanθ z) are
// linear-fractional in the point, so their maxima over a convex body lie at its vertices.
ErrorPair LogVertexMaxErrors(const ViewFrustum& frustum, const LogWarpedMap& map,
                             std::span<const glm::dvec3> esVertices);
// LogPSM's S̄ for the frustum: the map fitted to its 8 corners with n' = n / sin γ (η = 1, as
// Scheme's maps; +∞ along the light), S̄ = M_x M_z / aspect by the vertex rule. For an overhead
// light n' = n, the warping frustum is the view frustum, and S̄ = S̄_opt (OptimalStorageFactor).
double LogPsmStorageFactor(const ViewFrustum& frustum, const glm::dvec3& esToLight);

// The single map of §4.4 for an explicit n' (light-space units, > 0 or +∞), fitted to the whole
// frustum in the frame of the view vector: S̄ = M_x M_z / aspect over the 8 vertices.
double StorageFactorForWarpOffset(const ViewFrustum& frustum, const glm::dvec3& esToLight,
                                  double nPrime);

// ---------------------------------------------------------------------------------------------
// Schemes: z-partitioning (ZP, §5.2), warping (W, §4), face partitioning (FP, §5.1).

// zPartitions k ≥ 1 (eqs. 15–16, split by planar eye depth); eta ∈ [-1, 1] for every map, -1 the
// unwarped ZP. Each map's n' is eq. 11 on its own depth range [n_i, f_i] divided by sinγ of its
// frame (Wimmer et al.'s general-γ LiSPSM, n' → ∞ as the light aligns with the axis; η = 0 is
// LiSPSM exactly, η = 1 is PSM's n' only for γ = 90°). Face partitioning: one map per piece of
// each side face whose light rays meet the narrowest image beams (front faces when v·y ≤ 0, back
// faces otherwise), z along the bisector of the face's projected side edges, depths [n_i, f_i]
// along it; plus, if nearFace, an unwarped map of the near face (image beams constant on it).
struct Scheme {
    int zPartitions = 1;
    double eta = 0.0;
    bool facePartitioning = false;
    bool nearFace = true;

    static Scheme Zp(int k) { return {k, -1.0, false, true}; }
    static Scheme ZpWarp(int k, double eta = 0.0) { return {k, eta, false, true}; }
    static Scheme FpZpWarp(int k, double eta = 0.0) { return {k, eta, true, true}; }
};
void ValidateScheme(const Scheme& scheme);

// One shadow map of a scheme: which part it covers, its warp and its critical resolution.
struct MapStorage {
    std::string label;    // "z 2/4", "top z 1/2", "near"
    double nPrime = 0.0;  // +∞ unwarped
    ErrorPair maxErrors;  // M_x, M_z: critical texels per image pixel (res_s*, res_t* at res_y = 1)
    double storage = 0.0;  // M_x M_z / aspect
};
struct SchemeStorage {
    double storage = 0.0;  // S̄ = Σ maps' storage
    std::vector<MapStorage> maps;
};
// §4.4's vertex rule for every map of the scheme. Throws for a bad frustum, light or scheme.
SchemeStorage EvaluateScheme(const ViewFrustum& frustum, const glm::dvec3& esToLight,
                             const Scheme& scheme);
// The same maps measured numerically: FrustumSamples(frustum, perAxis, k) assigned to partitions
// by planar eye depth (ZP) or by the face and depth where their light ray meets the chosen faces
// (FP; ties go to every partition), errors by SampledMaxErrors. perAxis ≥ 2.
SchemeStorage SampleScheme(const ViewFrustum& frustum, const glm::dvec3& esToLight,
                           const Scheme& scheme, int perAxis);

// ---------------------------------------------------------------------------------------------
// The data behind the paper's figures (plain series; the caller prints or plots them).

// Figs. 5–6, light overhead: `count` ≥ 2 values of η from -1 to 1 with n', M_x, M_z, S̄.
struct WarpSweepPoint {
    double eta = 0.0, nPrime = 0.0;  // nPrime +∞ at η = -1
    ErrorPair maxErrors;
    double storage = 0.0;
};
std::vector<WarpSweepPoint> WarpSweep(const ViewFrustum& frustum, int count);

// Fig. 5, light overhead: m_x(z), m_z(z) at `count` ≥ 2 depths from n to f (eqs. 7–8).
struct ErrorProfilePoint {
    double z = 0.0;
    ErrorPair errors;
};
std::vector<ErrorProfilePoint> ErrorProfile(const ViewFrustum& frustum, double nPrime, int count);

// Fig. 7: S̄ of a scheme over the hemisphere of lights above the viewer, a size × size image
// (size ≥ 1), row-major, row 0 at the top. Cell (col, row) has centre gx = toLight·v (-1 behind,
// on the left; +1 in front, on the right) and gy = toLight·right (+1 at the top), the orthographic
// view of the hemisphere from above: toLight·up = √(1 - gx² - gy²). Cells with gx² + gy² > 1
// are outside (inside = false, storage 0). The caller takes log10 for the paper's scale.
struct HemisphereCell {
    bool inside = false;
    double gx = 0.0, gy = 0.0;
    glm::dvec3 esToLight{0.0};
    double storage = 0.0;
};
struct HemisphereGrid {
    int size = 0;
    std::vector<HemisphereCell> cells;
    const HemisphereCell& Max() const;  // the inside cell of largest S̄ (throws if none)
};
HemisphereGrid StorageHemisphere(const ViewFrustum& frustum, const Scheme& scheme, int size);

// Fig. 10, light overhead: S̄ of ZP (eq. 17) and ZP + W (eq. 18) for k = 1..maxK (≥ 1), with
// S̄_opt; evaluated by the vertex rule (EvaluateScheme).
struct PartitionSweepPoint {
    int k = 0;
    double zp = 0.0, zpWarp = 0.0, optimal = 0.0;
};
std::vector<PartitionSweepPoint> PartitionSweep(const ViewFrustum& frustum, int maxK);

// Fig. 12: S̄ against the number of shadow maps j = 1..maxMaps (≥ 1), light overhead and behind,
// by the vertex rule. FP + ZP + W has j / 4 partitions per side face ("one z-partitioning for
// every four shadow maps", §5.3) and is only defined for j divisible by 4; its near-face map
// (S̄ = 1 from behind, 0 overhead) is counted in S̄ but not in j, as in eq. 21.
struct MapCountPoint {
    int maps = 0;
    double zpOverhead = 0.0, zpWarpOverhead = 0.0;  // eqs. 17, 18
    double zpBehind = 0.0, zpWarpBehind = 0.0;      // eq. 20 (both)
    std::optional<double> fpOverhead, fpBehind;     // eqs. 19, 21
};
std::vector<MapCountPoint> MapCountSweep(const ViewFrustum& frustum, int maxMaps);

// Fig. 13, light behind: for j = 4m maps (m = 1..maxFacePartitions), the depth ratio where ZP and
// FP + ZP + W cross — closed form (ZpFpCrossoverDepthRatio) and a bisection on EvaluateScheme for
// the frustum's θ and aspect (its n, f are ignored).
struct CrossoverPoint {
    int maps = 0, facePartitions = 0;
    double depthRatio = 0.0;           // closed form
    double depthRatioEvaluated = 0.0;  // vertex rule
};
std::vector<CrossoverPoint> ZpFpCrossover(const ViewFrustum& frustum, int maxFacePartitions);

}  // namespace lexel::spatial
