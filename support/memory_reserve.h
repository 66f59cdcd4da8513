// memory_reserve.h - memory held back so that a run whose allocation failed can still unwind.
//
// Usage:
//   keep_memory_reserve();   // at the start of main
//   keep_memory_reserve();   // again before a large build (the machine): the reserve made whole
// Each allocation by operator new that the system refuses frees one of the reserve's eight
// blocks and throws std::bad_alloc as usual: the destructors that run while the exception
// travels to main may allocate again (SystemC's module destructors do, moving their children to
// the top level), which without the reserve would throw inside a destructor and abort the
// process. A failure caught and dropped on the way (a std::ostream sets its badbit and goes on)
// leaves the other blocks for the next. An allocation refused while an exception unwinds the
// stack is given a freed block and tried again instead of throwing (a throw out of a destructor
// would abort). Once all are freed, failures throw as usual.
#pragma once

#include <cstddef>

namespace torusrt {

// Sets aside `bytes` in eight blocks (address space only: the pages are never touched), making
// again those freed since, and installs the new-handler that frees them.
void keep_memory_reserve(size_t bytes = size_t{16} << 20);

}  // namespace torusrt
