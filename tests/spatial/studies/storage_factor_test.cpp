// Lloyd et al. 2006's storage factor: every closed form (eqs. 7–12, 17–21, Appendices B–C, the
// Fig. 13 crossover) against the dense numeric evaluation (central differences of the fitted
// map over a lattice of the frustum, relative 1e-6), the vertex rule of §4.4 against the same
// evaluation for random light directions, and the values the paper prints for Fig. 12.
#include "lexel/spatial/studies/storage_factor.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <sstream>
#include <string>

namespace lexel::spatial {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// Closed form against dense numeric evaluation (5-point differences, step 1e-3 of the nearest
// scale): the relative agreement a closed form must reach.
constexpr double kNumericTolerance = 1e-6;
const glm::dvec3 kEsView{0.0, 0.0, -1.0};

void ExpectRelative(double actual, double expected, double tolerance, const std::string& what) {
    EXPECT_NEAR(actual, expected, tolerance * std::abs(expected)) << what;
}

std::string Describe(const ViewFrustum& f) {
    std::ostringstream out;
    out << "fovY " << f.fovYDeg << "°, aspect " << f.aspect << ", n " << f.nearPlane << ", f "
        << f.farPlane;
    return out.str();
}

// The numeric M_x, M_z of the whole-frustum map with warp offset n' and the light overhead.
ErrorPair SampledOverhead(const ViewFrustum& frustum, double nPrime, int perAxis = 9) {
    const LightFrame frame = MakeLightFrame(DirectionToLight(90.0), kEsView);
    const std::vector<glm::dvec3> corners = FrustumSamples(frustum, 2, 1);
    const WarpedMap map = FitWarpedMap(frame, corners, nPrime);
    const std::vector<glm::dvec3> samples = FrustumSamples(frustum, perAxis, 1);
    const double step = 1e-3 * std::min(nPrime, frustum.farPlane - frustum.nearPlane);
    return SampledMaxErrors(
        frustum, frame, [&](const glm::dvec3& p) { return map.Map(p); }, samples, step);
}

// --- Domain errors name the quantity ---

std::string QuantityOf(const std::function<void()>& call) {
    try {
        call();
    } catch (const StorageFactorError& e) {
        return e.quantity();
    }
    return "(no error)";
}

TEST(StorageFactorInput, BadInputNamesTheQuantity) {
    const ViewFrustum good{60.0, 1.0, 1.0, 100.0};
    ViewFrustum f = good;
    f.farPlane = 1.0;
    EXPECT_EQ(QuantityOf([&] { ValidateFrustum(f); }), "far plane f");
    f = good;
    f.nearPlane = 0.0;
    EXPECT_EQ(QuantityOf([&] { ValidateFrustum(f); }), "near plane n");
    f = good;
    f.fovYDeg = 190.0;
    EXPECT_EQ(QuantityOf([&] { ValidateFrustum(f); }), "field of view");
    f = good;
    f.aspect = std::numeric_limits<double>::quiet_NaN();
    EXPECT_EQ(QuantityOf([&] { ValidateFrustum(f); }), "aspect");
    EXPECT_EQ(QuantityOf([&] { WarpOffsetFromEta(1.5, 1.0, 20.0); }), "warp parameter eta");
    EXPECT_EQ(QuantityOf([&] { OverheadStorageFactor(good, 0.5); }), "warp offset n'");
    EXPECT_EQ(QuantityOf([&] { OverheadErrors(good, 2.0, 200.0); }), "depth z");
    EXPECT_EQ(QuantityOf([&] { EvaluateScheme(good, glm::dvec3(0.0), Scheme::Zp(1)); }),
              "light direction");
    EXPECT_EQ(QuantityOf([&] { EvaluateScheme(good, glm::dvec3(0, 1, 0), Scheme::Zp(0)); }),
              "z-partitions k");
    EXPECT_EQ(QuantityOf([&] { DirectionToLight(200.0); }), "light angle gamma");
    EXPECT_EQ(QuantityOf([&] { StorageHemisphere(good, Scheme::Zp(1), 0); }), "hemisphere size");
    // One line: "<quantity>: <reason>", with the value.
    f = good;
    f.farPlane = 0.5;
    try {
        ValidateFrustum(f);
        FAIL() << "no error";
    } catch (const StorageFactorError& e) {
        EXPECT_EQ(std::string(e.what()), "far plane f: must be finite and > n = 1, got 0.5");
    }
}

// --- η (eq. 11, Appendix B) ---

TEST(StorageFactorWarpParameter, EtaEndpointsAreUnwarpedLispsmAndPsm) {
    for (const auto& [n, f] : {std::pair{1.0, 20.0}, {1.0, 100.0}, {0.3, 1000.0}, {2.0, 5.0}}) {
        EXPECT_EQ(WarpOffsetFromEta(-1.0, n, f), kInf);
        EXPECT_DOUBLE_EQ(WarpOffsetFromEta(0.0, n, f), n + std::sqrt(f * n));
        EXPECT_DOUBLE_EQ(WarpOffsetFromEta(1.0, n, f), n);
        EXPECT_DOUBLE_EQ(LispsmWarpOffset(n, f), n + std::sqrt(f * n));
        for (double eta = -0.95; eta <= 1.0; eta += 0.05)
            EXPECT_NEAR(EtaFromWarpOffset(WarpOffsetFromEta(eta, n, f), n, f), eta, 1e-12)
                << "n " << n << " f " << f << " eta " << eta;
    }
}

// Appendix B defines η so that M_z interpolates linearly between its values at n' = ∞, n'_LSPSM
// and n: the numeric M_z at n'(η) must be linear in η on each half.
TEST(StorageFactorWarpParameter, NumericMaxZErrorIsLinearInEtaOnEachHalf) {
    for (const ViewFrustum& frustum :
         {ViewFrustum{60.0, 1.0, 1.0, 20.0}, ViewFrustum{40.0, 1.3, 0.5, 50.0}}) {
        const double n = frustum.nearPlane, f = frustum.farPlane;
        const double atInf = OverheadMaxErrors(frustum, kInf).z;
        const double atLispsm = SampledOverhead(frustum, LispsmWarpOffset(n, f)).z;
        const double atPsm = SampledOverhead(frustum, n).z;
        EXPECT_NEAR(atPsm, atInf, kNumericTolerance * atInf);  // both ends: (f - n)/(2n tanθ)
        for (double eta : {-0.9, -0.6, -0.3, 0.2, 0.5, 0.8}) {
            const double sampled = SampledOverhead(frustum, WarpOffsetFromEta(eta, n, f)).z;
            const double linear = eta < 0.0 ? atLispsm - eta * (atInf - atLispsm)
                                            : atLispsm + eta * (atPsm - atLispsm);
            ExpectRelative(sampled, linear, kNumericTolerance,
                           Describe(frustum) + ", eta " + std::to_string(eta));
        }
    }
}

// --- Light overhead: eqs. 7–10, 12 against the dense evaluation ---

const std::vector<ViewFrustum>& OverheadFrusta() {
    static const std::vector<ViewFrustum> frusta = {{60.0, 1.0, 1.0, 20.0},
                                                    {60.0, 1.0, 1.0, 100.0},
                                                    {90.0, 1.0, 2.0, 200.0},
                                                    {45.0, 1.6, 0.1, 100.0},
                                                    {60.0, 1.0, 1.0, 1000.0}};
    return frusta;
}

std::vector<double> WarpOffsets(const ViewFrustum& frustum) {
    const double n = frustum.nearPlane, lispsm = LispsmWarpOffset(n, frustum.farPlane);
    return {n, 0.5 * (n + lispsm), lispsm, 1.5 * lispsm, 10.0 * lispsm, 1e6 * lispsm, kInf};
}

TEST(StorageFactorOverhead, PointErrorsMatchEqs7And8) {
    const LightFrame frame = MakeLightFrame(DirectionToLight(90.0), kEsView);
    for (const ViewFrustum& frustum : OverheadFrusta())
        for (double nPrime : WarpOffsets(frustum)) {
            const auto corners = FrustumSamples(frustum, 2, 1);
            const WarpedMap map = FitWarpedMap(frame, corners, nPrime);
            for (double u : {0.0, 0.1, 0.5, 1.0}) {
                const double z = frustum.nearPlane + u * (frustum.farPlane - frustum.nearPlane);
                const glm::dvec3 p(0.3 * z, -0.2 * z, -z);  // any lateral position
                const double step = 1e-3 * std::min(nPrime, frustum.farPlane);
                const ErrorPair sampled = SampledMaxErrors(
                    frustum, frame, [&](const glm::dvec3& q) { return map.Map(q); }, std::vector{p},
                    step);
                const ErrorPair closed = OverheadErrors(frustum, nPrime, z);
                const std::string what = Describe(frustum) + ", n' " + std::to_string(nPrime) +
                                         ", z " + std::to_string(z);
                ExpectRelative(sampled.x, closed.x, kNumericTolerance, "m_x, " + what);
                ExpectRelative(sampled.z, closed.z, kNumericTolerance, "m_z, " + what);
            }
        }
}

TEST(StorageFactorOverhead, MaximaMatchEqs9And10AndLieWhereThePaperSays) {
    for (const ViewFrustum& frustum : OverheadFrusta())
        for (double nPrime : WarpOffsets(frustum)) {
            const std::string what = Describe(frustum) + ", n' " + std::to_string(nPrime);
            const ErrorPair closed = OverheadMaxErrors(frustum, nPrime);
            const ErrorPair sampled = SampledOverhead(frustum, nPrime);
            ExpectRelative(sampled.x, closed.x, kNumericTolerance, "M_x, " + what);
            ExpectRelative(sampled.z, closed.z, kNumericTolerance, "M_z, " + what);
            // M_x at z = n; M_z at z = f up to n'_LSPSM, at z = n beyond (§4.1).
            const double n = frustum.nearPlane, f = frustum.farPlane;
            EXPECT_DOUBLE_EQ(closed.x, OverheadErrors(frustum, nPrime, n).x) << what;
            const double atNear = OverheadErrors(frustum, nPrime, n).z;
            const double atFar = OverheadErrors(frustum, nPrime, f).z;
            if (nPrime < LispsmWarpOffset(n, f)) {
                EXPECT_GT(atFar, atNear) << what;
            }
            if (nPrime > LispsmWarpOffset(n, f)) {
                EXPECT_GT(atNear, atFar) << what;
            }
            // Eq. 9 corrected: a f n' / (n (n' + f - n)).
            const double eq9 = std::isinf(nPrime)
                                   ? frustum.aspect * f / n
                                   : frustum.aspect * f * nPrime / (n * (nPrime + f - n));
            ExpectRelative(closed.x, eq9, 1e-14, what);
        }
}

TEST(StorageFactorOverhead, StorageFactorMatchesEq12TheVertexRuleAndTheDenseEvaluation) {
    for (const ViewFrustum& frustum : OverheadFrusta())
        for (double nPrime : WarpOffsets(frustum)) {
            const std::string what = Describe(frustum) + ", n' " + std::to_string(nPrime);
            const double closed = OverheadStorageFactor(frustum, nPrime);
            const ErrorPair sampled = SampledOverhead(frustum, nPrime);
            ExpectRelative(sampled.x * sampled.z / frustum.aspect, closed, kNumericTolerance, what);
            ExpectRelative(StorageFactorForWarpOffset(frustum, DirectionToLight(90.0), nPrime),
                           closed, 1e-12, what);
            const ErrorPair maxima = OverheadMaxErrors(frustum, nPrime);
            ExpectRelative(maxima.x * maxima.z / frustum.aspect, closed, 1e-12, what);
        }
}

// §4.3: PSM, LiSPSM and every n' between them need the same storage; beyond n'_LSPSM more.
TEST(StorageFactorOverhead, StorageIsConstantFromPsmToLispsm) {
    for (const ViewFrustum& frustum : OverheadFrusta()) {
        const double n = frustum.nearPlane, f = frustum.farPlane;
        const double flat = (f / n - 1.0) / (2.0 * frustum.TanHalfFovY());
        const double lispsm = LispsmWarpOffset(n, f);
        for (double u = 0.0; u <= 1.0; u += 0.125) {
            const double nPrime = n + u * (lispsm - n);
            EXPECT_NEAR(OverheadStorageFactor(frustum, nPrime), flat, 1e-12 * flat);
            const ErrorPair sampled = SampledOverhead(frustum, nPrime, 5);
            ExpectRelative(sampled.x * sampled.z / frustum.aspect, flat, kNumericTolerance,
                           Describe(frustum) + ", n' " + std::to_string(nPrime));
        }
        EXPECT_GT(OverheadStorageFactor(frustum, 1.01 * lispsm), flat * (1.0 + 1e-6));
        // Unwarped: the bracket of eq. 12 tends to f/n.
        EXPECT_NEAR(OverheadStorageFactor(frustum, kInf), flat * f / n, 1e-12 * flat * f / n);
    }
}

// --- Appendix C ---

TEST(StorageFactorOptimal, LogarithmicParameterizationMatchesTheDenseEvaluation) {
    for (const ViewFrustum& frustum : OverheadFrusta()) {
        const double n = frustum.nearPlane, f = frustum.farPlane;
        const double t = frustum.TanHalfFovY(), a = frustum.aspect;
        const LightFrame frame = MakeLightFrame(DirectionToLight(90.0), kEsView);
        // s: the view frustum itself (PSM-like in x); t = ln(z/n)/ln(f/n).
        auto logMap = [&](const glm::dvec3& p) {
            const glm::dvec3 ls = frame.ToLight(p);
            return glm::dvec2(ls.x / (2.0 * ls.z * a * t) + 0.5,
                              std::log(ls.z / n) / std::log(f / n));
        };
        const ErrorPair sampled =
            SampledMaxErrors(frustum, frame, logMap, FrustumSamples(frustum, 9, 1), 1e-3 * n);
        ExpectRelative(sampled.x * sampled.z / a, OptimalStorageFactor(frustum), kNumericTolerance,
                       Describe(frustum));
        ExpectRelative(OptimalStorageFactor(frustum), std::log(f / n) / (2.0 * t), 1e-15,
                       Describe(frustum));
    }
}

// --- LogPSM (Lloyd et al. 2008): the η = 1 warp with a logarithmic t ---

TEST(StorageFactorLogPsm, OverheadIsTheOptimalStorageFactor) {
    // Appendix C: with the light overhead the warping frustum is the view frustum (n' = n) and the
    // log map reaches S̄_opt exactly; M_x = a, M_z = ln(f/n) / (2 tanθ).
    for (const ViewFrustum& frustum : OverheadFrusta()) {
        ExpectRelative(LogPsmStorageFactor(frustum, DirectionToLight(90.0)),
                       OptimalStorageFactor(frustum), 1e-12, Describe(frustum));
        const LightFrame frame = MakeLightFrame(DirectionToLight(90.0), kEsView);
        const std::vector<glm::dvec3> corners = FrustumSamples(frustum, 2, 1);
        const LogWarpedMap map = FitLogWarpedMap(frame, corners, frustum.nearPlane);
        const ErrorPair worst = LogVertexMaxErrors(frustum, map, corners);
        ExpectRelative(worst.x, frustum.aspect, 1e-12, Describe(frustum));
        ExpectRelative(worst.z, std::log(frustum.DepthRatio()) / (2.0 * frustum.TanHalfFovY()),
                       1e-12, Describe(frustum));
    }
}

TEST(StorageFactorLogPsm, VertexRuleMatchesDenseSamplesForRandomLights) {
    std::mt19937_64 random(20080401);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int trial = 0; trial < 40; ++trial) {
        ViewFrustum f;
        f.fovYDeg = 20.0 + 100.0 * unit(random);
        f.aspect = 0.6 + 1.2 * unit(random);
        f.nearPlane = 0.1 + unit(random);
        f.farPlane = f.nearPlane * std::exp(1.0 + 6.0 * unit(random));
        const double gamma = 5.0 + 170.0 * unit(random), azimuth = 360.0 * unit(random);
        const glm::dvec3 light = DirectionToLight(gamma, azimuth);
        std::ostringstream what;
        what << "trial " << trial << ": " << Describe(f) << ", gamma " << gamma << "°, azimuth "
             << azimuth << "°";
        SCOPED_TRACE(what.str());
        const LightFrame frame = MakeLightFrame(light, kEsView);
        const std::vector<glm::dvec3> corners = FrustumSamples(f, 2, 1);
        const double nPrime = f.nearPlane / frame.sinGamma;
        const LogWarpedMap map = FitLogWarpedMap(frame, corners, nPrime);
        const ErrorPair vertices = LogVertexMaxErrors(f, map, corners);
        const double step = 1e-3 * std::min(nPrime, f.farPlane - f.nearPlane);
        const ErrorPair sampled = SampledMaxErrors(
            f, frame, [&](const glm::dvec3& p) { return map.Map(p); }, FrustumSamples(f, 7, 1),
            step);
        ExpectRelative(sampled.x, vertices.x, kNumericTolerance, "M_x");
        ExpectRelative(sampled.z, vertices.z, kNumericTolerance, "M_z");
        ExpectRelative(LogPsmStorageFactor(f, light), vertices.x * vertices.z / f.aspect, 1e-12,
                       "S̄");
    }
}

