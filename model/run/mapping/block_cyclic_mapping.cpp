// block_cyclic_mapping.cpp - block-cyclic:B: blocks of B cells dealt cyclically along each axis,
// (c / B) mod P.
#include "axis_mapping.h"

namespace torusrt {

namespace {

nlohmann::json fill(const SimConfig &config, rt_scene *, const rt_grid *grid, std::vector<int32_t> &owner,
                    ReplicaTable &)
{
    return fill_axes(config, RT_MAP_BLOCK_CYCLIC, grid, owner);
}

}  // namespace

extern const Mapping kBlockCyclicMapping;
const Mapping kBlockCyclicMapping = {
    "block-cyclic",              // name
    "block-cyclic:B",            // forms in --map's help
    MappingParameter::required,  // parameter
    "B",                         // its name
    1 << 20,                     // its largest value
    false,                       // from_file
    false,                       // measured
    nullptr,                     // check_inputs
    fill,                        // fill
    unfolded,                    // remap_fold
    nullptr,                     // no_remap
};

}  // namespace torusrt
