// Lloyd et al. 2006's storage factor (storage_factor.h). The derivations of every formula here —
// light overhead (eqs. 5–12), η (eq. 11, Appendix B), the log bound (Appendix C), the vertex rule
// for a general light (§4.4), z- and face partitioning (§5) — are in storage_factor.md beside this
// file; tests/spatial/studies/storage_factor_test.cpp checks them against dense samples of the
// frustum (relative 1e-6).
#include "lexel/spatial/studies/storage_factor.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <sstream>

namespace lexel::spatial {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kPi = 3.14159265358979323846;
const glm::dvec3 kEsView{0.0, 0.0, -1.0};
const glm::dvec3 kEsUp{0.0, 1.0, 0.0};
const glm::dvec3 kEsRight{1.0, 0.0, 0.0};

// Below this sin γ (dimensionless) an axis counts as parallel to the light: the light-space z is
// undefined, the frame falls back to the eye's up vector and the warp to n' = ∞ (Lloyd §4.4: the
// warping methods "revert back to an orthogonal projection" there; n' ∝ 1/sinγ anyway).
constexpr double kMinSinGamma = 1e-9;
// A face with |n·y| at most this (cosine, dimensionless) is edge-on to the light: its projection
// has no area and it gets no map.
constexpr double kEdgeOnCosine = 1e-12;
// Samples within this many eye units per unit far-plane distance of a partition boundary belong
// to every partition the boundary separates (so each partition sees its own vertices).
constexpr double kTieTolerance = 1e-9;
// Upper bounds that keep the outputs' sizes sane (no paper value comes near them).
constexpr int kMaxPartitions = 4096;
constexpr int kMaxSeriesLength = 1 << 20;
constexpr int kMaxCrossoverPartitions = 32;

std::string Num(double x) {
    std::ostringstream out;
    out.precision(10);
    out << x;
    return out.str();
}

void Require(bool ok, const std::string& quantity, const std::string& reason) {
    if (!ok) throw StorageFactorError(quantity, reason);
}

void CheckNearFar(double nearPlane, double farPlane) {
    Require(std::isfinite(nearPlane) && nearPlane > 0.0, "near plane n",
            "must be finite and > 0, got " + Num(nearPlane));
    Require(std::isfinite(farPlane) && farPlane > nearPlane, "far plane f",
            "must be finite and > n = " + Num(nearPlane) + ", got " + Num(farPlane));
}

void CheckCount(int count, int least, const std::string& quantity) {
    Require(count >= least && count <= kMaxSeriesLength, quantity,
            "must be in [" + std::to_string(least) + ", " + std::to_string(kMaxSeriesLength) +
                "], got " + std::to_string(count));
}

void CheckPartitions(int k, const std::string& quantity) {
    Require(k >= 1 && k <= kMaxPartitions, quantity,
            "must be in [1, " + std::to_string(kMaxPartitions) + "], got " + std::to_string(k));
}

// n' for the overhead closed forms: [n, +∞].
void CheckOverheadWarpOffset(double nPrime, double nearPlane) {
    Require(nPrime >= nearPlane, "warp offset n'",
            "must be in [n, +inf] = [" + Num(nearPlane) + ", +inf], got " + Num(nPrime));
}

// cos and sin of an angle in degrees, exact at multiples of 90° (so that "overhead" is exactly
// perpendicular to the view vector).
glm::dvec2 CosSinDeg(double deg) {
    const double r = std::remainder(deg, 360.0);
    if (r == 0.0) return {1.0, 0.0};
    if (r == 90.0) return {0.0, 1.0};
    if (r == -90.0) return {0.0, -1.0};
    if (r == 180.0 || r == -180.0) return {-1.0, 0.0};
    return {std::cos(r * kPi / 180.0), std::sin(r * kPi / 180.0)};
}

// ρ - 1 and ρ for ρ = α^(1/k), without cancellation for large k.
double RhoMinusOne(double depthRatio, int k) { return std::expm1(std::log(depthRatio) / k); }

glm::dvec3 EyePoint(const ViewFrustum& frustum, double screenX, double screenY, double depth) {
    const double t = frustum.TanHalfFovY();
    return depth * glm::dvec3(screenX * frustum.aspect * t, screenY * t, -1.0);
}

// The 8 corners of the sub-frustum between eye depths lo and hi.
std::vector<glm::dvec3> SubFrustumCorners(const ViewFrustum& frustum, double lo, double hi) {
    std::vector<glm::dvec3> corners;
    for (double depth : {lo, hi})
        for (double sy : {-1.0, 1.0})
            for (double sx : {-1.0, 1.0}) corners.push_back(EyePoint(frustum, sx, sy, depth));
    return corners;
}

// A face of the view frustum: outward unit normal, plane normal·p + offset = 0 (inside ≤ 0), and
// for a side face its two edge rays at unit eye depth.
struct Face {
    std::string name;
    glm::dvec3 normal{0.0};
    double offset = 0.0;
    bool side = true;
    glm::dvec3 edge0{0.0}, edge1{0.0};
};

std::array<Face, 5> FrustumFaces(const ViewFrustum& frustum) {
    const double t = frustum.TanHalfFovY(), at = frustum.aspect * t;
    auto edge = [&](double sx, double sy) { return glm::dvec3(sx * at, sy * t, -1.0); };
    return {{
        {"top", glm::normalize(glm::dvec3(0.0, 1.0, t)), 0.0, true, edge(-1, 1), edge(1, 1)},
        {"bottom", glm::normalize(glm::dvec3(0.0, -1.0, t)), 0.0, true, edge(-1, -1), edge(1, -1)},
        {"right", glm::normalize(glm::dvec3(1.0, 0.0, at)), 0.0, true, edge(1, -1), edge(1, 1)},
        {"left", glm::normalize(glm::dvec3(-1.0, 0.0, at)), 0.0, true, edge(-1, -1), edge(-1, 1)},
        {"near", glm::dvec3(0.0, 0.0, 1.0), frustum.nearPlane, false, {}, {}},
    }};
}

// One map of a scheme, the vertices where its maxima lie, and the region it serves: samples
// with eye depth in [depthLo, depthHi] (ZP), or whose light ray crosses face `face` at such a
// depth (FP).
struct Partition {
    std::string label;
    WarpedMap map;
    std::vector<glm::dvec3> esVertices;
    int face = -1;
    double depthLo = 0.0, depthHi = 0.0;
};

// n' for a map whose depth range along its frame's axis is [lo, hi]: eq. 11 divided by sin γ
// (Wimmer et al.'s general-γ LiSPSM); +∞ when the axis is parallel to the light.
double SchemeWarpOffset(double eta, double lo, double hi, double sinGamma) {
    if (eta == -1.0 || sinGamma < kMinSinGamma) return kInf;
    return WarpOffsetFromEta(eta, lo, hi) / sinGamma;
}

std::string PieceLabel(const std::string& what, int i, int k) {
    return what + " z " + std::to_string(i + 1) + "/" + std::to_string(k);
}

std::vector<Partition> ZPartitions(const ViewFrustum& frustum, const glm::dvec3& y,
                                   const Scheme& scheme) {
    const LightFrame frame = MakeLightFrame(y, kEsView);
    const int k = scheme.zPartitions;
    const std::vector<double> depths = ZPartitionDepths(frustum.nearPlane, frustum.farPlane, k);
    std::vector<Partition> partitions;
    for (int i = 0; i < k; ++i) {
        Partition p;
        p.label = "z " + std::to_string(i + 1) + "/" + std::to_string(k);
        p.esVertices = SubFrustumCorners(frustum, depths[i], depths[i + 1]);
        const double nPrime =
            SchemeWarpOffset(scheme.eta, depths[i], depths[i + 1], frame.sinGamma);
        p.map = FitWarpedMap(frame, p.esVertices, nPrime);
        p.depthLo = depths[i];
        p.depthHi = depths[i + 1];
        partitions.push_back(std::move(p));
    }
    return partitions;
}

// Whether face F gets maps: front faces (n·y > 0) when v·y ≤ 0, back faces otherwise.
bool FaceChosen(const Face& face, const glm::dvec3& y) {
    const double c = glm::dot(face.normal, y);
    return glm::dot(kEsView, y) <= 0.0 ? c > kEdgeOnCosine : c < -kEdgeOnCosine;
}

// §5.1: z along the bisector of the side edges projected perpendicular to the light.
glm::dvec3 FaceAxis(const Face& face, const glm::dvec3& y) {
    glm::dvec3 sum(0.0);
    for (const glm::dvec3& e : {face.edge0, face.edge1}) {
        const glm::dvec3 projected = e - glm::dot(e, y) * y;
        const double length = glm::length(projected);
        if (length > 0.0) sum += projected / length;  // zero: that edge is parallel to the light
    }
    return glm::normalize(sum);
}

void AddSideFacePartitions(const ViewFrustum& frustum, const glm::dvec3& y, const Scheme& scheme,
                           const Face& face, int faceIndex, std::vector<Partition>* out) {
    const glm::dvec3 axis = FaceAxis(face, y);
    const LightFrame frame = MakeLightFrame(y, axis);
    const int k = scheme.zPartitions;
    const std::vector<double> depths = ZPartitionDepths(frustum.nearPlane, frustum.farPlane, k);
    for (int i = 0; i < k; ++i) {
        Partition p;
        p.label = PieceLabel(face.name, i, k);
        p.esVertices = {depths[i] * face.edge0, depths[i] * face.edge1, depths[i + 1] * face.edge0,
                        depths[i + 1] * face.edge1};
        // Wimmer's z_n, z_f: the piece's depth range along the face's axis (> 0: the projected
        // edges are within 90° of their bisector).
        double lo = kInf, hi = -kInf;
        for (const glm::dvec3& v : p.esVertices) {
            lo = std::min(lo, glm::dot(v, axis));
            hi = std::max(hi, glm::dot(v, axis));
        }
        p.map =
            FitWarpedMap(frame, p.esVertices, SchemeWarpOffset(scheme.eta, lo, hi, frame.sinGamma));
        p.face = faceIndex;
        p.depthLo = depths[i];
        p.depthHi = depths[i + 1];
        out->push_back(std::move(p));
    }
}

std::vector<Partition> FacePartitions(const ViewFrustum& frustum, const glm::dvec3& y,
                                      const Scheme& scheme) {
    const std::array<Face, 5> faces = FrustumFaces(frustum);
    std::vector<Partition> partitions;
    for (int f = 0; f < static_cast<int>(faces.size()); ++f) {
        const Face& face = faces[f];
        if (!FaceChosen(face, y)) continue;
        if (face.side) {
            AddSideFacePartitions(frustum, y, scheme, face, f, &partitions);
        } else if (scheme.nearFace) {
            Partition p;
            p.label = face.name;
            p.esVertices = SubFrustumCorners(frustum, frustum.nearPlane, frustum.nearPlane);
            p.esVertices.resize(4);
            p.map = FitWarpedMap(MakeLightFrame(y, kEsView), p.esVertices, kInf);
            p.face = f;
            p.depthLo = p.depthHi = frustum.nearPlane;
            partitions.push_back(std::move(p));
        }
    }
    return partitions;
}

glm::dvec3 CheckedLight(const glm::dvec3& esToLight) {
    const double length = glm::length(esToLight);
    Require(std::isfinite(length) && length > 0.0, "light direction",
            "must be a finite nonzero vector, got (" + Num(esToLight.x) + ", " + Num(esToLight.y) +
                ", " + Num(esToLight.z) + ")");
    return esToLight / length;
}

std::vector<Partition> SchemePartitions(const ViewFrustum& frustum, const glm::dvec3& esToLight,
                                        const Scheme& scheme) {
    ValidateFrustum(frustum);
    ValidateScheme(scheme);
    const glm::dvec3 y = CheckedLight(esToLight);
    return scheme.facePartitioning ? FacePartitions(frustum, y, scheme)
                                   : ZPartitions(frustum, y, scheme);
}

MapStorage MakeMapStorage(const ViewFrustum& frustum, const Partition& partition,
                          const ErrorPair& maxErrors) {
    MapStorage m;
    m.label = partition.label;
    m.nPrime = partition.map.nPrime;
    m.maxErrors = maxErrors;
    m.storage = maxErrors.x * maxErrors.z / frustum.aspect;
    return m;
}

// The central-difference step for a map: small against the nearest distance to the warp's
// centre (n') and the body's depth (5-point stencil: relative truncation ~ (step/n')⁴).
double DifferenceStep(const WarpedMap& map) {
    const double depth = map.zHi - map.zLo;
    return 1e-3 * (std::isinf(map.nPrime) ? depth : std::min(map.nPrime, depth));
}

// The samples each partition serves (see Partition).
std::vector<std::vector<glm::dvec3>> AssignSamples(const ViewFrustum& frustum, const glm::dvec3& y,
                                                   const std::vector<Partition>& partitions,
                                                   std::span<const glm::dvec3> esSamples,
                                                   bool byFace) {
    const double tolerance = kTieTolerance * frustum.farPlane;
    std::vector<std::vector<glm::dvec3>> assigned(partitions.size());
    const std::array<Face, 5> faces = FrustumFaces(frustum);
    // Toward the chosen faces: to the light (front faces) or away from it (back faces).
    const glm::dvec3 u = glm::dot(kEsView, y) <= 0.0 ? y : -y;
    for (const glm::dvec3& p : esSamples) {
        if (!byFace) {
            const double depth = glm::dot(p, kEsView);
            for (std::size_t i = 0; i < partitions.size(); ++i)
                if (depth >= partitions[i].depthLo - tolerance &&
                    depth <= partitions[i].depthHi + tolerance)
                    assigned[i].push_back(p);
            continue;
        }
        // Where the ray p + t u leaves the frustum: the smallest t over the faces it heads out
        // of (the far face never is one, see the top of the file).
        std::array<double, 5> t;
        double tMin = kInf;
        for (std::size_t f = 0; f < faces.size(); ++f) {
            const double c = glm::dot(faces[f].normal, u);
            t[f] = c > kEdgeOnCosine ? -(glm::dot(faces[f].normal, p) + faces[f].offset) / c : kInf;
            tMin = std::min(tMin, t[f]);
        }
        for (std::size_t i = 0; i < partitions.size(); ++i) {
            const int f = partitions[i].face;
            if (!(t[f] <= tMin + tolerance)) continue;
            const double depth = glm::dot(p + t[f] * u, kEsView);
            if (depth >= partitions[i].depthLo - tolerance &&
                depth <= partitions[i].depthHi + tolerance)
                assigned[i].push_back(p);
        }
    }
    return assigned;
}

// Bisection on ln α for the depth ratio where ZP (4m maps) and FP + ZP + W (m per face) cross
// with the light behind, by the vertex rule.
double EvaluatedCrossover(const ViewFrustum& shape, int m) {
    const glm::dvec3 behind = DirectionToLight(0.0);
    auto difference = [&](double logRatio) {
        ViewFrustum frustum = shape;
        frustum.nearPlane = 1.0;
        frustum.farPlane = std::exp(logRatio);
        return EvaluateScheme(frustum, behind, Scheme::Zp(4 * m)).storage -
               EvaluateScheme(frustum, behind, Scheme::FpZpWarp(m)).storage;
    };
    double lo = 1e-6, hi = 1.0;  // ZP needs more at α → 1 (4m against 1)
    while (difference(hi) > 0.0) {
        lo = hi;
        hi *= 2.0;
        Require(hi < 600.0, "crossover", "not bracketed below f/n = e^600");
    }
    for (int iteration = 0; iteration < 200 && hi - lo > 1e-15 * hi; ++iteration) {
        const double mid = 0.5 * (lo + hi);
        (difference(mid) > 0.0 ? lo : hi) = mid;
    }
    return std::exp(0.5 * (lo + hi));
}

}  // namespace

