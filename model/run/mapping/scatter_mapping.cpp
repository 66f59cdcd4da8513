// scatter_mapping.cpp - scatter: a pilot run's measured work dealt cell by cell to the least
// loaded node.
#include "pilot_mapping.h"

namespace torusrt {

namespace {

nlohmann::json fill(const SimConfig &config, rt_scene *scene, const rt_grid *grid, std::vector<int32_t> &owner,
                    ReplicaTable &replicas)
{
    return pilot_mapping(config, PilotMapper::scatter, scene, grid, owner, replicas);
}

}  // namespace

extern const Mapping kScatterMapping;
const Mapping kScatterMapping = {
    "scatter",                                                              // name
    "scatter",                                                              // forms in --map's help
    MappingParameter::none,                                                 // parameter
    "",                                                                     // its name
    0,                                                                      // its largest value
    false,                                                                  // from_file
    true,                                                                   // measured
    nullptr,                                                                // check_inputs
    fill,                                                                   // fill
    unfolded,                                                               // remap_fold
    "the frames after the first are remapped with Scotch; use --map cost",  // no_remap
};

}  // namespace torusrt
