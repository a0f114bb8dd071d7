// Trapezoidal shadow maps (spatial/tsm.h; Martin & Tan, EGSR 2004): N_T against the authors'
// recipe (the chain T1 R T2 H S1 N T3 S2 built independently here), the 80% rule, and on the
// shipped scenes the trapezoid around every visible point with its focus point at 80% of its
// height.
#include "lexel/spatial/tsm.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "lexel/cases/load/spatial_case.h"
#include "lexel/cases/run/sweep.h"
#include "lexel/solvers/geometry.h"
#include "lexel/spatial/harness/evaluation.h"
#include "lexel/spatial/harness/methods.h"

namespace lexel::spatial {
namespace {

// The recipe's N_T (www.comp.nus.edu.sg/~tants/tsm/TSM_recipe.html): eight 4×4 steps on (x, y, 1,
// 1), written from its text with glm column vectors. t = the corners t0..t3 (base t0, t1; top t2,
// t3), q = the projection centre.
glm::dmat4 RecipeNt(const std::array<glm::dvec2, 4>& t2d, const glm::dvec2& q2d) {
    std::array<glm::dvec4, 4> t;
    for (int i = 0; i < 4; ++i) t[i] = glm::dvec4(t2d[i], 1.0, 1.0);
    const glm::dvec4 q(q2d, 1.0, 1.0);
    const auto translate = [](double x, double y) {
        glm::dmat4 m(1.0);
        m[3][0] = x;
        m[3][1] = y;
        return m;
    };
    // T1: the centre of the top edge to the origin.
    glm::dvec4 u = 0.5 * (t[2] + t[3]);
    const glm::dmat4 t1 = translate(-u.x, -u.y);
    // R: the top edge onto the x axis.
    u = (t[2] - t[3]) / std::hypot(t[2].x - t[3].x, t[2].y - t[3].y);
    glm::dmat4 r(1.0);
    r[0][0] = u.x, r[1][0] = u.y, r[0][1] = u.y, r[1][1] = -u.x;
    glm::dmat4 nt = r * t1;
    // T2: the projection centre q to the origin.
    u = nt * q;
    nt = translate(-u.x, -u.y) * nt;
    // H: shear so the trapezoid is symmetric about the y axis.
    u = 0.5 * (nt * (t[2] + t[3]));
    glm::dmat4 h(1.0);
    h[1][0] = -u.x / u.y;
    nt = h * nt;
    // S1: the side edges at 45°, the top edge at y = 1.
    u = nt * t[2];
    glm::dmat4 s1(1.0);
    s1[0][0] = 1.0 / u.x, s1[1][1] = 1.0 / u.y;
    nt = s1 * nt;
    // N: the projective step (rows (1 0 0 0), (0 1 0 1), (0 0 1 0), (0 1 0 0)).
    glm::dmat4 n(0.0);
    n[0][0] = 1.0, n[1][1] = 1.0, n[3][1] = 1.0, n[2][2] = 1.0, n[1][3] = 1.0;
    nt = n * nt;
    // T3: centre the image of the top and base edges on y = 0.
    u = nt * t[0];
    glm::dvec4 v = nt * t[2];
    glm::dmat4 t3(1.0);
    t3[3][1] = -0.5 * (u.y / u.w + v.y / v.w);
    nt = t3 * nt;
    // S2: scale y so the base lands on y = -1.
    u = nt * t[0];
    glm::dmat4 s2(1.0);
    s2[1][1] = -u.w / u.y;
    return s2 * nt;
}

glm::dvec2 Apply(const glm::dmat4& m, const glm::dvec2& y) {
    const glm::dvec4 h = m * glm::dvec4(y, 1.0, 1.0);
    return {h.x / h.w, h.y / h.w};
}

// A random point cloud, a centre line and a focus point between its ends.
struct Cloud {
    std::vector<glm::dvec2> points;
    glm::dvec2 nearPoint, farPoint, focus;
};

Cloud RandomCloud(std::mt19937& rng) {
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    Cloud c;
    const double angle = 3.14159 * unit(rng);
    const glm::dvec2 axis(std::cos(angle), std::sin(angle));
    const glm::dvec2 origin(5.0 * unit(rng), 5.0 * unit(rng));
    c.nearPoint = origin;
    c.farPoint = origin + (2.0 + unit(rng)) * axis;
    const int n = 5 + static_cast<int>(20 * (unit(rng) + 1.0));
    for (int i = 0; i < n; ++i) {
        // A frustum-like wedge widening toward the far end.
        const double along = 0.5 * (unit(rng) + 1.0);
        c.points.push_back(c.nearPoint + along * (c.farPoint - c.nearPoint) +
                           (0.2 + along) * unit(rng) * Perp(axis));
    }
    c.focus = c.nearPoint + (0.3 + 0.2 * unit(rng)) * (c.farPoint - c.nearPoint);
    return c;
}

TEST(Tsm, SquareMapIsTheRecipesChain) {
    std::mt19937 rng(27);
    int fitted = 0;
    for (int trial = 0; trial < 200; ++trial) {
        const Cloud c = RandomCloud(rng);
        std::string failure;
        const auto t =
            FitTrapezoid(c.points, c.nearPoint, c.farPoint, c.focus, kTsmFocusLine, &failure);
        if (!t) continue;  // the focus beyond the 80% line for this cloud
        ++fitted;
        const glm::dmat4 recipe = RecipeNt(t->t, t->q);
        const glm::dvec2 corners[4] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
        for (int i = 0; i < 4; ++i) {
            const glm::dvec2 ours = t->ToSquare(t->t[i]), theirs = Apply(recipe, t->t[i]);
            EXPECT_NEAR(ours.x, corners[i].x, 1e-12) << "trial " << trial << " corner " << i;
            EXPECT_NEAR(ours.y, corners[i].y, 1e-12) << "trial " << trial << " corner " << i;
            EXPECT_NEAR(theirs.x, corners[i].x, 1e-9) << "trial " << trial << " corner " << i;
            EXPECT_NEAR(theirs.y, corners[i].y, 1e-9) << "trial " << trial << " corner " << i;
        }
        for (const glm::dvec2& p : c.points) {
            const glm::dvec2 ours = t->ToSquare(p), theirs = Apply(recipe, p);
            EXPECT_NEAR(ours.x, theirs.x, 1e-9) << "trial " << trial;
            EXPECT_NEAR(ours.y, theirs.y, 1e-9) << "trial " << trial;
        }
    }
    EXPECT_GT(fitted, 150);
}

TEST(Tsm, TrapezoidHoldsItsPointsAndPutsTheFocusOnTheEightyPercentLine) {
    std::mt19937 rng(4);
    for (int trial = 0; trial < 200; ++trial) {
        const Cloud c = RandomCloud(rng);
        const auto t = FitTrapezoid(c.points, c.nearPoint, c.farPoint, c.focus);
        if (!t) continue;
        for (const glm::dvec2& p : c.points) {
            const glm::dvec2 s = t->ToSquare(p);
            EXPECT_TRUE(std::abs(s.x) <= 1.0 + 1e-10 && std::abs(s.y) <= 1.0 + 1e-10)
                << "trial " << trial << ": (" << s.x << ", " << s.y << ")";
        }
        // 80% of the height from the top edge (y = +1) toward the base (y = -1).
        const double fromTop = 0.5 * (1.0 - t->ToSquare(c.focus).y);
        EXPECT_NEAR(fromTop, 0.8, 1e-12) << "trial " << trial;
        // The paper's quantities: the focus δ' below the top line, q η above it.
        EXPECT_NEAR(glm::dot(c.focus - t->q, t->l), t->eta + t->deltaPrime, 1e-9);
        EXPECT_NEAR(t->eta, t->lambda * t->deltaPrime * 0.4 / (1.6 * t->lambda - 2 * t->deltaPrime),
                    1e-12 * t->eta);
    }
}

TEST(Tsm, RefusesAFocusBeyondTheEightyPercentLineAndAnEndOnCentreLine) {
    const std::vector<glm::dvec2> square = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    std::string failure;
    // The focus 85% of the way down: only an inverse warp would lift it to 80%.
    EXPECT_FALSE(
        FitTrapezoid(square, {0.5, 0.0}, {0.5, 1.0}, {0.5, 0.85}, kTsmFocusLine, &failure));
    EXPECT_NE(failure.find("focus"), std::string::npos) << failure;
    EXPECT_FALSE(
        FitTrapezoid(square, {0.5, 0.5}, {0.5, 0.5 + 1e-6}, {0.5, 0.5}, kTsmFocusLine, &failure));
    EXPECT_NE(failure.find("end on"), std::string::npos) << failure;
    // At 40% it fits: η = λδ'(1 + ξ) / (λ(1 − ξ) − 2δ') = 0.4 · 0.4 / (1.6 − 0.8) = 0.2.
    const auto t = FitTrapezoid(square, {0.5, 0.0}, {0.5, 1.0}, {0.5, 0.4});
    ASSERT_TRUE(t);
    EXPECT_NEAR(t->eta, 0.2, 1e-15);
    EXPECT_NEAR(t->q.y, -0.2, 1e-15);
    // The side lines from q = (0.5, -0.2) through the top corners (1, 0) and (0, 0) (slopes
    // across l measured along l⊥ = Perp(l) = -x): the base corners 1.2 / 0.2 = 6 times as far out.
    EXPECT_NEAR(t->t[0].x, 0.5 + 0.5 * 1.2 / 0.2, 1e-12);
    EXPECT_NEAR(t->t[1].x, 0.5 - 0.5 * 1.2 / 0.2, 1e-12);
    EXPECT_NEAR(t->t[0].y, 1.0, 1e-12);
    EXPECT_NEAR(t->t[3].x, 1.0, 1e-12);
    EXPECT_NEAR(t->t[3].y, 0.0, 1e-12);
}

// Scenes and lights of the fair comparison: every visible point of the readback (not just the
// hull's vertices) inside the trapezoid and the map, the focus at 80% of the trapezoid's height.
TEST(Tsm, OnShippedScenesTheTrapezoidHoldsEveryVisiblePointWithItsFocusAtEightyPercent) {
    int fitted = 0, total = 0;
    for (const char* file : {"walkthrough.json", "courtyard.json", "street.json"}) {
        const Scene scene =
            cases::LoadSpatialScene(std::filesystem::path(LEXEL_CASES_DIR) / "spatial" / file);
        const auto backend = MakeCpuRenderer(scene.geometry);
        const Evaluator evaluator(scene, *backend);
        const Readback& readback = evaluator.readback();
        std::vector<Light> lights = cases::SweepLightsOf(scene, 20, Light::Type::kPoint);
        for (const Light& l : cases::SweepLightsOf(scene, 20, Light::Type::kDirectional))
            lights.push_back(l);
        for (const Light& light : lights) {
            const std::string what = std::string(file) + " " + cases::LightLabel(light);
            const LightSpace lightSpace(light, evaluator.bounds());
            const BaselineContext context =
                MakeBaselineContext(scene, lightSpace, evaluator.bounds(), readback.wsRelevant,
                                    readback.wsRelevantHull);
            const TsmFit fit = FitTsm(context, TsmBody::kVisible);
            ++total;
            for (const glm::dvec3& ws : readback.wsRelevant) {
                const glm::dvec3 lsX = lightSpace.ToLight(ws);
                ASSERT_TRUE(InFront(fit.matrix.p4, lsX)) << what;
                const glm::dvec2 u = fit.matrix.Map(lsX);
                ASSERT_TRUE(u.x > -1e-6 && u.y > -1e-6 && u.x < scene.shadowMap.width + 1e-6 &&
                            u.y < scene.shadowMap.height + 1e-6)
                    << what << ": " << u.x << ", " << u.y;
            }
            if (!fit.trapezoid) {
                EXPECT_FALSE(fit.fallback.empty()) << what;
                continue;
            }
            ++fitted;
            const Trapezoid& t = *fit.trapezoid;
            glm::dvec3 b1, b2;
            PlaneBasis(fit.planeAxis, &b1, &b2);
            const auto plane = [&](const glm::dvec3& ws) {
                const glm::dvec3 lsX = lightSpace.ToLight(ws);
                return glm::dvec2(glm::dot(b1, lsX), glm::dot(b2, lsX)) /
                       glm::dot(fit.planeAxis, lsX);
            };
            for (const glm::dvec3& ws : readback.wsRelevant) {
                const glm::dvec2 s = t.ToSquare(plane(ws));
                ASSERT_TRUE(std::abs(s.x) <= 1.0 + 1e-9 && std::abs(s.y) <= 1.0 + 1e-9)
                    << what << ": a visible point at (" << s.x << ", " << s.y << ")";
            }
            const Camera& camera = scene.camera;
            const glm::dvec3 view = glm::normalize(camera.target - camera.position);
            const double fromTop =
                0.5 * (1.0 - t.ToSquare(plane(camera.position + fit.zFocus * view)).y);
            EXPECT_NEAR(fromTop, 0.8, 1e-9) << what;
            EXPECT_NEAR(fit.zFocus, 0.5 * (fit.zNear + fit.zFar), 1e-9 * fit.zFar) << what;
        }
    }
    // Most lights get a trapezoid; the rest are lights seen almost end on (or whose focus the
    // visible points' hull already puts past 80%), where TSM itself has none.
    EXPECT_GE(fitted, total * 3 / 4) << fitted << " of " << total;
    std::cout << "tsm: a trapezoid on " << fitted << " of " << total << " lights\n";
}

TEST(Tsm, ViewAlongADirectionalLightFallsBackToFocusedTight) {
    const Scene scene = cases::LoadSpatialScene(std::filesystem::path(LEXEL_CASES_DIR) / "spatial" /
                                                "walkthrough.json");
    const auto backend = MakeCpuRenderer(scene.geometry);
    const Evaluator evaluator(scene, *backend);
    const Readback& readback = evaluator.readback();
    Light light;
    light.type = Light::Type::kDirectional;
    light.direction = scene.camera.target - scene.camera.position;
    const LightSpace lightSpace(light, evaluator.bounds());
    const BaselineContext context = MakeBaselineContext(
        scene, lightSpace, evaluator.bounds(), readback.wsRelevant, readback.wsRelevantHull);
    const TsmFit fit = FitTsm(context, TsmBody::kVisible);
    EXPECT_FALSE(fit.trapezoid);
    EXPECT_NE(fit.fallback.find("end on"), std::string::npos) << fit.fallback;
    const LightMatrix focused = FocusedTightLightMatrix(context);
    EXPECT_EQ(fit.matrix.p1, focused.p1);
    EXPECT_EQ(fit.matrix.p4, focused.p4);
}

TEST(Tsm, ReportVariantHoldsTheViewFrustumBody) {
    const Scene scene = cases::LoadSpatialScene(std::filesystem::path(LEXEL_CASES_DIR) / "spatial" /
                                                "walkthrough.json");
    const auto backend = MakeCpuRenderer(scene.geometry);
    const Evaluator evaluator(scene, *backend);
    const Readback& readback = evaluator.readback();
    int fitted = 0;
    for (const Light& light : cases::SweepLightsOf(scene, 20, Light::Type::kPoint)) {
        const LightSpace lightSpace(light, evaluator.bounds());
        const BaselineContext context = MakeBaselineContext(
            scene, lightSpace, evaluator.bounds(), readback.wsRelevant, readback.wsRelevantHull);
        const TsmFit fit = FitTsm(context, TsmBody::kFrustum);
        const TsmFit tight = FitTsm(context, TsmBody::kVisible);
        if (!fit.trapezoid || !tight.trapezoid) continue;
        ++fitted;
        // The frustum ∩ bounds holds the visible points, so its depth range holds theirs.
        EXPECT_LE(fit.zNear, tight.zNear + 1e-9) << cases::LightLabel(light);
        EXPECT_GE(fit.zFar, tight.zFar - 1e-9) << cases::LightLabel(light);
        EXPECT_GT(fit.trapezoid->lambda, 0.0);
    }
    EXPECT_GE(fitted, 10);
}

}  // namespace
}  // namespace lexel::spatial
