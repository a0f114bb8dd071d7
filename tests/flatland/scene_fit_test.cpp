// Scene families and the inverse fit (flatland/studies/scene_family.h,
// flatland/studies/scene_fit.h): the families honor the constraints they claim, the comparison
// measures what `lexel tables` measures, and the fit recovers a scene from the numbers lexel itself
// printed for it.
#include "lexel/flatland/studies/scene_fit.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <random>
#include <sstream>

#include "lexel/flatland/lexel_remap.h"
#include "lexel/flatland/methods.h"
#include "lexel/flatland/sampling.h"
#include "lexel/flatland/studies/scene_family.h"
#include "lexel/solvers/errors.h"

namespace lexel::flatland {
namespace {

std::string Describe(const SceneFamily& family, std::span<const double> values) {
    std::ostringstream out;
    out.precision(17);
    out << family.name << ":";
    for (std::size_t i = 0; i < values.size(); ++i)
        out << " " << family.parameters[i].name << "=" << values[i];
    return out.str();
}

// A parameter vector drawn uniformly from the middle half of every range (log for logScale).
std::vector<double> MiddleSample(const SceneFamily& family, std::mt19937_64& rng) {
    std::uniform_real_distribution<double> unit(0.25, 0.75);
    std::vector<double> values;
    for (const auto& p : family.parameters) {
        const double u = unit(rng);
        values.push_back(p.logScale
                             ? std::exp(std::log(p.lo) + u * (std::log(p.hi) - std::log(p.lo)))
                             : p.lo + u * (p.hi - p.lo));
    }
    return values;
}

// The table lexel prints for `scene`, at full precision, in the layout of `layout`.
PublishedTable OwnTable(const FlatScene& scene, PublishedTable layout) {
    for (const ComparedNumber& n : CompareWithTable(scene, layout)) {
        PublishedRow& row = layout.rows[n.row];
        switch (n.quantity) {
            case Quantity::kAngle:
                row.angleDeg = n.value;
                break;
            case Quantity::kWorst:
                row.worst = n.value;
                break;
            case Quantity::kAverage:
                row.average = n.value;
                break;
            case Quantity::kMeanPlusSigma:
                row.meanPlusSigma = n.value;
                break;
            case Quantity::kTwoFrustaMean:
                row.twoFrustaMean = n.value;
                break;
        }
    }
    return layout;
}

// The rows of the thesis's single-plane table (values are replaced by OwnTable).
PublishedTable SinglePlaneLayout() {
    PublishedTable table;
    table.rows = {{"Our Method (both)", "optimal-l1", 9, 1, 1, 1},
                  {"Perspective SM", "psm-thesis", 91, 1, 1, 1},
                  {"Normal SM", "normal", 51, 1, 1, 1}};
    return table;
}

// Theorem 1 (Chong 2003 §2.2.1): the single-plane family puts the light on the 9° line through
// q, so its optimum is exactly the printed 9° with a constant footprint.
TEST(SceneFamily, SinglePlaneOptimumIsThePrintedAngle) {
    const SceneFamily family = SinglePlaneFamily();
    std::mt19937_64 rng(11);
    for (int trial = 0; trial < 6; ++trial) {
        const auto values = MiddleSample(family, rng);
        const FlatScene scene = family.Build(values);
        const std::vector<std::string> methods = {"optimal-l1", "optimal-l2"};
        const CaseReport report = RunFlatlandCase(scene, methods, Metric::kL1);
        for (const auto& m : report.methods) {
            EXPECT_NEAR(m.lexelPlaneDeg, 9.0, 1e-6) << m.method << " " << Describe(family, values);
            EXPECT_LT(m.stats.worst() / m.stats.average - 1.0, 1e-9) << Describe(family, values);
        }
    }
}

// The near plane is the given fraction of the nearest depth in view: never more than the
// nearest visible sample's depth, and within a pixel's worth of it.
TEST(SceneFamily, NearPlaneIsAFractionOfTheNearestVisibleDepth) {
    std::mt19937_64 rng(12);
    for (const SceneFamily& family : ThesisFamilies()) {
        int checked = 0;
        for (int trial = 0; trial < 40 && checked < 4; ++trial) {
            const auto values = MiddleSample(family, rng);
            const FlatScene scene = family.Build(values);
            const std::optional<SamplingPass> pass = TrySamplingPass(scene, scene.camera.pixels);
            if (!pass) continue;  // the family's ranges include scenes the sampling pass refuses
            const double minDepth = pass->depthNear;
            int nearIndex = 0;
            for (std::size_t i = 0; i < family.parameters.size(); ++i)
                if (family.parameters[i].name == "near_fraction") nearIndex = static_cast<int>(i);
            const double nearest = scene.camera.near / values[nearIndex];
            EXPECT_LE(nearest, minDepth * (1 + 1e-12)) << Describe(family, values);
            EXPECT_GT(nearest, 0.98 * minDepth) << Describe(family, values);
            ++checked;
        }
        EXPECT_EQ(checked, 4) << family.name;
    }
}

// The comparison is `lexel tables`' measurement: RunFlatlandCase's numbers, angles mod 180°,
// footprints relative.
TEST(SceneFit, CompareWithTableIsRunFlatlandCase) {
    const SceneFamily family = ProjectionAliasingFamily();
    const std::vector<double> values = {10, 40, 8, 0, 3, 0, 2, 2, 0.5, 100};
    const FlatScene scene = family.Build(values);
    const std::vector<std::string> methods = {"optimal-l1", "split-dp"};
    const CaseReport report = RunFlatlandCase(scene, methods, Metric::kL1);
    const MethodReport& l1 = report.methods[0];
    PublishedTable table;
    // 180° off the measured angle is the same lexel plane; the footprints are off by +10%.
    table.rows = {{"row", "optimal-l1", l1.lexelPlaneDeg + 180.0, 1.1 * l1.stats.worst(),
                   1.1 * l1.stats.average, 1.1 * l1.stats.meanPlusSigma,
                   1.1 * report.methods[1].stats.average}};
    const auto numbers = CompareWithTable(scene, table);
    ASSERT_EQ(numbers.size(), 5u);
    EXPECT_NEAR(numbers[0].error, 0.0, 1e-9);
    for (int i = 1; i < 5; ++i) EXPECT_NEAR(numbers[i].error, 1.0 / 1.1 - 1.0, 1e-12) << i;
    const TableAgreement a = Agreement(numbers, {});
    EXPECT_NEAR(a.worstFootprint, 1.0 - 1.0 / 1.1, 1e-12);
    EXPECT_NEAR(a.worstNormalized, (1.0 - 1.0 / 1.1) / 0.1, 1e-9);
    EXPECT_TRUE(a.accepted);
}

// Every footprint is N-proportional (lexel_remap.h, R1): the scale that lets a fit move the
// lexel count continuously is exact.
TEST(SceneFit, FootprintsScaleExactlyWithTheLexelCount) {
    const SceneFamily family = LightFromTopFamily();
    const std::vector<double> values = {10, 40, 6, 3, 0, 2, 2, 0.5, 250.4};
    const FlatScene scene = family.Build(values);
    ASSERT_EQ(scene.lexels, 250);
    const SamplingPass pass = RunSamplingPass(scene, scene.camera.pixels);
    const double axis = pass.wsAxis0 + 0.3;
    const auto atReal = FootprintsFromScratch(pass, scene.wsLight, axis, 250.4);
    const auto atInteger = FootprintsFromScratch(pass, scene.wsLight, axis, 250);
    ASSERT_TRUE(atReal && atInteger);
    const double scale = family.FootprintScale(values);
    EXPECT_DOUBLE_EQ(scale, 250.0 / 250.4);
    for (std::size_t i = 0; i < atReal->size(); ++i)
        EXPECT_NEAR((*atInteger)[i] * scale / (*atReal)[i], 1.0, 1e-13) << i;
}

// Central-difference Jacobian of the residuals, in units of each parameter's range.
Eigen::MatrixXd ResidualJacobian(const SceneFamily& family, const PublishedTable& table,
                                 const std::vector<double>& values) {
    const auto r0 = FamilyResiduals(family, table, values);
    Eigen::MatrixXd jacobian(r0.size(), values.size());
    for (std::size_t j = 0; j < values.size(); ++j) {
        const auto& p = family.parameters[j];
        const double step = 1e-5 * (p.logScale ? values[j] * std::log(p.hi / p.lo) : p.hi - p.lo);
        auto plus = values, minus = values;
        plus[j] += step, minus[j] -= step;
        const auto rPlus = FamilyResiduals(family, table, plus);
        const auto rMinus = FamilyResiduals(family, table, minus);
        for (std::size_t i = 0; i < r0.size(); ++i) jacobian(i, j) = (rPlus[i] - rMinus[i]) / 2e-5;
    }
    return jacobian;
}

// The single-plane table determines four combinations of the family's five parameters: at a
// single plane every row's footprints depend on the scene only through the light's view of
// the visible floor's two ends, PSM's angle and N (footprints at the optimum are constant by
// Theorem 1 and the pixels sample the lexel range uniformly). The Jacobian has one null
// direction; fixing the field of view removes it.
TEST(SceneFit, SinglePlaneTableDeterminesFourOfFiveParameters) {
    const SceneFamily family = SinglePlaneFamily();
    const std::vector<double> values = {35, 40, 8, 0.3, 1000};  // every pixel sees the floor
    const FlatScene scene = family.Build(values);
    const PublishedTable table = OwnTable(scene, SinglePlaneLayout());
    const Eigen::VectorXd full =
        Eigen::JacobiSVD<Eigen::MatrixXd>(ResidualJacobian(family, table, values)).singularValues();
    EXPECT_LT(full(4), 1e-6 * full(0)) << full.transpose();
    EXPECT_GT(full(3), 1e-2 * full(0)) << full.transpose();

    const SceneFamily fixed = FixParameter(family, "fov_deg", 40);
    const std::vector<double> rest = {35, 8, 0.3, 1000};
    const Eigen::VectorXd reduced =
        Eigen::JacobiSVD<Eigen::MatrixXd>(ResidualJacobian(fixed, table, rest)).singularValues();
    EXPECT_GT(reduced(3), 1e-2 * reduced(0)) << reduced.transpose();
}

// The inverse problem on lexel's own numbers: a random single-plane scene (field of view fixed,
// every pixel on the floor so no pixel changes what it sees), its table at full precision, and
// a start 2% of each range away; the fit returns the scene's parameters to 1e-4.
TEST(SceneFit, RecoversParametersFromItsOwnNumbers) {
    std::mt19937_64 rng(2024);
    std::uniform_real_distribution<double> fovDist(20.0, 60.0), sign(-1.0, 1.0);
    int recovered = 0;
    for (int trial = 0; recovered < 4 && trial < 50; ++trial) {
        const double fov = fovDist(rng);
        const SceneFamily family = FixParameter(SinglePlaneFamily(), "fov_deg", fov);
        std::vector<double> truth = MiddleSample(family, rng);
        truth[family.lexelsIndex] = std::round(truth[family.lexelsIndex]);
        if (truth[0] - 0.5 * fov < 5.0) continue;  // the top ray must hit the floor
        const FlatScene scene = family.Build(truth);
        const PublishedTable table = OwnTable(scene, SinglePlaneLayout());
        std::vector<double> start = truth;
        for (std::size_t i = 0; i < start.size(); ++i) {
            const auto& p = family.parameters[i];
            const double d = 0.02 * sign(rng);
            start[i] = p.logScale ? truth[i] * std::exp(d * std::log(p.hi / p.lo))
                                  : truth[i] + d * (p.hi - p.lo);
        }
        const FitResult fit = RefineFamily(family, table, start, FitOptions{});
        for (std::size_t i = 0; i < truth.size(); ++i)
            EXPECT_NEAR(fit.parameters[i] / truth[i], 1.0, 1e-4)
                << family.parameters[i].name << "; fov_deg=" << fov << "; truth "
                << Describe(family, truth) << "; start " << Describe(family, start);
        EXPECT_LT(fit.agreement.worstNormalized, 1e-6);
        ++recovered;
    }
    EXPECT_EQ(recovered, 4);
}

// A table with one number corrupted: leaving that number out lets the fit meet all the others,
// leaving out any other number does not.
TEST(SceneFit, DropOneAnalysisFindsTheInconsistentNumber) {
    const SceneFamily family = FixParameter(SinglePlaneFamily(), "fov_deg", 40);
    const std::vector<double> truth = {35, 8, 0.3, 1000};
    PublishedTable table = OwnTable(family.Build(truth), SinglePlaneLayout());
    table.rows[2].average *= 1.5;  // Normal's average, the 11th number
    const auto dropped = DropOneAnalysis(family, table, truth, FitOptions{});
    ASSERT_EQ(dropped.size(), 12u);
    for (const auto& d : dropped) {
        if (d.number == 10) {
            EXPECT_LT(d.restWorstNormalized, 1e-3);
            EXPECT_NEAR(d.droppedNormalized, (1.0 - 1.0 / 1.5) / 0.1, 1e-3);
        } else {
            EXPECT_GT(d.restWorstNormalized, 1.0) << "number " << d.number;
        }
    }
}

// A scene lexel refuses is a return value for the search and an error for a caller that asked
// for that scene: a camera looking up past a short plank sees nothing, and a split needs at least
// as many lexels as its frustum budget.
TEST(SceneFit, RefusedScenesAreReturnValuesForTheSearch) {
    const SceneFamily family = ProjectionAliasingFamily();
    const std::vector<double> skyward = {-30, 10, 40, 0, 0.1, 0, 2, 2, 0.5, 100};
    PublishedTable table;
    table.rows = {{"row", "optimal-l1", 30, 1, 1, 1, 1}};
    std::optional<DomainError> defect;
    EXPECT_FALSE(TryCompareWithTable(family.Build(skyward), table, 1.0, &defect));
    ASSERT_TRUE(defect.has_value());
    EXPECT_EQ(defect->subject(), Subject::kGeometry);
    EXPECT_TRUE(FamilyResiduals(family, table, skyward).empty());
    EXPECT_THROW(CompareWithTable(family.Build(skyward), table), DomainError);
    EXPECT_THROW(EvaluateFamily(family, table, skyward), DomainError);
    EXPECT_THROW(RefineFamily(family, table, skyward, FitOptions{}), DomainError);

    const std::vector<double> seen = {10, 40, 8, 0, 3, 0, 2, 2, 0.5, 100};
    FlatScene few = family.Build(seen);
    ASSERT_TRUE(TryCompareWithTable(few, table));
    few.lexels = few.frusta->budget - 1;
    defect.reset();
    EXPECT_FALSE(TryCompareWithTable(few, table, 1.0, &defect));
    ASSERT_TRUE(defect.has_value());
    EXPECT_EQ(defect->subject(), Subject::kLexels);
    // Without the two-frusta mean the table needs no split, and the scene is measured.
    table.rows[0].twoFrustaMean = NAN;
    EXPECT_TRUE(TryCompareWithTable(few, table));
}

TEST(SceneFamily, UnknownNamesAreErrors) {
    EXPECT_EQ(FindFamily("nope"), nullptr);
    EXPECT_THROW(FixParameter(SinglePlaneFamily(), "nope", 1.0), std::invalid_argument);
    EXPECT_THROW(FixParameter(SinglePlaneFamily(), "lexels", 1.0), std::invalid_argument);
    ASSERT_NE(FindFamily("light_from_top"), nullptr);
    EXPECT_EQ(FindFamily("light_from_top")->name, "light_from_top");
}

}  // namespace
}  // namespace lexel::flatland
