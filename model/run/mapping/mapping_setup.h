// mapping_setup.h - the cell -> node table a run uses, decided before the run by the mapping
// the machine names (mapping.h), and the files that show it.
#pragma once

#include <optional>

#include <nlohmann/json.hpp>
#include <string>

#include "rt_grid.h"
#include "rt_scene.h"
#include "mapping.h"
#include "output_files.h"
#include "sim_config.h"

namespace torusrt {

// Fills config.owner_table (and config.replica_first / replica_extra for a replicated table)
// for the loaded scene with the mapping config.mapping names (mapping.h), and returns what the
// report says about it (JSON `mapping`: kind, cells per node, the mapping's own facts such as
// the pilot and mapper costs of `cost`). Throws UserError naming the file and line (exit 2) for
// a bad --map-file.
nlohmann::json prepare_mapping(SimConfig &config, rt_scene *scene, const rt_grid *grid);

// Writes the files asked for into the run's output set (UserError on failure), committed with
// its other outputs: --write-map (config.owner_table) and --load-map (a pilot run's per-cell
// work beside the owners, as a PNG).
void write_mapping_outputs(const SimConfig &config, rt_scene *scene, const rt_grid *grid, OutputSet &outputs,
                           std::optional<OutputSet::Id> write_map, std::optional<OutputSet::Id> load_map);

}  // namespace torusrt
