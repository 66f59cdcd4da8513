// memory_reserve.h - memory held back so that a run whose allocation failed can still unwind.
//
// Usage:
//   keep_memory_reserve();   // at the start of main
// The first allocation by operator new that the system refuses frees the reserve and throws
// std::bad_alloc as usual: the destructors that run while the exception travels to main may
// allocate again (SystemC's module destructors do, moving their children to the top level),
// which without the reserve would throw inside a destructor and abort the process. Later
// failures throw std::bad_alloc as usual.
#pragma once

#include <cstddef>

namespace torusrt {

// Sets aside `bytes` (address space only: the pages are never touched) and installs the
// new-handler that frees them.
void keep_memory_reserve(size_t bytes = size_t{16} << 20);

}  // namespace torusrt
