#include "lexel/flatland/memory.h"

#include <algorithm>

#include "lexel/flatland/sampling.h"

namespace lexel::flatland {

// Where the bytes go (x86-64: 8-byte double and size_t, 4-byte int and uint32).
//
// Kept for the whole run, per pixel of each pass (RunSamplingPass reserves every pixel):
//     FlatSample       Vec2 wsPoint 16 + double lsAngle 8 + int pixel 4 + int segment 4 = 32
// (dp/dλ and g = |dp/dα| are recomputed from it; sampling.h). The full pass, and the decision
// pass when D ≠ P; with D = P the full pass is the decision pass.
//
// The largest of the working sets that follow each other (each freed before the next):
//   solve      LexelSamples tanOffset + footprint0, 8 + 8 = 16 per decision pixel, and the L∞
//              solver's envelope lines {a, b} 16 more (its hull is kept in place and candidates
//              are not stored): 32 D. Ceres has one residual per 4096 samples; the L1/L2 moments,
//              Newton and the sweep sum over the samples without storing.
//   measure    the decision samples still held (16 D) and one footprint f per full pixel (8 P);
//              the statistics' median reorders f in place.
//   plan split the decision samples released; a wedge index per decision pixel (uint32, 4) and
//              one group's LexelSamples (16, at most all samples): 20 D.
//   measure split  f per full pixel (8 P), each frustum's full-pass indices (uint32, 4, at most
//              8 with vector growth) and the largest frustum's f (at most 8 P): 24 P.
// With D = P the peak is 32 + max(32, 24, 20, 24) = 64 bytes per pixel (kRunBytesPerPixel).
//
// The rest is independent of the pixel counts: segments (FlatSegment: 2 Vec2 + 2 int = 40 bytes,
// held by up to three Segments() copies: both passes and the geometry check), and the split's
// tables: a std::map node per group [a, b] of wedges (32-byte tree header, 8-byte key, 40-byte
// Group, 16 bytes of malloc overhead: 96 bytes; the dynamic program visits all W(W+1)/2 groups)
// and its (B+1)(W+1) cost and back-pointer cells (8 + 4 bytes, plus the vector headers).
// A fixed 1 MiB covers the reports, the strings and the small vectors.
double FlatlandRunBytes(const FlatlandSizes& sizes) {
    static_assert(sizeof(FlatSample) == kPassBytesPerPixel);
    const double p = sizes.pixels, d = sizes.decisionPixels;
    const bool twoPasses = d != p;
    const double passes = kPassBytesPerPixel * (p + (twoPasses ? d : 0.0));
    const double working = std::max({32.0 * d, 16.0 * d + 8.0 * p, 20.0 * d, 24.0 * p});
    const double segments = 3.0 * 40.0 * sizes.segments;
    const double w = sizes.wedges;
    const double split =
        96.0 * w * (w + 1) / 2 + (sizes.budget + 1) * (w + 1) * 12.0 + (sizes.budget + 1) * 48.0;
    return passes + working + segments + split + 1024.0 * 1024.0;
}

FlatlandSizes SizesOf(const FlatScene& scene) {
    FlatlandSizes sizes;
    sizes.pixels = scene.camera.pixels;
    sizes.decisionPixels = scene.DecisionPixels();
    for (const auto& polyline : scene.geometry)
        sizes.segments += polyline.size() > 0 ? static_cast<double>(polyline.size()) - 1 : 0.0;
    const FrustaOptions frusta = scene.frusta.value_or(FrustaOptions{});
    sizes.wedges = frusta.max;
    sizes.budget = frusta.budget;
    return sizes;
}

}  // namespace lexel::flatland
