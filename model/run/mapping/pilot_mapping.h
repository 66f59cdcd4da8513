// pilot_mapping.h - the mappings made from measured work (--map cost, cost:K and scatter): a
// pilot sequential run measures per-cell work and per-face traffic, and Scotch maps the weighted
// cell graph onto the machine's torus or mesh, or scatter deals the work to the least loaded node.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "mapping.h"
#include "rt_budget.h"
#include "rt_grid.h"
#include "rt_scene.h"
#include "sim_config.h"

namespace torusrt {

// Which mapper turns the pilot's measurements into the table.
enum class PilotMapper { scotch, scatter };

// Fills owner (one node per cell) and, with --replicate above 0, the replica table (copies or
// pieces of the hottest cells), and returns the JSON facts: pilot and mapper modelled cost and
// wall time. The pilot and the mapper's tables are checked against the memory budget first.
// Throws UserError with a clear message if the pilot or the mapper fails.
nlohmann::json pilot_mapping(const SimConfig &config, PilotMapper mapper, rt_scene *scene, const rt_grid *grid,
                             std::vector<int32_t> &owner, ReplicaTable &replicas);

// Throws the memory budget's UserError, naming `option`, unless `bytes` for `what` fit in what
// the run has left; they are freed again before the run reserves its own.
void check_passing(const rt_budget &budget, uint64_t bytes, const std::string &option, const std::string &what);

// "WxH".
std::string size_text(unsigned w, unsigned h);

}  // namespace torusrt
