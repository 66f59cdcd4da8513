// mapping.h - the cell -> node mappings the model chooses by name (MachineConfig::mapping, set
// by --map NAME[:N] or --map-file). Each mapping is one unit in its own file (block_mapping.cpp,
// cyclic_mapping.cpp, ...) registered by one line in mapping_registry.cpp, in the help's order.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
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

// What NAME:N gives the mapping (MachineConfig::block): nothing, or a number it needs or may take.
enum class MappingParameter { none, required, optional };

struct Mapping {
    const char *name;            // as --map takes it and the reports print it
    const char *forms;           // its part of --map's help: the forms it takes ("cost, cost:K")
    MappingParameter parameter;  // what :N after the name gives
    const char *parameter_name;  // the N in the messages ("B", "K"; "" without one)
    int parameter_max;           // the largest N (the least is 1)
    bool from_file;              // a table read from --map-file, which chooses it (not --map)
    bool measured;               // made from a pilot run's measured work (--pilot-size, --replicate)
    // Checks what the mapping reads before the scene is loaded (null: nothing); UserError naming
    // the file and line (exit 2).
    void (*check_inputs)(const MachineConfig &config);
    // Fills owner (one node per cell, sized to the grid's cells) and the extra owners of
    // replicated cells, and returns the report's facts (JSON `mapping`, beside its kind). The
    // scene is read by a measured mapping only (the others may be given null). UserError on bad
    // input.
    nlohmann::json (*fill)(const SimConfig &config, rt_scene *scene, const rt_grid *grid, std::vector<int32_t> &owner,
                           ReplicaTable &replicas);
    // The fold (cost:K's K) Scotch remaps the frames after the first with (--remap).
    int (*remap_fold)(const MachineConfig &config);
    // Why the mapping is not remapped across frames (null: it is).
    const char *no_remap;
};

// The remap_fold of the mappings remapped without a fold (Scotch's plain mapping).
int unfolded(const MachineConfig &config);

// The mapping registered as `name`, or null.
const Mapping *find_mapping(const std::string &name);
// The mapping of `config`; UserError (exit 2) naming --map for a name no mapping has.
const Mapping &mapping_of(const MachineConfig &config);
// The name of the mapping --map-file chooses (the table read from a file).
const char *file_mapping_name();
// The names in the registry's order.
std::vector<std::string> mapping_names();
// "block, cyclic, ... or scatter": the forms --map takes, for the help and its messages.
std::string mapping_forms();
// The mapping as --map writes it: the name, with :N where N is needed or not the default 1.
std::string mapping_text(const MachineConfig &config);

}  // namespace torusrt
