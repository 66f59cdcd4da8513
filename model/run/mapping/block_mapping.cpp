// block_mapping.cpp - block: each axis cut into contiguous blocks, floor(c P / N) (paper Fig. 2a).
#include "axis_mapping.h"

namespace torusrt {

extern const Mapping kBlockMapping;
// name, its forms in --map's help, no :N
const Mapping kBlockMapping = axis_mapping<RT_MAP_BLOCK>("block", "block", MappingParameter::none, "", 0);

}  // namespace torusrt
