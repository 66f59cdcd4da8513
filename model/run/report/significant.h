// significant.h - figures as the summaries print them: 4 significant digits, no exponent for the
// sizes a run produces.
#ifndef TORUSRT_SIGNIFICANT_H
#define TORUSRT_SIGNIFICANT_H

#include <string>

namespace torusrt {

std::string sig4(double v);

}  // namespace torusrt

#endif