// ---------------------------------------------------------------------------------------------

double ViewFrustum::TanHalfFovY() const { return std::tan(fovYDeg * kPi / 360.0); }

StorageFactorError::StorageFactorError(const std::string& quantity, const std::string& reason)
    : std::invalid_argument(quantity + ": " + reason), quantity_(quantity) {}

void ValidateFrustum(const ViewFrustum& frustum) {
    Require(std::isfinite(frustum.fovYDeg) && frustum.fovYDeg > 0.0 && frustum.fovYDeg < 180.0,
            "field of view", "must be in (0, 180) degrees, got " + Num(frustum.fovYDeg));
    Require(std::isfinite(frustum.aspect) && frustum.aspect > 0.0, "aspect",
            "must be finite and > 0, got " + Num(frustum.aspect));
    CheckNearFar(frustum.nearPlane, frustum.farPlane);
}

glm::dvec3 DirectionToLight(double gammaDeg, double azimuthDeg) {
    Require(std::isfinite(gammaDeg) && gammaDeg >= 0.0 && gammaDeg <= 180.0, "light angle gamma",
            "must be in [0, 180] degrees, got " + Num(gammaDeg));
    Require(std::isfinite(azimuthDeg), "light azimuth", "must be finite, got " + Num(azimuthDeg));
    const glm::dvec2 g = CosSinDeg(gammaDeg), phi = CosSinDeg(azimuthDeg);
    return -g.x * kEsView + g.y * (phi.x * kEsUp + phi.y * kEsRight);
}

