// The global operator new and delete with a per-thread cap (see allocation_cap.h). Every form the
// standard lets a program replace is replaced, so no block is allocated by one allocator and freed
// by another.
#include "lexel/spatial/harness/allocation_cap.h"

#include <malloc.h>

#include <algorithm>
#include <cstdlib>
#include <new>
#include <stdexcept>

namespace lexel::spatial {
namespace {

// The calling thread's scope. Trivially destructible, so it stays usable while threads and the
// program end (blocks are freed then too).
struct ThreadCap {
    bool active = false;
    bool refused = false;
    long long heldBytes = 0;  // allocated minus freed on this thread during the scope
    long long capBytes = 0;
    long long headroomBytes = 0;  // open above the cap once it has refused
};
constinit thread_local ThreadCap tCap;

// nullptr when the cap refuses or malloc fails. `alignment` 0: the default alignment.
void* Allocate(std::size_t size, std::size_t alignment) noexcept {
    ThreadCap& cap = tCap;
    if (cap.active) {
        const long long room = cap.capBytes - cap.heldBytes + (cap.refused ? cap.headroomBytes : 0);
        if (room < 0 || size > static_cast<unsigned long long>(room)) {
            cap.refused = true;
            return nullptr;
        }
    }
    void* block = nullptr;
    if (alignment <= alignof(std::max_align_t))
        block = std::malloc(size == 0 ? 1 : size);
    else if (posix_memalign(&block, alignment, size == 0 ? 1 : size) != 0)
        block = nullptr;
    if (block != nullptr && cap.active)
        cap.heldBytes += static_cast<long long>(malloc_usable_size(block));
    return block;
}

void* AllocateOrThrow(std::size_t size, std::size_t alignment) {
    void* block = Allocate(size, alignment);
    if (block == nullptr) throw std::bad_alloc();
    return block;
}

void Free(void* block) noexcept {
    if (block == nullptr) return;
    ThreadCap& cap = tCap;
    if (cap.active) cap.heldBytes -= static_cast<long long>(malloc_usable_size(block));
    std::free(block);
}

}  // namespace

ScopedAllocationCap::ScopedAllocationCap(std::size_t bytes, std::size_t headroomAfterRefusal) {
    if (tCap.active) throw std::logic_error("ScopedAllocationCap: scopes do not nest");
    constexpr std::size_t kMost = std::size_t{1} << 61;  // no sum of the two overflows
    tCap =
        ThreadCap{.active = true,
                  .capBytes = static_cast<long long>(std::min(bytes, kMost)),
                  .headroomBytes = static_cast<long long>(std::min(headroomAfterRefusal, kMost))};
}

ScopedAllocationCap::~ScopedAllocationCap() { tCap = ThreadCap{}; }

bool ScopedAllocationCap::Refused() const { return tCap.refused; }

}  // namespace lexel::spatial

using lexel::spatial::Allocate;
using lexel::spatial::AllocateOrThrow;
using lexel::spatial::Free;

void* operator new(std::size_t n) { return AllocateOrThrow(n, 0); }
void* operator new[](std::size_t n) { return AllocateOrThrow(n, 0); }
void* operator new(std::size_t n, std::align_val_t a) {
    return AllocateOrThrow(n, static_cast<std::size_t>(a));
}
void* operator new[](std::size_t n, std::align_val_t a) {
    return AllocateOrThrow(n, static_cast<std::size_t>(a));
}
void* operator new(std::size_t n, const std::nothrow_t&) noexcept { return Allocate(n, 0); }
void* operator new[](std::size_t n, const std::nothrow_t&) noexcept { return Allocate(n, 0); }
void* operator new(std::size_t n, std::align_val_t a, const std::nothrow_t&) noexcept {
    return Allocate(n, static_cast<std::size_t>(a));
}
void* operator new[](std::size_t n, std::align_val_t a, const std::nothrow_t&) noexcept {
    return Allocate(n, static_cast<std::size_t>(a));
}
void operator delete(void* p) noexcept { Free(p); }
void operator delete[](void* p) noexcept { Free(p); }
void operator delete(void* p, std::size_t) noexcept { Free(p); }
void operator delete[](void* p, std::size_t) noexcept { Free(p); }
void operator delete(void* p, std::align_val_t) noexcept { Free(p); }
void operator delete[](void* p, std::align_val_t) noexcept { Free(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { Free(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { Free(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { Free(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { Free(p); }
void operator delete(void* p, std::align_val_t, const std::nothrow_t&) noexcept { Free(p); }
void operator delete[](void* p, std::align_val_t, const std::nothrow_t&) noexcept { Free(p); }
