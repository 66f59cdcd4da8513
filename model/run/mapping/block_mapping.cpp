// block_mapping.cpp - block: each axis cut into contiguous blocks, floor(c P / N) (paper Fig. 2a).
#include "axis_mapping.h"

namespace torusrt {

namespace {

nlohmann::json fill(const SimConfig &config, rt_scene *, const rt_grid *grid, std::vector<int32_t> &owner,
                    ReplicaTable &)
{
    return fill_axes(config, RT_MAP_BLOCK, grid, owner);
}

}  // namespace

extern const Mapping kBlockMapping;
const Mapping kBlockMapping = {
    "block",                 // name
    "block",                 // forms in --map's help
    MappingParameter::none,  // parameter
    "",                      // its name
    0,                       // its largest value
    false,                   // from_file
    false,                   // measured
    nullptr,                 // check_inputs
    fill,                    // fill
    unfolded,                // remap_fold
    nullptr,                 // no_remap
};

}  // namespace torusrt
