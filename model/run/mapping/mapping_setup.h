// mapping_setup.h - the cell -> node table a run uses, decided before the run:
// a regular mapping, an explicit --map-file, or --map cost (pilot run + Scotch).
#pragma once

#include <optional>

#include <nlohmann/json.hpp>
#include <string>

#include "rt_grid.h"
#include "rt_scene.h"
#include "cost_mapping.h"
#include "output_files.h"
#include "sim_config.h"

namespace torusrt {

// Fills config.owner_table (and config.replica_first / replica_extra for a replicated table) for the loaded scene and
// returns what the report says about it (JSON `mapping`: kind, cells per node, pilot and mapper costs for `cost`).
// Throws UserError naming the file and line (exit 2) for a bad --map-file.
// Reads config.map_file for a grid of `dims` cells into `owner` (UserError naming the file and
// line, exit 2).
void read_map_file(const SimConfig &config, const int dims[3], std::vector<int32_t> &owner);
// The same, with the extra owners of a `torusrt-map 2` table (empty for version 1).
void read_map_file(const SimConfig &config, const int dims[3], std::vector<int32_t> &owner, ReplicaTable &replicas);

nlohmann::json prepare_mapping(SimConfig &config, rt_scene *scene, const rt_grid *grid);

// Writes the files asked for into the run's output set (UserError on failure), committed with
// its other outputs: --write-map (config.owner_table) and --load-map (a pilot run's per-cell
// work beside the owners, as a PNG).
void write_mapping_outputs(const SimConfig &config, rt_scene *scene, const rt_grid *grid, OutputSet &outputs,
                           std::optional<OutputSet::Id> write_map, std::optional<OutputSet::Id> load_map);

}  // namespace torusrt