// --- Light overhead ---

double LispsmWarpOffset(double nearPlane, double farPlane) {
    CheckNearFar(nearPlane, farPlane);
    return nearPlane + std::sqrt(farPlane * nearPlane);
}

double WarpOffsetFromEta(double eta, double nearPlane, double farPlane) {
    CheckNearFar(nearPlane, farPlane);
    Require(eta >= -1.0 && eta <= 1.0, "warp parameter eta", "must be in [-1, 1], got " + Num(eta));
    const double alpha = farPlane / nearPlane, root = std::sqrt(alpha);
    if (eta == -1.0) return kInf;
    if (eta <= 0.0) return nearPlane * ((1.0 + root) - eta * (alpha - 1.0)) / (1.0 + eta);
    return nearPlane * (1.0 + root) / (1.0 + eta * root);
}

double EtaFromWarpOffset(double nPrime, double nearPlane, double farPlane) {
    CheckNearFar(nearPlane, farPlane);
    CheckOverheadWarpOffset(nPrime, nearPlane);
    const double n = nearPlane, f = farPlane, lispsm = LispsmWarpOffset(n, f);
    const double gLispsm = 1.0 / std::sqrt(f * n), gEnds = 1.0 / n;  // g(L); g(n) = g(∞)
    if (std::isinf(nPrime)) return -1.0;
    if (nPrime > lispsm) return (gLispsm - nPrime / (n * (nPrime + f - n))) / (gEnds - gLispsm);
    return ((nPrime + f - n) / (f * nPrime) - gLispsm) / (gEnds - gLispsm);
}