// --- Partitioning: eqs. 17–21 against the dense evaluation of the schemes ---

const std::vector<ViewFrustum>& PartitionFrusta() {
    static const std::vector<ViewFrustum> frusta = {
        {60.0, 1.0, 1.0, 1000.0}, {90.0, 1.0, 1.0, 50.0}, {40.0, 1.5, 0.2, 100.0}};
    return frusta;
}

TEST(StorageFactorPartitioning, OverheadClosedFormsMatchEqs17To19) {
    const glm::dvec3 overhead = DirectionToLight(90.0);
    for (const ViewFrustum& frustum : PartitionFrusta())
        for (int k : {1, 2, 3, 4, 8}) {
            const std::string what = Describe(frustum) + ", k " + std::to_string(k);
            const double zp = ZpOverheadStorageFactor(frustum, k);
            const double zpw = ZpWarpOverheadStorageFactor(frustum, k);
            ExpectRelative(SampleScheme(frustum, overhead, Scheme::Zp(k), 5).storage, zp,
                           kNumericTolerance, "ZP " + what);
            ExpectRelative(SampleScheme(frustum, overhead, Scheme::ZpWarp(k), 5).storage, zpw,
                           kNumericTolerance, "ZP+W " + what);
            ExpectRelative(SampleScheme(frustum, overhead, Scheme::FpZpWarp(k), 5).storage, zpw,
                           kNumericTolerance, "FP+ZP+W " + what);
            ExpectRelative(EvaluateScheme(frustum, overhead, Scheme::Zp(k)).storage, zp, 1e-12,
                           "ZP vertices " + what);
            ExpectRelative(EvaluateScheme(frustum, overhead, Scheme::ZpWarp(k)).storage, zpw, 1e-12,
                           "ZP+W vertices " + what);
            const SchemeStorage fp = EvaluateScheme(frustum, overhead, Scheme::FpZpWarp(k));
            ExpectRelative(fp.storage, zpw, 1e-12, "FP+ZP+W vertices " + what);
            EXPECT_EQ(fp.maps.size(), static_cast<std::size_t>(k)) << "only the top face";
            // The closed forms as printed: ρ = (f/n)^(1/k).
            const double rho = std::pow(frustum.DepthRatio(), 1.0 / k);
            const double twoTan = 2.0 * frustum.TanHalfFovY();
            ExpectRelative(zp, k * rho * (rho - 1.0) / twoTan, 1e-12, what);
            ExpectRelative(zpw, k * (rho - 1.0) / twoTan, 1e-12, what);
        }
}

