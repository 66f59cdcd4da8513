// cost_mapping.cpp - cost and cost:K: a pilot run's measured work and face traffic mapped with
// Scotch onto the torus or mesh (K times larger along each axis, folded back; cost is cost:1).
#include "pilot_mapping.h"

namespace torusrt {

namespace {

nlohmann::json fill(const SimConfig &config, rt_scene *scene, const rt_grid *grid, std::vector<int32_t> &owner,
                    ReplicaTable &replicas)
{
    return pilot_mapping(config, PilotMapper::scotch, scene, grid, owner, replicas);
}

// A remap folds as the first frame's mapping did.
int fold(const MachineConfig &config) { return config.block; }

}  // namespace

extern const Mapping kCostMapping;
const Mapping kCostMapping = {
    "cost",                      // name
    "cost, cost:K",              // forms in --map's help
    MappingParameter::optional,  // parameter
    "K",                         // its name
    64,                          // its largest value
    false,                       // from_file
    true,                        // measured
    nullptr,                     // check_inputs
    fill,                        // fill
    fold,                        // remap_fold
    nullptr,                     // no_remap
};

}  // namespace torusrt
