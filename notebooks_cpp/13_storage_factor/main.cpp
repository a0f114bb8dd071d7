// 13 — Lloyd's storage factor against the warping parameter η (Lloyd et al. 2006, §4, Fig. 6).
//
// How large must a shadow map be to have no perspective aliasing anywhere in the view frustum?
// With the light overhead, a warp whose projection centre sits n' before the near plane gives
// maximum errors M_x, M_z (eqs. 9–10), and the critical map is S̄ = M_x M_z times the image
// (the storage factor, eq. 12):
//     S̄ = (f/n − 1) / (2 tanθ) · [1 if n' ≤ n'_LiSPSM = n + √(fn), else n'² f / (n (n' + f − n)²)].
// η ∈ [−1, 1] (eq. 11, Appendix B) runs n' from ∞ (unwarped, η = −1) through n'_LiSPSM (η = 0,
// LiSPSM) to n (η = 1, PSM). No single map does better than the logarithmic parameterization,
// S̄_opt = ln(f/n) / (2 tanθ) (Appendix C). This program sweeps η for Fig. 6's frustum (n = 1,
// f = 100, θ = 30°) and prints S̄ from unwarped to LiSPSM against the optimum. The checks: the
// sweep's S̄ equals the general-direction vertex rule (§4.4) at every η to 1e-9; S̄ is flat at its
// least value (f/n − 1)/(2 tanθ) for η ∈ [0, 1]; unwarped costs f/n times that; nothing beats
// S̄_opt.
//
// Public API: lexel::spatial_studies (spatial/studies/storage_factor.h, a study, not installed).
// Figure: the program's own plot helper.
//
//   ./build/notebooks_cpp/notebook_13_storage_factor [OUT_DIR]    (default out/notebooks/)
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "lexel/spatial/studies/storage_factor.h"
#include "notebook.h"
#include "plot.h"

int main(int argc, char** argv) {
    using namespace lexel::spatial;
    using lexel::notebooks::Series;
    const auto outDir = lexel::notebooks::OutputDirectory(argc, argv);
    ViewFrustum frustum;  // Fig. 6: n = 1, f = 100; θ = 30° (a 60° field of view), square image
    frustum.fovYDeg = 60, frustum.nearPlane = 1, frustum.farPlane = 100;
    const double ratio = frustum.DepthRatio(), tanTheta = frustum.TanHalfFovY();
    const double warped = (ratio - 1) / (2 * tanTheta), optimal = OptimalStorageFactor(frustum);
    const std::vector<WarpSweepPoint> sweep = WarpSweep(frustum, 201);
    const glm::dvec3 overhead = DirectionToLight(90.0);

    Series mx("M_x / max"), mz("M_z / max"), storage("S (eq. 12)");
    Series best("S_opt (log)", Series::Style::kDashed);
    double maxMx = 0, maxMz = 0, vertexGap = 0, leastFlat = INFINITY, mostFlat = 0;
    for (const WarpSweepPoint& p : sweep)
        maxMx = std::max(maxMx, p.maxErrors.x), maxMz = std::max(maxMz, p.maxErrors.z);
    std::printf("%8s %12s %10s %10s %12s\n", "eta", "n'", "M_x", "M_z", "S");
    for (std::size_t k = 0; k < sweep.size(); ++k) {
        const WarpSweepPoint& p = sweep[k];
        if (k % 25 == 0)
            std::printf("%8.3f %12.4g %10.4f %10.4f %12.4f\n", p.eta, p.nPrime, p.maxErrors.x,
                        p.maxErrors.z, p.storage);
        const double vertexRule = StorageFactorForWarpOffset(frustum, overhead, p.nPrime);
        vertexGap = std::max(vertexGap, std::abs(vertexRule / p.storage - 1));
        if (p.eta >= 0)
            leastFlat = std::min(leastFlat, p.storage), mostFlat = std::max(mostFlat, p.storage);
        mx.Add(p.eta, p.maxErrors.x / maxMx);
        mz.Add(p.eta, p.maxErrors.z / maxMz);
        storage.Add(p.eta, p.storage);
        best.Add(p.eta, optimal);
    }
    const double unwarped = sweep.front().storage;
    std::printf(
        "storage factor, unwarped (η = -1) → LiSPSM (η = 0): %.4f → %.4f; "
        "logarithmic optimum %.4f\n",
        unwarped, OverheadStorageFactor(frustum, WarpOffsetFromEta(0, 1, 100)), optimal);
    std::printf(
        "n'_LiSPSM = n + √(fn) = %.4f; a critical map is %.1f× the image with LiSPSM, "
        "%.1f× unwarped\n",
        LispsmWarpOffset(1, 100), warped, unwarped);

    lexel::notebooks::Claims claims;
    claims.Check(vertexGap < 1e-9, "eq. 12 = the vertex rule of §4.4 at 201 values of η (%.1e)",
                 vertexGap);
    claims.Check(
        std::abs(leastFlat / warped - 1) < 1e-12 && std::abs(mostFlat / warped - 1) < 1e-12,
        "S is flat at (f/n - 1)/(2 tanθ) = %.9f for η in [0, 1] (%.9f to %.9f)", warped, leastFlat,
        mostFlat);
    claims.Check(std::abs(unwarped / (warped * ratio) - 1) < 1e-12,
                 "unwarped costs f/n = %g times more: %.6f = %.6f", ratio, unwarped,
                 warped * ratio);
    const double least =
        std::min_element(sweep.begin(), sweep.end(), [](const auto& a, const auto& b) {
            return a.storage < b.storage;
        })->storage;
    claims.Check(least > optimal && std::abs(optimal - std::log(ratio) / (2 * tanTheta)) < 1e-12,
                 "no warp beats S_opt = ln(f/n)/(2 tanθ) = %.6f (least %.6f)", optimal, least);
    const auto figure = outDir / "13_storage_factor.png";
    lexel::notebooks::Panel errors("Fig. 6: maximum errors (normalized)", "η", "M / max");
    lexel::notebooks::Panel storagePanel("storage factor S against η (n = 1, f = 100)", "η",
                                         "S (map texels per image pixel)", true);
    errors.series = {mx, mz};
    storagePanel.series = {storage, best};
    lexel::notebooks::WritePlot(figure, {errors, storagePanel});
    std::printf("wrote %s\n", figure.c_str());
    return claims.ExitStatus();
}
