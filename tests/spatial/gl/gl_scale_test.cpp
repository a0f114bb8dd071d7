// The OpenGL backend's results do not depend on the scene's scale or offset: the
// similar scenes of scale_invariance_test.cpp (spatial_small mapped by x → s·x + o in its case
// file) evaluated on the GPU give the GPU's counts for the case itself — counted and truly
// shadowed pixels, boundary samples, misclassified and uncovered pixels per light and method —
// with h equal to rounding. Every float on the GPU is in the mesh's unit frame (gl_renderer.h); in
// world floats a scene 1e7 units from the origin lost its shape (a float's step there is 1).
// Measured on llvmpipe: identical counts and samples at scales 1e-12 … 1e12 and offsets up to 1e8
// bounding radii.
#include <gtest/gtest.h>

#include "lexel/spatial/gl/gl_backend.h"
#include "spatial/gl/gl_test_support.h"
#include "spatial/harness/similar_case.h"

namespace lexel::spatial {
namespace {

using testing::GlTest;

std::unique_ptr<RenderBackend> Gl(const TriangleMesh& mesh) { return gl::MakeGlBackend(mesh); }

TEST_F(GlTest, ResultsDoNotDependOnTheScenesScaleOrOffset) {
    testing::ExpectResultsIndependentOfScaleAndOffset(Gl, "gl");
}

}  // namespace
}  // namespace lexel::spatial
