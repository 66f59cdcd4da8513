// axis_mapping.h - what the mappings that map each axis on its own share (block, cyclic,
// block-cyclic): the kernel's rt_mapping_fill makes their tables, and each unit's Mapping is
// axis_mapping<kind> with its name and :N.
#pragma once

#include "mapping.h"
#include "rt_mapping.h"

namespace torusrt {

// Fills owner with rt_mapping_fill's table of `kind` (block size config.block); UserError
// naming --map (exit 2) if it refuses. No facts beyond the kind.
nlohmann::json fill_axes(const MachineConfig &config, rt_map_kind kind, const rt_grid *grid,
                         std::vector<int32_t> &owner);

// fill_axes of `Kind` as a Mapping's fill (it reads no scene and makes no replicas).
template <rt_map_kind Kind>
nlohmann::json fill_axes_of(const SimConfig &config, rt_scene *, const rt_grid *grid, std::vector<int32_t> &owner,
                            ReplicaTable &)
{
    return fill_axes(config, Kind, grid, owner);
}

// The Mapping of the axis-wise `Kind`, named and given its :N (the block size) by the unit that
// registers it: its table from fill_axes_of<Kind>, no file, no pilot, remapped without a fold.
// Constant, so the registry may read it during static initialisation.
template <rt_map_kind Kind>
constexpr Mapping axis_mapping(const char *name, const char *forms, MappingParameter parameter,
                               const char *parameter_name, int parameter_max)
{
    return {name,
            forms,
            parameter,
            parameter_name,
            parameter_max,
            false,               // from_file
            false,               // measured
            nullptr,             // check_inputs
            fill_axes_of<Kind>,  // fill
            unfolded,            // remap_fold
            nullptr};            // no_remap
}

}  // namespace torusrt