ErrorPair OverheadErrors(const ViewFrustum& frustum, double nPrime, double z) {
    ValidateFrustum(frustum);
    const double n = frustum.nearPlane, f = frustum.farPlane;
    CheckOverheadWarpOffset(nPrime, n);
    Require(z >= n && z <= f, "depth z",
            "must be in [n, f] = [" + Num(n) + ", " + Num(f) + "], got " + Num(z));
    // z'/n' and z'/f' (both 1 for the unwarped map).
    const double overNear = std::isinf(nPrime) ? 1.0 : 1.0 + (z - n) / nPrime;
    const double overFar = std::isinf(nPrime) ? 1.0 : (nPrime + z - n) / (nPrime + f - n);
    const double c = (f - n) / (2.0 * frustum.TanHalfFovY());
    return {frustum.aspect * f * overFar / z, c * overNear * overFar / z};
}

ErrorPair OverheadMaxErrors(const ViewFrustum& frustum, double nPrime) {
    ValidateFrustum(frustum);
    CheckOverheadWarpOffset(nPrime, frustum.nearPlane);
    const double n = frustum.nearPlane, f = frustum.farPlane;
    const bool farIsWorst = nPrime <= LispsmWarpOffset(n, f);
    return {OverheadErrors(frustum, nPrime, n).x,
            OverheadErrors(frustum, nPrime, farIsWorst ? f : n).z};
}

