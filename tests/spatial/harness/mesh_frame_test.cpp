// A mesh file's axes and units against the scene's: exact matrices and the named units.
#include "lexel/spatial/harness/mesh_frame.h"

#include <gtest/gtest.h>

namespace lexel::spatial {
namespace {

TEST(MeshFrame, ZUpTurnsUpToYAndKeepsHandedness) {
    const glm::dmat4 m = SceneFromFile({UpAxis::kZ, 0.01});
    // (x, y, z) ↦ 0.01 · (x, z, −y), exactly: a Z-up file's up is the scene's up, its forward
    // (+y) the scene's −z.
    EXPECT_EQ(glm::dvec3(m * glm::dvec4(1, 2, 3, 1)), glm::dvec3(0.01, 0.03, -0.02));
    EXPECT_EQ(glm::dvec3(m * glm::dvec4(0, 0, 1, 0)), glm::dvec3(0, 0.01, 0));
    EXPECT_NEAR(glm::determinant(m), 1e-6, 1e-20);  // a rotation times 0.01³: windings kept
    EXPECT_EQ(SceneFromFile({UpAxis::kY, 2.5}),
              glm::dmat4(glm::dvec4(2.5, 0, 0, 0), glm::dvec4(0, 2.5, 0, 0),
                         glm::dvec4(0, 0, 2.5, 0), glm::dvec4(0, 0, 0, 1)));
    EXPECT_EQ(SceneFromFile({}), glm::dmat4(1.0));
    EXPECT_STREQ(UpAxisName(UpAxis::kZ), "z");
}

TEST(MeshFrame, NamedUnitsAreTheirLengthInMetres) {
    EXPECT_EQ(UnitScaleByName("m"), 1.0);
    EXPECT_EQ(UnitScaleByName("cm"), 0.01);
    EXPECT_EQ(UnitScaleByName("mm"), 0.001);
    EXPECT_EQ(UnitScaleByName("km"), 1000.0);
    EXPECT_EQ(UnitScaleByName("in"), 0.0254);  // exact by definition (1959)
    EXPECT_EQ(UnitScaleByName("ft"), 0.3048);
    EXPECT_EQ(UnitScaleByName("M"), std::nullopt);
    EXPECT_EQ(UnitScaleByName("furlong"), std::nullopt);
}

}  // namespace
}  // namespace lexel::spatial
