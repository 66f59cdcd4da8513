// axis_mapping.h - what the mappings that map each axis on its own share (block, cyclic,
// block-cyclic): the kernel's rt_mapping_fill makes their tables.
#pragma once

#include "mapping.h"
#include "rt_mapping.h"

namespace torusrt {

// Fills owner with rt_mapping_fill's table of `kind` (block size config.block); UserError
// naming --map (exit 2) if it refuses. No facts beyond the kind.
nlohmann::json fill_axes(const MachineConfig &config, rt_map_kind kind, const rt_grid *grid,
                         std::vector<int32_t> &owner);

}  // namespace torusrt
