// huge_pages.cpp - one exec of the program itself with the allocator's huge-page tunable set.
#include "huge_pages.h"

#include <climits>
#include <cstdlib>
#include <cstring>
#include <unistd.h>

#include "signal_cleanup.h"

namespace torusrt {

namespace {

// Valgrind runs the program on its own core and loads its preloads; an exec would leave it (or
// fail): the run goes on as it is.
bool under_valgrind()
{
    const char *preload = std::getenv("LD_PRELOAD");
    return preload && std::strstr(preload, "vgpreload");
}

}  // namespace

void reexec_with_huge_pages(char **argv)
{
    if (std::getenv("GLIBC_TUNABLES") || under_valgrind()) return;  // the user's choice, or our second start
    char self[PATH_MAX];
    ssize_t n = readlink("/proc/self/exe", self, sizeof self - 1);
    if (n <= 0) return;
    self[n] = '\0';
    if (setenv("GLIBC_TUNABLES", "glibc.malloc.hugetlb=1", 1) != 0) return;
    {
        // The stopping signals stay blocked across the exec (a signal meanwhile is kept pending)
        // until the new image's main has installed its handler (stop_on_signals).
        SignalsBlocked held;
        execv(self, argv);
    }
    unsetenv("GLIBC_TUNABLES");  // exec failed: run on as we are
}

}  // namespace torusrt
