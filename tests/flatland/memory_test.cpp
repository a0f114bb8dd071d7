// FlatlandRunBytes (flatland/memory.h) against what a run really allocates. This executable
// replaces the global operator new and delete with counting ones (malloc_usable_size of each
// block), so it runs alone: the peak of the bytes live through operator new during a run, above
// what was live before it, is the run's allocation. Eigen's own aligned mallocs are not counted;
// flatland has none per sample.
#include "lexel/flatland/memory.h"

#include <gtest/gtest.h>
#include <malloc.h>

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <new>
#include <string>
#include <vector>

#include "lexel/flatland/methods.h"

namespace {

std::atomic<long long> gLiveBytes{0};
std::atomic<long long> gPeakBytes{0};

void* CountedAlloc(std::size_t size, std::size_t alignment) {
    void* p = nullptr;
    if (alignment <= alignof(std::max_align_t))
        p = std::malloc(size == 0 ? 1 : size);
    else if (posix_memalign(&p, alignment, size == 0 ? 1 : size) != 0)
        p = nullptr;
    if (!p) return nullptr;
    const long long live = gLiveBytes += static_cast<long long>(malloc_usable_size(p));
    long long peak = gPeakBytes.load();
    while (live > peak && !gPeakBytes.compare_exchange_weak(peak, live)) {
    }
    return p;
}

void CountedFree(void* p) noexcept {
    if (!p) return;
    gLiveBytes -= static_cast<long long>(malloc_usable_size(p));
    std::free(p);
}

void* CountedNew(std::size_t size, std::size_t alignment) {
    void* p = CountedAlloc(size, alignment);
    if (!p) throw std::bad_alloc();
    return p;
}

}  // namespace

void* operator new(std::size_t n) { return CountedNew(n, 0); }
void* operator new[](std::size_t n) { return CountedNew(n, 0); }
void* operator new(std::size_t n, std::align_val_t a) {
    return CountedNew(n, static_cast<std::size_t>(a));
}
void* operator new[](std::size_t n, std::align_val_t a) {
    return CountedNew(n, static_cast<std::size_t>(a));
}
void* operator new(std::size_t n, const std::nothrow_t&) noexcept { return CountedAlloc(n, 0); }
void* operator new[](std::size_t n, const std::nothrow_t&) noexcept { return CountedAlloc(n, 0); }
void operator delete(void* p) noexcept { CountedFree(p); }
void operator delete[](void* p) noexcept { CountedFree(p); }
void operator delete(void* p, std::size_t) noexcept { CountedFree(p); }
void operator delete[](void* p, std::size_t) noexcept { CountedFree(p); }
void operator delete(void* p, std::align_val_t) noexcept { CountedFree(p); }
void operator delete[](void* p, std::align_val_t) noexcept { CountedFree(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { CountedFree(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { CountedFree(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { CountedFree(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { CountedFree(p); }

namespace lexel::flatland {
namespace {

// The thesis's single plane (cases/flatland/single_plane.json) at `pixels`: 94% of them see
// the floor.
FlatScene SinglePlane(int pixels, int decisionPixels) {
    FlatScene scene;
    scene.name = "single_plane";
    scene.camera.wsPosition = {0, 2};
    scene.camera.wsDirection = Vec2(-1, -0.55).normalized();
    scene.camera.fovDeg = 60;
    scene.camera.pixels = pixels;
    scene.camera.near = 0.1;
    scene.camera.far = 100;
    scene.wsLight = {-0.484, 10};
    scene.lexels = 1000;
    scene.decisionPixels = decisionPixels;
    scene.geometry = {{{-60, 0}, {20, 0}}};
    return scene;
}

// Peak bytes allocated (above those live before) by running every method on the scene, as
// `lexel run` does.
double MeasuredRunBytes(const FlatScene& scene) {
    const long long before = gLiveBytes.load();
    gPeakBytes = before;
    {
        const CaseReport report = RunFlatlandCase(scene, FlatlandMethodNames(), Metric::kL1);
        EXPECT_EQ(report.methods.size(), FlatlandMethodNames().size());
    }
    return static_cast<double>(gPeakBytes.load() - before);
}

TEST(FlatlandMemory, EstimateBoundsTheMeasuredPeakOfOnePass) {
    const int pixels = 100'000;
    const FlatScene scene = SinglePlane(pixels, 0);
    const double estimate = FlatlandRunBytes(SizesOf(scene));
    const double measured = MeasuredRunBytes(scene);
    RecordProperty("bytes_per_pixel", std::to_string(measured / pixels));
    EXPECT_LE(measured, estimate) << "measured " << measured / pixels << " bytes per pixel";
    // The goal (at most 64 bytes a pixel), and an estimate that is an upper bound without being
    // loose.
    EXPECT_LE(measured / pixels, kRunBytesPerPixel);
    EXPECT_GE(measured, 0.7 * estimate) << "estimate " << estimate << ", measured " << measured;
}

TEST(FlatlandMemory, EstimateBoundsTheMeasuredPeakOfTwoPasses) {
    for (const int decisionPixels : {10'000, 100'001}) {
        const FlatScene scene = SinglePlane(100'000, decisionPixels);
        const double estimate = FlatlandRunBytes(SizesOf(scene));
        const double measured = MeasuredRunBytes(scene);
        EXPECT_LE(measured, estimate) << "decision pixels " << decisionPixels;
        EXPECT_GE(measured, 0.6 * estimate) << "decision pixels " << decisionPixels;
    }
}

// A split plan over many wedges: the per-group cache and the dynamic program's tables count.
TEST(FlatlandMemory, EstimateBoundsASplitOverManyWedges) {
    FlatScene scene = SinglePlane(5'000, 0);
    scene.frusta = FrustaOptions{128, 8, Metric::kL1};
    const double estimate = FlatlandRunBytes(SizesOf(scene));
    const long long before = gLiveBytes.load();
    gPeakBytes = before;
    RunFlatlandCase(scene, std::vector<std::string>{"split-dp"}, Metric::kL1);
    const double measured = static_cast<double>(gPeakBytes.load() - before);
    EXPECT_LE(measured, estimate);
}

}  // namespace
}  // namespace lexel::flatland
