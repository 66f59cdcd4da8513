// block_cyclic_mapping.cpp - block-cyclic:B: blocks of B cells dealt cyclically along each axis,
// (c / B) mod P.
#include "axis_mapping.h"

namespace torusrt {

extern const Mapping kBlockCyclicMapping;
// name, its forms in --map's help, :B required, B at most 2^20
const Mapping kBlockCyclicMapping =
    axis_mapping<RT_MAP_BLOCK_CYCLIC>("block-cyclic", "block-cyclic:B", MappingParameter::required, "B", 1 << 20);

}  // namespace torusrt
