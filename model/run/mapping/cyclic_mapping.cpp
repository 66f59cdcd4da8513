// cyclic_mapping.cpp - cyclic: each axis interleaved, c mod P (paper Fig. 2b, its load-balancing
// mapping).
#include "axis_mapping.h"

namespace torusrt {

extern const Mapping kCyclicMapping;
// name, its forms in --map's help, no :N
const Mapping kCyclicMapping = axis_mapping<RT_MAP_CYCLIC>("cyclic", "cyclic", MappingParameter::none, "", 0);

}  // namespace torusrt