double OverheadStorageFactor(const ViewFrustum& frustum, double nPrime) {
    ValidateFrustum(frustum);
    const double n = frustum.nearPlane, f = frustum.farPlane;
    CheckOverheadWarpOffset(nPrime, n);
    const double base = (f / n - 1.0) / (2.0 * frustum.TanHalfFovY());
    if (nPrime <= LispsmWarpOffset(n, f)) return base;
    const double shrink = std::isinf(nPrime) ? 1.0 : 1.0 / (1.0 + (f - n) / nPrime);  // n'/f'
    return base * shrink * shrink * f / n;
}

double OptimalStorageFactor(const ViewFrustum& frustum) {
    ValidateFrustum(frustum);
    return std::log(frustum.DepthRatio()) / (2.0 * frustum.TanHalfFovY());
}

std::vector<double> ZPartitionDepths(double nearPlane, double farPlane, int k) {
    CheckNearFar(nearPlane, farPlane);
    CheckPartitions(k, "z-partitions k");
    std::vector<double> depths(k + 1);
    const double logRatio = std::log(farPlane / nearPlane);
    for (int i = 0; i <= k; ++i) depths[i] = nearPlane * std::exp(logRatio * i / k);
    depths.front() = nearPlane;
    depths.back() = farPlane;
    return depths;
}

double ZpOverheadStorageFactor(const ViewFrustum& frustum, int k) {
    ValidateFrustum(frustum);
    CheckPartitions(k, "z-partitions k");
    const double rhoMinusOne = RhoMinusOne(frustum.DepthRatio(), k);
    return k * (1.0 + rhoMinusOne) * rhoMinusOne / (2.0 * frustum.TanHalfFovY());
}

double ZpWarpOverheadStorageFactor(const ViewFrustum& frustum, int k) {
    ValidateFrustum(frustum);
    CheckPartitions(k, "z-partitions k");
    return k * RhoMinusOne(frustum.DepthRatio(), k) / (2.0 * frustum.TanHalfFovY());
}

double ZpBehindStorageFactor(const ViewFrustum& frustum, int k) {
    ValidateFrustum(frustum);
    CheckPartitions(k, "z-partitions k");
    return k * std::exp(2.0 * std::log(frustum.DepthRatio()) / k);
}

double FpZpWarpBehindStorageFactor(const ViewFrustum& frustum, int k) {
    ValidateFrustum(frustum);
    CheckPartitions(k, "z-partitions k");
    return 2.0 * k * RhoMinusOne(frustum.DepthRatio(), k) + 1.0;
}

double ZpFpCrossoverDepthRatio(int facePartitions) {
    Require(facePartitions >= 1 && facePartitions <= kMaxCrossoverPartitions, "face z-partitions m",
            "must be in [1, " + std::to_string(kMaxCrossoverPartitions) + "], got " +
                std::to_string(facePartitions));
    const double m = facePartitions;
    return std::pow(1.0 + std::sqrt(2.0 - 1.0 / (2.0 * m)), 2.0 * m);
}

// --- General light directions ---

glm::dvec3 LightFrame::ToLight(const glm::dvec3& esPoint) const {
    return {glm::dot(esPoint, x), glm::dot(esPoint, y), glm::dot(esPoint, z)};
}

LightFrame MakeLightFrame(const glm::dvec3& esToLight, const glm::dvec3& esAxis) {
    LightFrame frame;
    frame.y = CheckedLight(esToLight);
    const double axisLength = glm::length(esAxis);
    Require(std::isfinite(axisLength) && axisLength > 0.0, "light-space axis",
            "must be a finite nonzero vector");
    const glm::dvec3 axis = esAxis / axisLength;
    glm::dvec3 z = axis - glm::dot(axis, frame.y) * frame.y;
    frame.sinGamma = glm::length(z);
    if (frame.sinGamma < kMinSinGamma) {
        frame.sinGamma = 0.0;
        z = kEsUp - glm::dot(kEsUp, frame.y) * frame.y;
        if (glm::length(z) < 0.5) z = kEsRight - glm::dot(kEsRight, frame.y) * frame.y;
    }
    frame.z = glm::normalize(z);
    frame.x = glm::cross(frame.y, frame.z);
    return frame;
}

glm::dvec2 WarpedMap::Map(const glm::dvec3& esPoint) const {
    const glm::dvec3 ls = frame.ToLight(esPoint);
    const double depth = zHi - zLo, fromNear = ls.z - zLo;
    if (std::isinf(nPrime)) return {(ls.x - slopeLo) / (slopeHi - slopeLo), fromNear / depth};
    const double zPrime = nPrime + fromNear;
    return {(ls.x / zPrime - slopeLo) / (slopeHi - slopeLo),
            fromNear * (nPrime + depth) / (depth * zPrime)};
}

