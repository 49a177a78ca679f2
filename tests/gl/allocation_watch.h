// The process's heap allocations through operator new, watched by replacing every form of the global
// operator new and delete (allocation_watch.cpp). Linked only into the test executables that watch them
// (tests/CMakeLists.txt); GL's own buffers and C libraries go through malloc and are not counted.
#pragma once

#include <cstddef>

namespace shadelab::test {

// Every operator-new request so far, of every form.
long allocationCount();
// The largest single request since resetLargestAllocation() (or the start).
std::size_t largestAllocation();
void resetLargestAllocation();

} // namespace shadelab::test
