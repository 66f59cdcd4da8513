// huge_pages.cpp - one exec of the program itself with the allocator's huge-page tunable set.
#include "huge_pages.h"

#include <cstdlib>
#include <unistd.h>

namespace torusrt {

void reexec_with_huge_pages(char **argv)
{
    if (std::getenv("GLIBC_TUNABLES")) return; // set by the user, or by the first run of this program
    if (setenv("GLIBC_TUNABLES", "glibc.malloc.hugetlb=1", 1) != 0) return;
    execv("/proc/self/exe", argv);
    unsetenv("GLIBC_TUNABLES"); // exec failed: run on as we are
}

}  // namespace torusrt
