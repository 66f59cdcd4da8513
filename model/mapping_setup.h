// mapping_setup.h - the cell -> node table a run uses, decided before the run:
// a regular mapping, an explicit --map-file, or --map cost (pilot run + Scotch).
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "rt_grid.h"
#include "rt_scene.h"
#include "sim_config.h"

namespace torusrt {

// The mapping options as typed (their own block on the command line).
struct MappingOptions {
    std::string map_file, write_map, pilot_size, load_map;
    bool map_given = false; // --map was on the command line
};

// Checks the options against --map and stores them in `config` (UserError, exit 2).
void apply_mapping_options(SimConfig &config, const MappingOptions &options);

// Fills config.owner_table for the loaded scene and returns what the report says about it
// (JSON `mapping`: kind, cells per node, pilot and mapper costs for `cost`).
// Throws UserError naming the file and line (exit 2) for a bad --map-file.
nlohmann::json prepare_mapping(SimConfig &config, rt_scene *scene, const rt_grid *grid);

// Writes config.owner_table to config.write_map if asked (UserError on failure).
void write_mapping(const SimConfig &config, const rt_grid *grid);

// --load-map: a pilot run's per-cell work beside config.owner_table, as a PNG
// (UserError on failure). Does nothing for an empty path.
void write_load_map(const SimConfig &config, rt_scene *scene, const rt_grid *grid, const std::string &path);

}  // namespace torusrt
