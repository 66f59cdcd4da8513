// cyclic_mapping.cpp - cyclic: each axis interleaved, c mod P (paper Fig. 2b, its load-balancing
// mapping).
#include "axis_mapping.h"

namespace torusrt {

namespace {

nlohmann::json fill(const SimConfig &config, rt_scene *, const rt_grid *grid, std::vector<int32_t> &owner,
                    ReplicaTable &)
{
    return fill_axes(config, RT_MAP_CYCLIC, grid, owner);
}

}  // namespace

extern const Mapping kCyclicMapping;
const Mapping kCyclicMapping = {
    "cyclic",                // name
    "cyclic",                // forms in --map's help
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