// Eq. 20, and eq. 21 for every θ and aspect (the paper states it at θ = 45°).
TEST(StorageFactorPartitioning, BehindClosedFormsMatchEqs20And21) {
    const glm::dvec3 behind = DirectionToLight(0.0);
    std::vector<ViewFrustum> frusta = PartitionFrusta();
    frusta.push_back({90.0, 1.0, 1.0, 1000.0});  // θ = 45°: eq. 21 as printed
    for (const ViewFrustum& frustum : frusta)
        for (int k : {1, 2, 3, 4, 8}) {
            const std::string what = Describe(frustum) + ", k " + std::to_string(k);
            const double zp = ZpBehindStorageFactor(frustum, k);
            const double fp = FpZpWarpBehindStorageFactor(frustum, k);
            ExpectRelative(SampleScheme(frustum, behind, Scheme::Zp(k), 5).storage, zp,
                           kNumericTolerance, "ZP " + what);
            ExpectRelative(SampleScheme(frustum, behind, Scheme::ZpWarp(k), 5).storage, zp,
                           kNumericTolerance, "ZP+W (no warp possible) " + what);
            const SchemeStorage sampledFp = SampleScheme(frustum, behind, Scheme::FpZpWarp(k), 5);
            ExpectRelative(sampledFp.storage, fp, kNumericTolerance, "FP+ZP+W " + what);
            EXPECT_EQ(sampledFp.maps.size(), static_cast<std::size_t>(4 * k + 1)) << what;
            ExpectRelative(EvaluateScheme(frustum, behind, Scheme::FpZpWarp(k)).storage, fp, 1e-12,
                           what);
            const double rho = std::pow(frustum.DepthRatio(), 1.0 / k);
            ExpectRelative(zp, k * rho * rho, 1e-12, what);
            if (frustum.fovYDeg == 90.0 && frustum.aspect == 1.0)
                ExpectRelative(fp, 4.0 * ZpWarpOverheadStorageFactor(frustum, k) + 1.0, 1e-12,
                               "eq. 21 as printed, " + what);
        }
}

