// cost_mapping.h - --map cost: a pilot sequential run measures per-cell work and per-face
// traffic, and Scotch maps the weighted cell graph onto the machine's torus or mesh.
#pragma once

#include <nlohmann/json.hpp>
#include <vector>

#include "rt_grid.h"
#include "rt_scene.h"
#include "sim_config.h"

namespace torusrt {

// Extra owners of replicated cells, as SimConfig keeps them (rt_replicas.h; empty: none).
struct ReplicaTable {
    std::vector<uint32_t> first;
    std::vector<int32_t> extra;
};

// Fills owner (one node per cell) and, with --replicate above 0, the replica table (copies of
// the hottest cells, rt_cost_replicate), and returns the JSON facts: pilot and mapper modelled
// cost and wall time. Throws UserError with a clear message if the pilot or Scotch fails.
nlohmann::json cost_mapping(const MachineConfig &config, rt_scene *scene, const rt_grid *grid,
                            std::vector<int32_t> &owner, ReplicaTable &replicas);

}  // namespace torusrt
