// preprocess_count.h - the names of the preprocessing counting rules (--preprocess-count), as
// the options accept them and the reports print them (docs/fidelity.md gives each rule).
#pragma once

#include "named_values.h"
#include "rt_grid.h"

namespace torusrt {

constexpr NamedValue<rt_preprocess_count> kPreprocessCountNames[] = {{RT_COUNT_SEQUENTIAL, "sequential"},
                                                                     {RT_COUNT_PER_PLANE, "per-plane"},
                                                                     {RT_COUNT_BOUNDING_SPHERE, "bounding-sphere"}};

inline const char *preprocess_count_name(rt_preprocess_count rule) { return name_in(kPreprocessCountNames, rule); }

}  // namespace torusrt