ErrorPair WarpedMap::BeamWidths(const glm::dvec3& esPoint) const {
    const double depth = zHi - zLo;
    if (std::isinf(nPrime)) return {slopeHi - slopeLo, depth};
    const double zPrime = nPrime + (frame.ToLight(esPoint).z - zLo);
    return {zPrime * (slopeHi - slopeLo), (zPrime / nPrime) * (zPrime / (nPrime + depth)) * depth};
}

WarpedMap FitWarpedMap(const LightFrame& frame, std::span<const glm::dvec3> esBody, double nPrime) {
    Require(!esBody.empty(), "body", "has no vertices");
    Require(nPrime > 0.0, "warp offset n'", "must be > 0 or +inf, got " + Num(nPrime));
    WarpedMap map;
    map.frame = frame;
    map.nPrime = nPrime;
    map.zLo = kInf;
    map.zHi = -kInf;
    for (const glm::dvec3& p : esBody) {
        map.zLo = std::min(map.zLo, glm::dot(p, frame.z));
        map.zHi = std::max(map.zHi, glm::dot(p, frame.z));
    }
    map.slopeLo = kInf;
    map.slopeHi = -kInf;
    for (const glm::dvec3& p : esBody) {
        const glm::dvec3 ls = frame.ToLight(p);
        const double slope = std::isinf(nPrime) ? ls.x : ls.x / (nPrime + (ls.z - map.zLo));
        map.slopeLo = std::min(map.slopeLo, slope);
        map.slopeHi = std::max(map.slopeHi, slope);
    }
    Require(map.zHi > map.zLo && map.slopeHi > map.slopeLo, "body",
            "has no extent across the light (a flat projection)");
    return map;
}

double ImageBeamWidth(const ViewFrustum& frustum, const glm::dvec3& esPoint) {
    const double depth = glm::dot(esPoint, kEsView);
    Require(depth > 0.0, "point", "must be in front of the eye, eye depth " + Num(depth));
    return 2.0 * frustum.TanHalfFovY() * depth;
}

namespace {

// The largest w_l / w_i over the vertices of either map kind (both have BeamWidths).
template <class Map>
ErrorPair MaxErrorsAtVertices(const ViewFrustum& frustum, const Map& map,
                              std::span<const glm::dvec3> esVertices) {
    Require(!esVertices.empty(), "vertices", "none given");
    ErrorPair worst;
    for (const glm::dvec3& p : esVertices) {
        const ErrorPair w = map.BeamWidths(p);
        const double wi = ImageBeamWidth(frustum, p);
        worst.x = std::max(worst.x, w.x / wi);
        worst.z = std::max(worst.z, w.z / wi);
    }
    return worst;
}

}  // namespace

ErrorPair VertexMaxErrors(const ViewFrustum& frustum, const WarpedMap& map,
                          std::span<const glm::dvec3> esVertices) {
    return MaxErrorsAtVertices(frustum, map, esVertices);
}

ErrorPair SampledMaxErrors(const ViewFrustum& frustum, const LightFrame& frame,
                           const std::function<glm::dvec2(const glm::dvec3&)>& map,
                           std::span<const glm::dvec3> esSamples, double step) {
    Require(!esSamples.empty(), "samples", "none given");
    Require(std::isfinite(step) && step > 0.0, "difference step",
            "must be finite and > 0, got " + Num(step));
    // d/dh of component c of map(p + h e) at h = 0, 5-point stencil (error O(step⁴)).
    auto derivative = [&](const glm::dvec3& p, const glm::dvec3& e, int c) {
        return (-map(p + 2.0 * step * e)[c] + 8.0 * map(p + step * e)[c] -
                8.0 * map(p - step * e)[c] + map(p - 2.0 * step * e)[c]) /
               (12.0 * step);
    };
    ErrorPair worst;
    for (const glm::dvec3& p : esSamples) {
        const double dsdx = derivative(p, frame.x, 0), dtdz = derivative(p, frame.z, 1);
        Require(std::isfinite(dsdx) && std::isfinite(dtdz) && dsdx != 0.0 && dtdz != 0.0, "map",
                "has a zero or non-finite derivative at a sample");
        const double wi = ImageBeamWidth(frustum, p);
        worst.x = std::max(worst.x, 1.0 / std::abs(dsdx) / wi);
        worst.z = std::max(worst.z, 1.0 / std::abs(dtdz) / wi);
    }
    return worst;
}

std::vector<glm::dvec3> FrustumSamples(const ViewFrustum& frustum, int perAxis, int k) {
    ValidateFrustum(frustum);
    CheckCount(perAxis, 2, "samples per axis");
    const std::vector<double> bounds = ZPartitionDepths(frustum.nearPlane, frustum.farPlane, k);
    std::vector<double> depths = {bounds.front()};
    for (int i = 0; i < k; ++i)
        for (int j = 1; j < perAxis; ++j)
            depths.push_back(j + 1 == perAxis
                                 ? bounds[i + 1]
                                 : bounds[i] * std::pow(bounds[i + 1] / bounds[i],
                                                        static_cast<double>(j) / (perAxis - 1)));
    std::vector<glm::dvec3> samples;
    for (double depth : depths)
        for (int row = 0; row < perAxis; ++row)
            for (int col = 0; col < perAxis; ++col)
                samples.push_back(EyePoint(frustum, -1.0 + 2.0 * col / (perAxis - 1),
                                           -1.0 + 2.0 * row / (perAxis - 1), depth));
    return samples;
}