// §5.2, seams: with n'_LSPSM in every self-similar partition, all maps have the same critical
// resolution and m_z is continuous across each seam.
TEST(StorageFactorPartitioning, LispsmSeamsAreContinuousInZ) {
    const ViewFrustum frustum{60.0, 1.0, 1.0, 1000.0};
    const int k = 4;
    const SchemeStorage s = EvaluateScheme(frustum, DirectionToLight(90.0), Scheme::ZpWarp(k));
    const std::vector<double> d = ZPartitionDepths(1.0, 1000.0, k);
    for (int i = 0; i + 1 < k; ++i) {
        EXPECT_NEAR(s.maps[i].maxErrors.x, s.maps[i + 1].maxErrors.x, 1e-9 * s.maps[i].maxErrors.x);
        EXPECT_NEAR(s.maps[i].maxErrors.z, s.maps[i + 1].maxErrors.z, 1e-9 * s.maps[i].maxErrors.z);
        ViewFrustum left = frustum, right = frustum;
        left.nearPlane = d[i];
        left.farPlane = d[i + 1];
        right.nearPlane = d[i + 1];
        right.farPlane = d[i + 2];
        const double leftEnd = OverheadErrors(left, LispsmWarpOffset(d[i], d[i + 1]), d[i + 1]).z;
        const double rightStart =
            OverheadErrors(right, LispsmWarpOffset(d[i + 1], d[i + 2]), d[i + 1]).z;
        EXPECT_NEAR(leftEnd, rightStart, 1e-12 * leftEnd) << "seam " << i;
    }
}

