// huge_pages.h - runs the simulator with glibc's allocator asking for transparent huge pages.
// A big machine's modules, events and packets are spread over hundreds of megabytes that every
// hop touches somewhere; with 4 KiB pages most of those touches also miss the TLB.
#pragma once

namespace torusrt {

// Unless GLIBC_TUNABLES is set already (the user's choice wins) or the program runs under
// Valgrind, sets it to glibc.malloc.hugetlb=1 and executes this program again with the same
// arguments, so the allocator reads it at start-up. Returns only when it did not (already set,
// under Valgrind, or the exec failed).
void reexec_with_huge_pages(char **argv);

}  // namespace torusrt
