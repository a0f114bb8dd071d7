// Partitioned shadow maps (cascades.h, partitions.h): PSSM's split formula, the Lagrange texel
// allocation's exchange optimality, and on the shipped walkthrough for point and directional
// lights: the intervals tile the camera's depth range, every visible point lies in its cascade's
// map, sdsm-optimal never has a larger energy than sdsm (on e and on h), each optimized method
// searches on its energy, and an empty partition is reported, not NaN.
#include "lexel/spatial/partitions.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <sstream>

#include "lexel/cases/load/spatial_case.h"
#include "lexel/cases/run/sweep.h"
#include "lexel/spatial/baselines.h"
#include "lexel/spatial/cascades.h"
#include "lexel/spatial/harness/evaluation.h"
#include "lexel/spatial/harness/methods.h"

namespace lexel::spatial {
namespace {

TEST(PssmSplits, LambdaOneIsLogarithmicAndZeroUniform) {
    const double n = 0.3, f = 70.0;
    for (int k : {1, 2, 3, 4, 7}) {
        const std::vector<double> logSplit = PssmSplits(n, f, k, 1.0);
        const std::vector<double> uniform = PssmSplits(n, f, k, 0.0);
        const std::vector<double> half = PssmSplits(n, f, k, 0.5);
        ASSERT_EQ(logSplit.size(), static_cast<std::size_t>(k + 1));
        EXPECT_EQ(logSplit.front(), n);
        EXPECT_EQ(logSplit.back(), f);
        EXPECT_EQ(uniform.front(), n);
        EXPECT_EQ(uniform.back(), f);
        for (int i = 0; i <= k; ++i) {
            // Lloyd eq. 15: C_i = n (f/n)^(i/k); the uniform split n + (f - n) i/k.
            EXPECT_NEAR(logSplit[i], n * std::pow(f / n, double(i) / k), 1e-12 * f)
                << k << " " << i;
            EXPECT_NEAR(uniform[i], n + (f - n) * i / k, 1e-12 * f) << k << " " << i;
            EXPECT_NEAR(half[i], 0.5 * (logSplit[i] + uniform[i]), 1e-12 * f) << k << " " << i;
            if (i > 0) {
                EXPECT_LT(logSplit[i - 1], logSplit[i]);
            }
        }
        // Logarithmic splits keep the ratio of consecutive splits constant: (f/n)^(1/k).
        for (int i = 1; i < k; ++i)
            EXPECT_NEAR(logSplit[i + 1] / logSplit[i], std::pow(f / n, 1.0 / k), 1e-12);
    }
    EXPECT_THROW(PssmSplits(0.0, 1.0, 4, 0.5), std::invalid_argument);
    EXPECT_THROW(PssmSplits(1.0, 1.0, 4, 0.5), std::invalid_argument);
    EXPECT_THROW(PssmSplits(1.0, 2.0, 0, 0.5), std::invalid_argument);
    EXPECT_THROW(PssmSplits(1.0, 2.0, 4, 1.5), std::invalid_argument);
}

// Σ c_i / N_i^k over the cascades that have a cost.
double AllocationCost(std::span<const double> costs, std::span<const int> texels, double k) {
    double total = 0.0;
    for (std::size_t i = 0; i < costs.size(); ++i)
        if (costs[i] > 0.0) total += costs[i] / std::pow(texels[i], k);
    return total;
}

// k = 1: h's law (squared footprints, 1/N); k = 1/2: e₁'s (lengths, 1/√N); e at p = 5/8 has 5/16.
TEST(LagrangeCascadeTexels, NoSingleTexelExchangeLowersTheTotal) {
    const Resolution budget{400, 400};
    const std::vector<std::vector<double>> cases = {
        {1.0, 1.0, 1.0, 1.0}, {5.0, 1.0, 0.2, 0.01}, {3.0, 0.0, 7.0}, {1e6, 1.0}, {2.5}};
    for (const double k : {1.0, 0.5})
        for (const std::vector<double>& costs : cases) {
            std::ostringstream what;
            what << "k " << k << ", costs ";
            for (double c : costs) what << c << " ";
            const std::vector<int> texels = LagrangeCascadeTexels(budget, costs, k);
            long long sum = 0;
            for (int n : texels) sum += n;
            EXPECT_EQ(sum, budget.Count()) << what.str();
            const double best = AllocationCost(costs, texels, k);
            for (std::size_t i = 0; i < costs.size(); ++i) {
                if (costs[i] == 0.0) {
                    EXPECT_EQ(texels[i], 0) << what.str();
                }
                for (std::size_t j = 0; j < costs.size(); ++j) {
                    if (i == j || texels[i] <= 1 || costs[j] == 0.0) continue;
                    std::vector<int> moved = texels;
                    --moved[i];
                    ++moved[j];
                    EXPECT_LE(best, AllocationCost(costs, moved, k)) << what.str() << i << "→" << j;
                }
            }
            // The real Lagrange solution N_i = N c_i^(1/(k+1)) / Σ c_j^(1/(k+1)) (√c_i for h,
            // c_i^(2/3) for e₁) is within one texel.
            double rootSum = 0.0;
            for (double c : costs) rootSum += std::pow(c, 1.0 / (k + 1.0));
            for (std::size_t i = 0; i < costs.size(); ++i)
                EXPECT_NEAR(texels[i],
                            budget.Count() * std::pow(costs[i], 1.0 / (k + 1.0)) / rootSum, 1.0)
                    << what.str();
            // The maps are the squarest layouts of those counts: w h ≤ N_i, less than one row lost.
            const std::vector<Resolution> maps =
                AllocateCascadeMaps(budget, costs, CascadeAllocation::kLagrange, k);
            for (std::size_t i = 0; i < costs.size(); ++i) {
                if (texels[i] == 0) {
                    EXPECT_EQ(maps[i].Count(), 1) << what.str();
                    continue;
                }
                EXPECT_LE(maps[i].Count(), texels[i]) << what.str();
                EXPECT_GT(maps[i].Count(), texels[i] - maps[i].width) << what.str();
            }
        }
    EXPECT_THROW(
        AllocateCascadeMaps(budget, std::vector<double>{1.0, -1.0}, CascadeAllocation::kLagrange),
        std::invalid_argument);
    EXPECT_THROW(LagrangeCascadeTexels(budget, std::vector<double>{1.0, 2.0}, 0.0),
                 std::invalid_argument);
    const std::vector<Resolution> equal =
        AllocateCascadeMaps(budget, std::vector<double>(4, 0.0), CascadeAllocation::kEqual);
    for (const Resolution& r : equal) EXPECT_EQ(r.width, 200);
}

TEST(RescaleMap, MapsTheSamePointToTheSameFractionOfTheMap) {
    LightMatrix m;
    m.p1 = {3.0, -0.25, 7.0};
    m.p2 = {0.5, 2.0, 11.0};
    m.p4 = {0.1, -0.2, 1.0};
    const LightMatrix r = RescaleMap(m, {200, 100}, {50, 300});
    const glm::dvec3 lsX(0.3, 0.7, 2.0);
    EXPECT_NEAR(r.Map(lsX).x, m.Map(lsX).x * 50.0 / 200.0, 1e-12);
    EXPECT_NEAR(r.Map(lsX).y, m.Map(lsX).y * 300.0 / 100.0, 1e-12);
}

// The walkthrough with its evaluator and 3 point and 3 directional sweep lights.
struct Walkthrough {
    Walkthrough()
        : scene(cases::LoadSpatialScene(std::filesystem::path(LEXEL_CASES_DIR) / "spatial" /
                                        "walkthrough.json")),
          backend(MakeCpuRenderer(scene.geometry)),
          evaluator(scene, *backend) {
        lights = cases::SweepLightsOf(scene, 3, Light::Type::kPoint);
        for (const Light& l : cases::SweepLightsOf(scene, 3, Light::Type::kDirectional))
            lights.push_back(l);
    }
    Scene scene;
    std::unique_ptr<RenderBackend> backend;
    Evaluator evaluator;
    std::vector<Light> lights;
};

const Walkthrough& SharedWalkthrough() {
    static const Walkthrough w;
    return w;
}

struct PartitionRun {
    LightOutcome outcome;
    BaselineContext context;
    std::unique_ptr<LightSpace> lightSpace;
};

PartitionRun RunLight(const Walkthrough& w, const Light& light) {
    PartitionRun run;
    run.outcome = w.evaluator.Evaluate(light, EvaluationOptions{});
    run.lightSpace = std::make_unique<LightSpace>(light, w.evaluator.bounds());
    run.context = MakeBaselineContext(w.scene, *run.lightSpace, w.evaluator.bounds(),
                                      w.evaluator.readback().wsRelevant,
                                      w.evaluator.readback().wsRelevantHull);
    run.context.samples = &run.outcome.samples;
    return run;
}

TEST(Partitions, IntervalsTileTheCameraDepthRangeAroundTheVisibleRange) {
    const Walkthrough& w = SharedWalkthrough();
    const Camera& camera = w.scene.camera;
    double zMin = std::numeric_limits<double>::infinity(), zMax = -zMin;
    for (const glm::dvec3& x : w.evaluator.readback().wsRelevant) {
        zMin = std::min(zMin, PlanarEyeDepth(camera, x));
        zMax = std::max(zMax, PlanarEyeDepth(camera, x));
    }
    const PartitionRun run = RunLight(w, w.lights.front());
    for (PartitionScheme scheme : {PartitionScheme::kPssm, PartitionScheme::kSdsm,
                                   PartitionScheme::kZpLispsm, PartitionScheme::kSdsmOptimal})
        for (int k : {1, 2, 4, 8}) {
            PartitionOptions options;
            options.count = k;
            const std::vector<Cascade> cascades =
                PartitionedLightMatrices(scheme, run.context, run.outcome.samples, options);
            ASSERT_EQ(cascades.size(), static_cast<std::size_t>(k));
            EXPECT_EQ(cascades.front().zNear, camera.nearPlane);
            EXPECT_GE(cascades.back().zFar, camera.farPlane);
            EXPECT_GT(cascades.back().zFar, zMax);
            for (int i = 0; i + 1 < k; ++i) {
                EXPECT_EQ(cascades[i].zFar, cascades[i + 1].zNear);  // no gap, no overlap
                EXPECT_LT(cascades[i].zNear, cascades[i].zFar);
            }
            if (scheme == PartitionScheme::kPssm) {
                const std::vector<double> splits =
                    PssmSplits(camera.nearPlane, camera.farPlane, k, options.lambda);
                for (int i = 0; i < k; ++i) EXPECT_EQ(cascades[i].zNear, splits[i]);
            }
            if (scheme == PartitionScheme::kSdsm && k > 1) {  // log splits over [zMin, zMax]
                const std::vector<double> splits = PssmSplits(zMin, zMax, k, 1.0);
                for (int i = 1; i < k; ++i) EXPECT_NEAR(cascades[i].zNear, splits[i], 1e-12 * zMax);
            }
        }
}

// Every visible point the cascade serves maps into its map, in front of its plane.
void ExpectEveryPointInItsCascade(const std::vector<Cascade>& cascades, const PartitionRun& run,
                                  const Camera& camera, const std::string& what) {
    const auto& wsRelevant = run.context.wsRelevant;
    for (std::size_t p = 0; p < wsRelevant.size(); ++p) {
        bool covered = false;
        const std::size_t i =
            CascadeFor(cascades, PlanarEyeDepth(camera, wsRelevant[p]), wsRelevant[p], &covered);
        ASSERT_TRUE(covered) << what << " point " << p;
        const Cascade& c = cascades[i];
        const glm::dvec3 lsX = run.outcome.samples.lsRelevant[p];
        ASSERT_TRUE(InFront(c.matrix.p4, lsX)) << what << " point " << p;
        const glm::dvec2 u = c.matrix.Map(lsX);
        ASSERT_TRUE(u.x > -1e-6 && u.y > -1e-6 && u.x < c.map.width + 1e-6 &&
                    u.y < c.map.height + 1e-6)
            << what << " cascade " << i << " maps point " << p << " to " << u.x << ", " << u.y;
    }
}

TEST(Partitions, EveryVisiblePointLiesInItsCascadesMap) {
    const Walkthrough& w = SharedWalkthrough();
    for (const Light& light : w.lights) {
        const PartitionRun run = RunLight(w, light);
        for (PartitionScheme scheme : {PartitionScheme::kPssm, PartitionScheme::kSdsm,
                                       PartitionScheme::kSdsmRect, PartitionScheme::kZpLispsm,
                                       PartitionScheme::kFpLispsm, PartitionScheme::kSdsmOptimal})
            for (CascadeAllocation allocation :
                 {CascadeAllocation::kEqual, CascadeAllocation::kLagrange}) {
                PartitionOptions options;
                options.allocation = allocation;
                options.snap = light.type == Light::Type::kDirectional;
                const std::string what = cases::LightLabel(light) + " scheme " +
                                         std::to_string(int(scheme)) + " allocation " +
                                         std::to_string(int(allocation));
                const std::vector<Cascade> cascades =
                    PartitionedLightMatrices(scheme, run.context, run.outcome.samples, options);
                long long texels = 0;
                for (const Cascade& c : cascades) texels += c.map.Count();
                // Equal maps are rounded down; a Lagrange empty partition adds its 1 × 1 map.
                EXPECT_LE(texels, w.scene.shadowMap.Count() + kMaxCascades) << what;
                EXPECT_GT(texels, w.scene.shadowMap.Count() * 0.98) << what;
                ExpectEveryPointInItsCascade(cascades, run, w.scene.camera, what);
            }
    }
}

// On e (sdsm-optimal) and on h (sdsm-optimal-h), with either allocation: each cascade's energy,
// and their sum, at most SDSM's (the Lagrange allocation on the same energy's law).
TEST(Partitions, SdsmOptimalNeverHasALargerEnergyThanSdsm) {
    const Walkthrough& w = SharedWalkthrough();
    for (const Light& light : w.lights) {
        const PartitionRun run = RunLight(w, light);
        for (const EnergyOptions& energy : {kEdgeEnergy, EnergyOptions{}})
            for (CascadeAllocation allocation :
                 {CascadeAllocation::kEqual, CascadeAllocation::kLagrange}) {
                PartitionOptions options;
                options.allocation = allocation;
                options.energy = energy;
                const std::string what = cases::LightLabel(light) +
                                         (energy.IsReport() ? " h" : " e") + " allocation " +
                                         std::to_string(int(allocation));
                const auto sdsm = PartitionedLightMatrices(PartitionScheme::kSdsm, run.context,
                                                           run.outcome.samples, options);
                const auto optimal = PartitionedLightMatrices(
                    PartitionScheme::kSdsmOptimal, run.context, run.outcome.samples, options);
                const auto& relevant = run.context.wsRelevant;
                const double eSdsm =
                    PartitionedEnergy(sdsm, run.outcome.samples, relevant, w.scene.camera, energy);
                const double eOptimal = PartitionedEnergy(optimal, run.outcome.samples, relevant,
                                                          w.scene.camera, energy);
                ASSERT_TRUE(std::isfinite(eSdsm) && std::isfinite(eOptimal)) << what;
                if (allocation == CascadeAllocation::kEqual) {  // the same maps: cascade by cascade
                    for (std::size_t i = 0; i < sdsm.size(); ++i) {
                        const LightSamples part = SamplesOfCascade(run.outcome.samples, relevant,
                                                                   w.scene.camera, sdsm, i);
                        EXPECT_LE(Energy(optimal[i].matrix, part, energy),
                                  Energy(sdsm[i].matrix, part, energy))
                            << what << " cascade " << i;
                    }
                }
                EXPECT_LE(eOptimal, eSdsm) << what;
            }
    }
}

TEST(Partitions, AnEmptyPartitionIsReportedNotNaN) {
    // A uniform PSSM split of 8 over the camera's [near, far]: the walkthrough's visible points
    // end well before far, so the farthest partitions serve no point.
    Scene scene = SharedWalkthrough().scene;
    scene.partitions.count = 8;
    scene.partitions.lambda = 0.0;
    scene.partitions.allocation = CascadeAllocation::kLagrange;
    const std::unique_ptr<RenderBackend> backend = MakeCpuRenderer(scene.geometry);
    const Evaluator evaluator(scene, *backend);
    EvaluationOptions options;
    options.methods = {"pssm"};
    const LightOutcome o = evaluator.Evaluate(SharedWalkthrough().lights.front(), options);
    const MethodOutcome& m = o.methods.front();
    ASSERT_EQ(m.cascades.size(), 8u);
    int empty = 0;
    for (const CascadeOutcome& c : m.cascades) {
        if (c.cascade.visiblePoints == 0) ++empty;
        EXPECT_TRUE(std::isfinite(c.h));
    }
    EXPECT_GT(empty, 0);
    EXPECT_EQ(m.emptyPartitions, empty);
    EXPECT_TRUE(std::isfinite(m.metrics.h));
    EXPECT_TRUE(std::isfinite(m.metrics.footprintMean));
    EXPECT_TRUE(std::isfinite(m.metrics.footprintMax));
    EXPECT_GE(m.metrics.misclassified, 0);
    EXPECT_LE(m.metrics.misclassified, o.receiverPixels);
}

// `sdsm-optimal` searches on the case's cascade energy (e with the prior by default), and
// `sdsm-optimal-h` on h whatever the case says: each is PartitionedLightMatrices on that energy.
TEST(Partitions, SdsmOptimalIsOnTheCasesEnergyAndSdsmOptimalHOnH) {
    const Walkthrough& w = SharedWalkthrough();
    const PartitionRun run = RunLight(w, w.lights.front());
    MethodContext context;
    context.baseline = run.context;
    context.samples = &run.outcome.samples;
    const auto sameMaps = [](const std::vector<Cascade>& a, const std::vector<Cascade>& b) {
        if (a.size() != b.size()) return false;
        for (std::size_t i = 0; i < a.size(); ++i)
            if (a[i].matrix.p1 != b[i].matrix.p1 || a[i].matrix.p2 != b[i].matrix.p2 ||
                a[i].matrix.p4 != b[i].matrix.p4 || a[i].map.width != b[i].map.width)
                return false;
        return true;
    };
    const auto direct = [&](const EnergyOptions& energy) {
        PartitionOptions options;
        options.energy = energy;
        return PartitionedLightMatrices(PartitionScheme::kSdsmOptimal, run.context,
                                        run.outcome.samples, options);
    };
    const std::vector<Cascade> onE = direct(kEdgeEnergy), onH = direct(EnergyOptions{});
    ASSERT_FALSE(sameMaps(onE, onH));  // the two energies choose different maps on this light
    EXPECT_TRUE(sameMaps(ComputeLightMatrix("sdsm-optimal", context).cascades, onE));
    EXPECT_TRUE(sameMaps(ComputeLightMatrix("sdsm-optimal-h", context).cascades, onH));
    context.partitions.energy = EnergyOptions{};  // a case's "cascades": {"energy": "h"}
    EXPECT_TRUE(sameMaps(ComputeLightMatrix("sdsm-optimal", context).cascades, onH));
    EXPECT_TRUE(sameMaps(ComputeLightMatrix("sdsm-optimal-h", context).cascades, onH));
}

}  // namespace
}  // namespace lexel::spatial
