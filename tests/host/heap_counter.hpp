// Counts every heap allocation of the test program (malloc, calloc, realloc,
// aligned_alloc, posix_memalign and every operator new), so a test can prove that a
// stretch of code never touched the heap. See heap_counter.cpp.
#pragma once

#include <cstddef>

namespace aloft_test {

// Allocations since the program started; read before and after the code under test.
std::size_t heap_allocations();

}  // namespace aloft_test
