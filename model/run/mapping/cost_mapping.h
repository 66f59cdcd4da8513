// cost_mapping.h - --map cost: a pilot sequential run measures per-cell work and per-face
// traffic, and Scotch maps the weighted cell graph onto the machine's torus or mesh.
#pragma once

#include <nlohmann/json.hpp>
#include <vector>

#include "rt_grid.h"
#include "rt_scene.h"
#include "sim_config.h"

namespace torusrt {

// Fills owner (one node per cell) and returns the JSON facts: pilot and mapper modelled
// cost and wall time. Throws UserError with a clear message if the pilot or Scotch fails.
nlohmann::json cost_mapping(const MachineConfig &config, rt_scene *scene, const rt_grid *grid,
                            std::vector<int32_t> &owner);

}  // namespace torusrt
