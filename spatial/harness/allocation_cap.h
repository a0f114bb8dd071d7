// A cap on the memory the calling thread takes through operator new while a scope lives. Assimp
// reserves what a model file's counts say before it reads the values they count (a PLY face whose
// list length read 1.9e9 made it reserve 7.6 GB for a 303-byte file: the mesh_fuzzer input
// tests/fuzz/seeds/mesh/regress_ply_list_length.ply; Assimp no longer reads PLY: lexel has its own
// reader), and no check of a header sees every count of a body; LoadMesh reads each file under a
// cap proportional to its size.
//
// Linking this file replaces the global operator new and delete of the whole program (malloc and
// free underneath; the bytes a block holds are malloc_usable_size). Outside a scope they cost one
// thread-local test. The harness is lexel's own test bench, not installed, so no renderer that
// links lexel::spatial gets them. Under AddressSanitizer every block is still checked (malloc and
// free are its own); only its check that new pairs with delete is lost.
#pragma once

#include <cstddef>

namespace lexel::spatial {

class ScopedAllocationCap {
  public:
    static constexpr std::size_t kDefaultHeadroomBytes = std::size_t{16} << 20;
    // Until destruction, an allocation on this thread that would take the bytes held by blocks
    // allocated on it (less those freed on it) during the scope above `bytes` is refused:
    // operator new throws std::bad_alloc and the nothrow forms return nullptr. After the first
    // refusal `headroomAfterRefusal` bytes above the cap stay open for the refused code's error
    // handling (an exception's message; a destructor that allocates as it frees, as nlohmann's
    // json does) rather than a second std::bad_alloc thrown where none may be. Scopes do not
    // nest: a second on the same thread throws std::logic_error.
    explicit ScopedAllocationCap(std::size_t bytes,
                                 std::size_t headroomAfterRefusal = kDefaultHeadroomBytes);
    ~ScopedAllocationCap();
    ScopedAllocationCap(const ScopedAllocationCap&) = delete;
    ScopedAllocationCap& operator=(const ScopedAllocationCap&) = delete;

    // Whether an allocation was refused during the scope.
    bool Refused() const;
};

}  // namespace lexel::spatial
