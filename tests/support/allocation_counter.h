#pragma once
// Counts heap allocations: allocation_counter.cc interposes the C allocator, so link it only
// into an executable of its own.

namespace cbbg::testing {

// Calls of malloc, calloc, realloc and the aligned allocators since the program started.
// Counting the C allocator, not operator new, also catches Eigen, whose dynamic matrices
// allocate with std::malloc; operator new ends in malloc too.
long long allocation_count();

}  // namespace cbbg::testing