// --- The numbers the paper prints ---

// Fig. 12 (f/n = 1000, θ = 30°) and S̄_opt, to the digits printed (reference values in
// /work/shared/notes/partitioning.md).
TEST(StorageFactorPublishedValues, Figure12ToThePrintedDigits) {
    const ViewFrustum frustum{60.0, 1.0, 1.0, 1000.0};
    const std::vector<MapCountPoint> sweep = MapCountSweep(frustum, 8);
    struct Row {
        int maps;
        double zpWarpOverhead, zpOverhead, zpBehind;
        double halfUlpWarp, halfUlpZp, halfUlpBehind;  // half a unit of the last printed digit
    };
    const Row rows[] = {{1, 865.0, 865159.0, 1e6, 0.5, 0.5, 0.5},
                        {2, 53.0, 1677.0, 2000.0, 0.05, 0.5, 0.5},
                        {4, 16.0, 90.1, 126.5, 0.05, 0.05, 0.05},
                        {8, 9.5, 22.5, 45.0, 0.05, 0.05, 0.05}};
    for (const Row& r : rows) {
        const MapCountPoint& p = sweep[r.maps - 1];
        EXPECT_NEAR(p.zpWarpOverhead, r.zpWarpOverhead, r.halfUlpWarp) << r.maps << " maps";
        EXPECT_NEAR(p.zpOverhead, r.zpOverhead, r.halfUlpZp) << r.maps << " maps";
        EXPECT_NEAR(p.zpBehind, r.zpBehind, r.halfUlpBehind) << r.maps << " maps";
        EXPECT_NEAR(p.zpWarpBehind, r.zpBehind, r.halfUlpBehind) << r.maps << " maps";
    }
    EXPECT_NEAR(OptimalStorageFactor(frustum), 5.98, 0.005);
}

