// axis_mapping.cpp - the table of an axis-wise mapping, from the kernel.
#include "axis_mapping.h"

#include "routing.h"
#include "user_error.h"

namespace torusrt {

nlohmann::json fill_axes(const MachineConfig &config, rt_map_kind kind, const rt_grid *grid,
                         std::vector<int32_t> &owner)
{
    int dims[3];
    rt_grid_dims(grid, dims);
    owner.resize(rt_grid_cell_count(grid));
    char msg[RT_MSG_LEN] = "";
    if (rt_mapping_fill(dims, config.ips.data(), kind, config.block, owner.data(), msg, sizeof msg) != RT_OK)
        throw UserError(std::string("--map: ") + msg, 2);
    place_on_nodes(config.network(), owner);  // grid positions to the topology's node ids
    return nlohmann::json::object();
}

}  // namespace torusrt
