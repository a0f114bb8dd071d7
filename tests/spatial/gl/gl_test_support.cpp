#include "spatial/gl/gl_test_support.h"

#include "lexel/cases/load/spatial_case.h"

namespace lexel::spatial::testing {

const Scene& Walkthrough() {
    static const Scene scene =
        cases::LoadSpatialScene(std::string(LEXEL_CASES_DIR) + "/spatial/walkthrough.json");
    return scene;
}

const Scene& ReportWalkthrough() {
    static const Scene scene = WithReportReadback(Walkthrough());
    return scene;
}

}  // namespace lexel::spatial::testing