TEST(StorageFactorPublishedValues, Figure12SeriesFollowTheClosedForms) {
    const ViewFrustum frustum{60.0, 1.0, 1.0, 1000.0};
    for (const MapCountPoint& p : MapCountSweep(frustum, 16)) {
        const int j = p.maps;
        ExpectRelative(p.zpOverhead, ZpOverheadStorageFactor(frustum, j), 1e-12, "eq. 17");
        ExpectRelative(p.zpWarpOverhead, ZpWarpOverheadStorageFactor(frustum, j), 1e-12, "eq. 18");
        ExpectRelative(p.zpBehind, ZpBehindStorageFactor(frustum, j), 1e-12, "eq. 20");
        ASSERT_EQ(p.fpOverhead.has_value(), j % 4 == 0);
        ASSERT_EQ(p.fpBehind.has_value(), j % 4 == 0);
        if (j % 4 != 0) continue;
        ExpectRelative(*p.fpOverhead, ZpWarpOverheadStorageFactor(frustum, j / 4), 1e-12, "eq. 19");
        ExpectRelative(*p.fpBehind, FpZpWarpBehindStorageFactor(frustum, j / 4), 1e-12, "eq. 21");
    }
    // §5.3: "Even ZP without warping does better than FP + ZP + W in the overhead case."
    for (const MapCountPoint& p : MapCountSweep(frustum, 16))
        if (p.fpOverhead && p.maps >= 8) {
            EXPECT_LT(p.zpOverhead, *p.fpOverhead) << p.maps;
        }
}

// Fig. 10: ZP + W decreases toward S̄_opt and stays above it (k(ρ - 1) > ln(f/n)).
TEST(StorageFactorPublishedValues, Figure10ApproachesTheOptimum) {
    const ViewFrustum frustum{60.0, 1.0, 1.0, 1000.0};
    const std::vector<PartitionSweepPoint> sweep = PartitionSweep(frustum, 64);
    for (std::size_t i = 0; i < sweep.size(); ++i) {
        EXPECT_GT(sweep[i].zpWarp, sweep[i].optimal);
        EXPECT_GT(sweep[i].zp, sweep[i].zpWarp);
        if (i > 0) {
            EXPECT_LT(sweep[i].zpWarp, sweep[i - 1].zpWarp);
        }
    }
    EXPECT_NEAR(sweep.back().zpWarp / sweep.back().optimal, 1.0, 0.06);
}

// Fig. 13: the crossover closed form solves eq. 20 = eq. 21 and matches the vertex rule.
TEST(StorageFactorPublishedValues, Figure13CrossoverMatchesTheVertexRule) {
    for (const ViewFrustum& shape :
         {ViewFrustum{60.0, 1.0, 1.0, 2.0}, ViewFrustum{90.0, 1.7, 1.0, 2.0}}) {
        for (const CrossoverPoint& c : ZpFpCrossover(shape, 5)) {
            ExpectRelative(c.depthRatioEvaluated, c.depthRatio, 1e-9,
                           Describe(shape) + ", m " + std::to_string(c.facePartitions));
            ViewFrustum at = shape;
            at.farPlane = c.depthRatio;
            ExpectRelative(ZpBehindStorageFactor(at, c.maps),
                           FpZpWarpBehindStorageFactor(at, c.facePartitions), 1e-12, "crossing");
        }
    }
    EXPECT_NEAR(ZpFpCrossoverDepthRatio(1), std::pow(1.0 + std::sqrt(1.5), 2.0), 1e-12);
}

