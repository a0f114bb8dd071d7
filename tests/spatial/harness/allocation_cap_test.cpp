// ScopedAllocationCap: the per-thread cap under which LoadMesh lets Assimp read a file.
#include "lexel/spatial/harness/allocation_cap.h"

#include <gtest/gtest.h>

#include <memory>
#include <new>
#include <stdexcept>
#include <thread>
#include <vector>

namespace lexel::spatial {
namespace {

constexpr std::size_t kMiB = std::size_t{1} << 20;

TEST(AllocationCap, RefusesWhatWouldPassTheCapAndCountsFreedBlocks) {
    const ScopedAllocationCap cap(8 * kMiB);
    std::vector<char> held(5 * kMiB);
    EXPECT_THROW(std::vector<char>(4 * kMiB), std::bad_alloc);  // 5 + 4 > 8
    EXPECT_TRUE(cap.Refused());
    std::vector<char>().swap(held);  // freed inside the scope: its bytes are room again
    EXPECT_NO_THROW(std::vector<char>(7 * kMiB));
    // After a refusal 16 MiB above the cap stay open for error handling, and no more.
    const std::unique_ptr<char[]> handling(new (std::nothrow) char[9 * kMiB]);
    EXPECT_NE(handling, nullptr);
    EXPECT_EQ(new (std::nothrow) char[16 * kMiB], nullptr);
}

TEST(AllocationCap, HoldsOnlyInsideTheScopeAndOnItsThread) {
    {
        const ScopedAllocationCap cap(kMiB);
        std::unique_ptr<char[]> other;
        std::thread([&] { other = std::make_unique<char[]>(16 * kMiB); }).join();
        EXPECT_NE(other, nullptr);
        EXPECT_FALSE(cap.Refused());
        EXPECT_THROW(ScopedAllocationCap{kMiB}, std::logic_error);
    }
    EXPECT_NO_THROW(std::vector<char>(16 * kMiB));
}

}  // namespace
}  // namespace lexel::spatial
