// harness.h - a minimal check-and-count harness for the SystemC model tests (one sc_main each).
#pragma once

#include <cstdio>

namespace harness {
inline int passed = 0, failed = 0;
inline void check(bool ok, const char *what)
{
    if (ok) passed++;
    else {
        failed++;
        std::printf("FAIL: %s\n", what);
    }
}
inline int finish()
{
    std::printf("%d passed, %d failed\n", passed, failed);
    return failed == 0 ? 0 : 1;
}
}  // namespace harness
