// The OpenGL backend's results do not depend on the scene's scale or offset (issue 24): the
// similar scenes of scale_invariance_test.cpp (spatial_small mapped by x → s·x + o in its case
// file) evaluated on the GPU give the GPU's counts for the case itself — counted and truly
// shadowed pixels, boundary samples, misclassified and uncovered pixels per light and method —
// with h equal to rounding. Every float on the GPU is in the mesh's unit frame (gl_renderer.h); in
// world floats a scene 1e7 units from the origin lost its shape (a float's step there is 1).
// Measured on llvmpipe: identical counts and samples at scales 1e-12 … 1e12 and offsets up to 1e8
// bounding radii.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>

#include "lexel/spatial/gl/gl_backend.h"
#include "spatial/gl/gl_test_support.h"
#include "spatial/harness/similar_case.h"

namespace lexel::spatial {
namespace {

using testing::CaseCounts;
using testing::EvaluateCase;
using testing::GlTest;
using testing::ScaleTestSimilarities;
using testing::SimilarCase;
using testing::SmallCaseDocument;

std::unique_ptr<RenderBackend> Gl(const TriangleMesh& mesh) { return gl::MakeGlBackend(mesh); }

TEST_F(GlTest, ResultsDoNotDependOnTheScenesScaleOrOffset) {
    const nlohmann::json document = SmallCaseDocument();
    const CaseCounts reference = EvaluateCase(document, Gl);
    double worstH = 0.0;
    for (const testing::ScaleTestSimilarity& m : ScaleTestSimilarities()) {
        const CaseCounts c = EvaluateCase(SimilarCase(document, m.scale, m.offset), Gl);
        const std::string what = m.Describe();
        EXPECT_EQ(c.counted, reference.counted) << what;
        EXPECT_EQ(c.truthShadowed, reference.truthShadowed) << what;
        EXPECT_EQ(c.samplePixels, reference.samplePixels) << what;
        EXPECT_EQ(c.misclassified, reference.misclassified) << what;
        EXPECT_EQ(c.uncovered, reference.uncovered) << what;
        const double h = testing::WorstRelativeH(c, reference);
        std::cout << "[   INFO   ] " << what << ": h within " << h << '\n';
        EXPECT_LE(h, m.hTolerance) << what;
        worstH = std::max(worstH, h);
    }
    std::cout << "[   INFO   ] " << ScaleTestSimilarities().size()
              << " similar scenes on gl: identical counts and samples, h within " << worstH
              << " of the case's\n";
}

}  // namespace
}  // namespace lexel::spatial