glm::dvec2 LogWarpedMap::Map(const glm::dvec3& esPoint) const {
    const WarpedMap& w = perspective;
    const double depth = w.zHi - w.zLo, fromNear = w.frame.ToLight(esPoint).z - w.zLo;
    const glm::dvec2 st = w.Map(esPoint);
    if (std::isinf(w.nPrime)) return st;
    return {st.x, std::log1p(fromNear / w.nPrime) / std::log1p(depth / w.nPrime)};
}

ErrorPair LogWarpedMap::BeamWidths(const glm::dvec3& esPoint) const {
    const WarpedMap& w = perspective;
    const ErrorPair widths = w.BeamWidths(esPoint);
    if (std::isinf(w.nPrime)) return widths;
    const double depth = w.zHi - w.zLo;
    const double zeta = w.nPrime + (w.frame.ToLight(esPoint).z - w.zLo);
    return {widths.x, zeta * std::log1p(depth / w.nPrime)};
}

LogWarpedMap FitLogWarpedMap(const LightFrame& frame, std::span<const glm::dvec3> esBody,
                             double nPrime) {
    return {FitWarpedMap(frame, esBody, nPrime)};
}

ErrorPair LogVertexMaxErrors(const ViewFrustum& frustum, const LogWarpedMap& map,
                             std::span<const glm::dvec3> esVertices) {
    return MaxErrorsAtVertices(frustum, map, esVertices);
}

double LogPsmStorageFactor(const ViewFrustum& frustum, const glm::dvec3& esToLight) {
    ValidateFrustum(frustum);
    const LightFrame frame = MakeLightFrame(esToLight, kEsView);
    const std::vector<glm::dvec3> corners =
        SubFrustumCorners(frustum, frustum.nearPlane, frustum.farPlane);
    const double nPrime =
        SchemeWarpOffset(1.0, frustum.nearPlane, frustum.farPlane, frame.sinGamma);
    const ErrorPair worst =
        LogVertexMaxErrors(frustum, FitLogWarpedMap(frame, corners, nPrime), corners);
    return worst.x * worst.z / frustum.aspect;
}

double StorageFactorForWarpOffset(const ViewFrustum& frustum, const glm::dvec3& esToLight,
                                  double nPrime) {
    ValidateFrustum(frustum);
    const LightFrame frame = MakeLightFrame(esToLight, kEsView);
    const std::vector<glm::dvec3> corners =
        SubFrustumCorners(frustum, frustum.nearPlane, frustum.farPlane);
    const ErrorPair worst = VertexMaxErrors(frustum, FitWarpedMap(frame, corners, nPrime), corners);
    return worst.x * worst.z / frustum.aspect;
}

// --- Schemes ---

void ValidateScheme(const Scheme& scheme) {
    CheckPartitions(scheme.zPartitions, "z-partitions k");
    Require(scheme.eta >= -1.0 && scheme.eta <= 1.0, "warp parameter eta",
            "must be in [-1, 1], got " + Num(scheme.eta));
}

SchemeStorage EvaluateScheme(const ViewFrustum& frustum, const glm::dvec3& esToLight,
                             const Scheme& scheme) {
    SchemeStorage result;
    for (const Partition& p : SchemePartitions(frustum, esToLight, scheme)) {
        result.maps.push_back(
            MakeMapStorage(frustum, p, VertexMaxErrors(frustum, p.map, p.esVertices)));
        result.storage += result.maps.back().storage;
    }
    return result;
}

SchemeStorage SampleScheme(const ViewFrustum& frustum, const glm::dvec3& esToLight,
                           const Scheme& scheme, int perAxis) {
    const std::vector<Partition> partitions = SchemePartitions(frustum, esToLight, scheme);
    const std::vector<glm::dvec3> samples = FrustumSamples(frustum, perAxis, scheme.zPartitions);
    const auto assigned = AssignSamples(frustum, CheckedLight(esToLight), partitions, samples,
                                        scheme.facePartitioning);
    SchemeStorage result;
    for (std::size_t i = 0; i < partitions.size(); ++i) {
        const WarpedMap& map = partitions[i].map;
        const ErrorPair worst = SampledMaxErrors(
            frustum, map.frame, [&](const glm::dvec3& p) { return map.Map(p); }, assigned[i],
            DifferenceStep(map));
        result.maps.push_back(MakeMapStorage(frustum, partitions[i], worst));
        result.storage += result.maps.back().storage;
    }
    return result;
}

// --- Figure data ---

