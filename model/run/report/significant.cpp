// significant.cpp - figures with 4 significant digits.
#include "significant.h"

#include <cmath>
#include <cstdio>

namespace torusrt {

std::string sig4(double v)
{
    char buf[48];
    double a = std::fabs(v);
    if (a == 0 || a >= 1e9 || a < 1e-6) {
        std::snprintf(buf, sizeof buf, "%.4g", v);
    } else {
        int decimals = 3 - static_cast<int>(std::floor(std::log10(a)));
        std::snprintf(buf, sizeof buf, "%.*f", decimals < 0 ? 0 : decimals, v);
    }
    return buf;
}

}  // namespace torusrt