// --- General light directions: the vertex rule against the dense evaluation ---

TEST(StorageFactorGeneralLight, VertexRuleMatchesDenseSamplesForRandomLights) {
    std::mt19937_64 random(20060626);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int trial = 0; trial < 60; ++trial) {
        ViewFrustum f;
        f.fovYDeg = 20.0 + 100.0 * unit(random);
        f.aspect = 0.6 + 1.2 * unit(random);
        f.nearPlane = 0.1 + unit(random);
        f.farPlane = f.nearPlane * std::exp(1.0 + 6.0 * unit(random));  // f/n in [e, e^7]
        const double gamma = 180.0 * unit(random), azimuth = 360.0 * unit(random);
        Scheme scheme;
        scheme.zPartitions = 1 + trial % 3;
        scheme.eta = trial % 4 == 0 ? -1.0 : -0.5 + 1.5 * unit(random);
        scheme.facePartitioning = trial % 2 == 1;
        const glm::dvec3 light = DirectionToLight(gamma, azimuth);
        std::ostringstream what;
        what << "trial " << trial << ": " << Describe(f) << ", gamma " << gamma << "°, azimuth "
             << azimuth << "°, k " << scheme.zPartitions << ", eta " << scheme.eta << ", FP "
             << scheme.facePartitioning;
        SCOPED_TRACE(what.str());
        const SchemeStorage vertices = EvaluateScheme(f, light, scheme);
        const SchemeStorage sampled = SampleScheme(f, light, scheme, 7);
        ASSERT_EQ(vertices.maps.size(), sampled.maps.size());
        for (std::size_t i = 0; i < vertices.maps.size(); ++i) {
            ExpectRelative(sampled.maps[i].maxErrors.x, vertices.maps[i].maxErrors.x,
                           kNumericTolerance, "M_x of " + vertices.maps[i].label);
            ExpectRelative(sampled.maps[i].maxErrors.z, vertices.maps[i].maxErrors.z,
                           kNumericTolerance, "M_z of " + vertices.maps[i].label);
        }
        ExpectRelative(sampled.storage, vertices.storage, kNumericTolerance, "S̄");
    }
}

// The WNP project page's note: the PSM–LiSPSM equivalence holds for the light overhead only.
TEST(StorageFactorGeneralLight, EquivalenceOfWarpParametersHoldsOnlyOverhead) {
    const ViewFrustum frustum{60.0, 1.0, 1.0, 100.0};
    auto storage = [&](double gamma, double eta) {
        return EvaluateScheme(frustum, DirectionToLight(gamma), Scheme::ZpWarp(1, eta)).storage;
    };
    for (double eta : {0.25, 0.5, 1.0}) EXPECT_NEAR(storage(90.0, eta), storage(90.0, 0.0), 1e-9);
    EXPECT_GT(storage(60.0, 1.0), 1.4 * storage(60.0, 0.0));  // 297.0 against 205.8
}

// §4.4 with Wimmer et al.'s general-γ LiSPSM: n' = (n + √(fn)) / sinγ, unwarped as the light
// aligns with the view; the light in front needs what the light behind needs.
TEST(StorageFactorGeneralLight, WarpOffsetScalesWithOneOverSinGamma) {
    const ViewFrustum frustum{60.0, 1.0, 1.0, 100.0};
    for (double gamma : {30.0, 60.0, 120.0}) {
        const SchemeStorage s =
            EvaluateScheme(frustum, DirectionToLight(gamma, 20.0), Scheme::ZpWarp(1));
        ExpectRelative(s.maps[0].nPrime, 11.0 / std::sin(gamma * std::numbers::pi / 180.0), 1e-12,
                       "gamma " + std::to_string(gamma));
    }
    const SchemeStorage aligned = EvaluateScheme(frustum, DirectionToLight(0.0), Scheme::ZpWarp(1));
    EXPECT_EQ(aligned.maps[0].nPrime, kInf);
    for (const Scheme& scheme : {Scheme::Zp(3), Scheme::ZpWarp(3), Scheme::FpZpWarp(3)})
        ExpectRelative(EvaluateScheme(frustum, DirectionToLight(180.0), scheme).storage,
                       EvaluateScheme(frustum, DirectionToLight(0.0), scheme).storage, 1e-12,
                       "in front against behind");
}