std::vector<WarpSweepPoint> WarpSweep(const ViewFrustum& frustum, int count) {
    ValidateFrustum(frustum);
    CheckCount(count, 2, "sweep count");
    std::vector<WarpSweepPoint> points;
    for (int i = 0; i < count; ++i) {
        WarpSweepPoint p;
        p.eta = i + 1 == count ? 1.0 : -1.0 + 2.0 * i / (count - 1);
        p.nPrime = WarpOffsetFromEta(p.eta, frustum.nearPlane, frustum.farPlane);
        p.maxErrors = OverheadMaxErrors(frustum, p.nPrime);
        p.storage = OverheadStorageFactor(frustum, p.nPrime);
        points.push_back(p);
    }
    return points;
}

std::vector<ErrorProfilePoint> ErrorProfile(const ViewFrustum& frustum, double nPrime, int count) {
    ValidateFrustum(frustum);
    CheckCount(count, 2, "profile count");
    const double n = frustum.nearPlane, f = frustum.farPlane;
    std::vector<ErrorProfilePoint> points;
    for (int i = 0; i < count; ++i) {
        const double z = i + 1 == count ? f : n + (f - n) * i / (count - 1);
        points.push_back({z, OverheadErrors(frustum, nPrime, z)});
    }
    return points;
}

const HemisphereCell& HemisphereGrid::Max() const {
    const HemisphereCell* best = nullptr;
    for (const HemisphereCell& c : cells)
        if (c.inside && (best == nullptr || c.storage > best->storage)) best = &c;
    Require(best != nullptr, "hemisphere grid", "has no inside cell");
    return *best;
}

HemisphereGrid StorageHemisphere(const ViewFrustum& frustum, const Scheme& scheme, int size) {
    ValidateFrustum(frustum);
    ValidateScheme(scheme);
    Require(size >= 1 && size <= 4096, "hemisphere size",
            "must be in [1, 4096], got " + std::to_string(size));
    HemisphereGrid grid;
    grid.size = size;
    for (int row = 0; row < size; ++row)
        for (int col = 0; col < size; ++col) {
            HemisphereCell cell;
            cell.gx = -1.0 + (2.0 * col + 1.0) / size;
            cell.gy = 1.0 - (2.0 * row + 1.0) / size;
            const double up2 = 1.0 - cell.gx * cell.gx - cell.gy * cell.gy;
            cell.inside = up2 >= 0.0;
            if (cell.inside) {
                cell.esToLight = cell.gx * kEsView + cell.gy * kEsRight + std::sqrt(up2) * kEsUp;
                cell.storage = EvaluateScheme(frustum, cell.esToLight, scheme).storage;
            }
            grid.cells.push_back(cell);
        }
    return grid;
}

std::vector<PartitionSweepPoint> PartitionSweep(const ViewFrustum& frustum, int maxK) {
    ValidateFrustum(frustum);
    CheckPartitions(maxK, "largest k");
    const glm::dvec3 overhead = DirectionToLight(90.0);
    std::vector<PartitionSweepPoint> points;
    for (int k = 1; k <= maxK; ++k)
        points.push_back({k, EvaluateScheme(frustum, overhead, Scheme::Zp(k)).storage,
                          EvaluateScheme(frustum, overhead, Scheme::ZpWarp(k)).storage,
                          OptimalStorageFactor(frustum)});
    return points;
}

std::vector<MapCountPoint> MapCountSweep(const ViewFrustum& frustum, int maxMaps) {
    ValidateFrustum(frustum);
    CheckPartitions(maxMaps, "largest map count");
    const glm::dvec3 overhead = DirectionToLight(90.0), behind = DirectionToLight(0.0);
    std::vector<MapCountPoint> points;
    for (int j = 1; j <= maxMaps; ++j) {
        MapCountPoint p;
        p.maps = j;
        p.zpOverhead = EvaluateScheme(frustum, overhead, Scheme::Zp(j)).storage;
        p.zpWarpOverhead = EvaluateScheme(frustum, overhead, Scheme::ZpWarp(j)).storage;
        p.zpBehind = EvaluateScheme(frustum, behind, Scheme::Zp(j)).storage;
        p.zpWarpBehind = EvaluateScheme(frustum, behind, Scheme::ZpWarp(j)).storage;
        if (j % 4 == 0) {
            p.fpOverhead = EvaluateScheme(frustum, overhead, Scheme::FpZpWarp(j / 4)).storage;
            p.fpBehind = EvaluateScheme(frustum, behind, Scheme::FpZpWarp(j / 4)).storage;
        }
        points.push_back(p);
    }
    return points;
}

std::vector<CrossoverPoint> ZpFpCrossover(const ViewFrustum& frustum, int maxFacePartitions) {
    ValidateFrustum(frustum);
    ZpFpCrossoverDepthRatio(maxFacePartitions);  // validates the range
    std::vector<CrossoverPoint> points;
    for (int m = 1; m <= maxFacePartitions; ++m)
        points.push_back({4 * m, m, ZpFpCrossoverDepthRatio(m), EvaluatedCrossover(frustum, m)});
    return points;
}

}  // namespace lexel::spatial
