// Shared set-up of the OpenGL tests: the walkthrough scene, and a fixture that skips a test when
// this machine has no OpenGL 4.5 context — unless LEXEL_REQUIRE_GL=1 (bootstrap.sh test sets it:
// CI has llvmpipe), which turns the skip into a failure.
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <string>

#include "lexel/spatial/gl/context.h"
#include "lexel/spatial/harness/scene.h"

namespace lexel::spatial::testing {

inline bool GlRequired() {
    const char* v = std::getenv("LEXEL_REQUIRE_GL");
    return v != nullptr && std::strcmp(v, "1") == 0;
}

class GlTest : public ::testing::Test {
  protected:
    void SetUp() override {
        try {
            gl::Context::Shared();
        } catch (const gl::GlUnavailable& e) {
            if (GlRequired()) FAIL() << "LEXEL_REQUIRE_GL=1 but " << e.what();
            GTEST_SKIP() << e.what();
        }
    }
};

// cases/spatial/walkthrough.json, loaded once (report §3's scene: 17k triangles, 750² frame,
// 400² maps; a 720² readback with the optimizer's budget of 512 samples).
const Scene& Walkthrough();

// The same scene as the report set it up: a 180² readback and every sample to the optimizer.
const Scene& ReportWalkthrough();

}  // namespace lexel::spatial::testing