// Fig. 7 and §4.4–5.1 in numbers (f/n = 100, θ = 30°): unwarped is high everywhere (within a
// factor 2.2 over the hemisphere); LiSPSM is lowest overhead and ~170× worse near the view axis;
// face partitioning makes it uniform (within a factor 3.7) and far lower there.
TEST(StorageFactorGeneralLight, Figure7Shape) {
    const ViewFrustum frustum{60.0, 1.0, 1.0, 100.0};
    auto range = [&](const Scheme& scheme) {
        const HemisphereGrid grid = StorageHemisphere(frustum, scheme, 21);
        double least = kInf;
        for (const HemisphereCell& c : grid.cells)
            if (c.inside) least = std::min(least, c.storage);
        return std::pair{least, grid.Max().storage};
    };
    const auto [noWarpMin, noWarpMax] = range(Scheme::Zp(1));
    const auto [warpMin, warpMax] = range(Scheme::ZpWarp(1));
    const auto [faceMin, faceMax] = range(Scheme::FpZpWarp(1));
    const double overhead = OverheadStorageFactor(frustum, LispsmWarpOffset(1.0, 100.0));
    EXPECT_LT(noWarpMax / noWarpMin, 2.5);
    EXPECT_NEAR(warpMin, overhead, 1e-9 * overhead);
    EXPECT_GT(warpMax / warpMin, 100.0);
    EXPECT_NEAR(faceMin, overhead, 1e-9 * overhead);
    EXPECT_LT(faceMax / faceMin, 4.0);
    EXPECT_LT(faceMax, warpMax / 10.0);
}

// Fig. 7's grid: layout, mirror symmetry about the plane of up and view, the overhead centre.
TEST(StorageFactorGeneralLight, HemisphereGridLayoutAndSymmetry) {
    const ViewFrustum frustum{60.0, 1.0, 1.0, 100.0};
    const int size = 9;
    for (const Scheme& scheme : {Scheme::Zp(1), Scheme::ZpWarp(1), Scheme::FpZpWarp(1)}) {
        const HemisphereGrid grid = StorageHemisphere(frustum, scheme, size);
        ASSERT_EQ(grid.cells.size(), static_cast<std::size_t>(size * size));
        const HemisphereCell& centre = grid.cells[(size / 2) * size + size / 2];
        EXPECT_NEAR(centre.esToLight.y, 1.0, 1e-15);
        EXPECT_NEAR(centre.storage,
                    OverheadStorageFactor(frustum, WarpOffsetFromEta(scheme.eta, 1.0, 100.0)),
                    1e-9 * centre.storage);
        EXPECT_FALSE(grid.cells[0].inside);                 // a corner
        EXPECT_LT(grid.cells[(size / 2) * size].gx, -0.8);  // left: behind the viewer
        EXPECT_GT(grid.cells[(size / 2) * size].esToLight.z, 0.8);
        for (int row = 0; row < size; ++row)
            for (int col = 0; col < size; ++col) {
                const HemisphereCell& a = grid.cells[row * size + col];
                const HemisphereCell& b = grid.cells[(size - 1 - row) * size + col];
                EXPECT_EQ(a.inside, b.inside);
                if (a.inside) {
                    EXPECT_NEAR(a.storage, b.storage, 1e-9 * a.storage);
                }
            }
        EXPECT_GE(grid.Max().storage, centre.storage);
    }
}

TEST(StorageFactorFigures, WarpSweepAndErrorProfileFollowTheClosedForms) {
    const ViewFrustum frustum{60.0, 1.0, 1.0, 100.0};
    const std::vector<WarpSweepPoint> sweep = WarpSweep(frustum, 41);
    EXPECT_EQ(sweep.front().nPrime, kInf);
    EXPECT_DOUBLE_EQ(sweep.back().nPrime, 1.0);
    const double flat = OverheadStorageFactor(frustum, 1.0);
    for (const WarpSweepPoint& p : sweep) {
        if (p.eta >= 0.0) {
            EXPECT_NEAR(p.storage, flat, 1e-12 * flat) << p.eta;
        }
        if (p.eta < 0.0) {
            EXPECT_GT(p.storage, flat) << p.eta;
        }
        EXPECT_NEAR(p.storage, p.maxErrors.x * p.maxErrors.z, 1e-12 * p.storage);
    }
    const std::vector<ErrorProfilePoint> profile =
        ErrorProfile(frustum, LispsmWarpOffset(1.0, 100.0), 11);
    EXPECT_DOUBLE_EQ(profile.front().z, 1.0);
    EXPECT_DOUBLE_EQ(profile.back().z, 100.0);
    EXPECT_NEAR(profile.front().errors.z, profile.back().errors.z, 1e-12 * profile.back().errors.z);
}

}  // namespace
}  // namespace lexel::spatial
