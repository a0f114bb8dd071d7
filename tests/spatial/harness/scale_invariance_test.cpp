// 3D results do not depend on where a scene sits or how large it is: the CLI test case
// spatial_small mapped by x → s·x + o in its case file (similar_case.h) gives, on the CPU
// backend, the case's counted and truly shadowed pixels, boundary samples, and misclassified and
// uncovered pixels for every method and light, with h equal to rounding, at scales 1e-12 … 1e12
// and offsets up to the loader's bounds. Before the scene's unit frame (scene.h) and the
// eye-relative camera pass (cpu_renderer.cpp), on this case: 1e4 units from the origin the truth
// rays found 98.6% of the counted pixels shadowed (1009 → 55,517), at scale 1e-20 none;
// plane-optimal fell back to focused at scales 1e-18 and 1e12 (1e14 from the origin) and 1e6
// units from the origin; the boundary samples thinned out from 1e6 units (373 → 364, 214 at 1e7).
// Outside the range the loader refuses the case.
#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <string>

#include "lexel/solvers/errors.h"
#include "spatial/harness/similar_case.h"

namespace lexel::spatial {
namespace {

using testing::CaseCounts;
using testing::SimilarCase;
using testing::SmallCaseDocument;

std::unique_ptr<RenderBackend> Cpu(const TriangleMesh& mesh) { return MakeCpuRenderer(mesh); }

TEST(ScaleInvariance, CpuResultsDoNotDependOnTheScenesScaleOrOffset) {
    const CaseCounts reference = testing::ExpectResultsIndependentOfScaleAndOffset(Cpu, "cpu");
    // The case has shadows and boundary samples to lose: over its five lights 1009 truly shadowed
    // pixels of 56,285 counted, 373 samples.
    std::int64_t shadowed = 0;
    std::size_t samples = 0;
    for (std::size_t l = 0; l < reference.counted.size(); ++l) {
        shadowed += reference.truthShadowed[l];
        samples += reference.samplePixels[l].size();
    }
    EXPECT_EQ(shadowed, 1009);
    EXPECT_EQ(samples, 373u);
}

std::string LoadError(const nlohmann::json& document) {
    try {
        cases::SpatialSceneFromJson(document, "similar", testing::SmallCaseDir());
    } catch (const InputError& e) {
        return e.what();
    }
    return "no error";
}

// The bounds of spatial_case.h: a scene at least 1e-15 across (here 28.4·s), centred at most 1e8
// of its bounding radii (14.18·s) from the origin.
TEST(ScaleInvariance, TheLoaderRefusesScenesOutsideTheRange) {
    const nlohmann::json document = SmallCaseDocument();
    const glm::dvec3 direction(1.0, -0.5, 0.25);
    EXPECT_EQ(LoadError(SimilarCase(document, 1e-16, glm::dvec3(0.0))), "no error");
    EXPECT_EQ(LoadError(SimilarCase(document, 1e-17, glm::dvec3(0.0))),
              "/geometry: the scene is 2.84e-16 across (its bounds' diagonal), must be at least "
              "1e-15");
    EXPECT_EQ(LoadError(SimilarCase(document, 1.0, 1.2255e9 * direction)), "no error");
    EXPECT_EQ(LoadError(SimilarCase(document, 1.0, 1.3e9 * direction)),
              "/geometry: the scene's centre [1300000000, -649999999, 325000000] is 1.05e+08 "
              "bounding radii from the origin, must be at most 1e+08 (farther, its coordinates "
              "keep under 8 digits within the scene); move it nearer the origin");
}

}  // namespace
}  // namespace lexel::spatial
