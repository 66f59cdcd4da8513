// file_mapping.cpp - file: an explicit cell -> node table read from --map-file (torusrt-map 1, or
// 2 with several owners for a cell).
#include <cstdlib>

#include "mapping.h"
#include "rt_map_file.h"
#include "user_error.h"

namespace torusrt {

namespace {

// Reads config.map_file for a grid of `dims` cells (UserError naming the file and line, exit 2).
void read_map_file(const MachineConfig &config, const int dims[3], std::vector<int32_t> &owner, ReplicaTable &replicas)
{
    size_t cells = size_t(dims[0]) * dims[1] * dims[2];
    owner.assign(cells, 0);
    std::vector<uint32_t> first(cells + 1);
    int32_t *extra = nullptr;
    size_t count = 0;
    char msg[RT_MSG_LEN] = "";
    if (rt_map_file_read_replicas(config.map_file.c_str(), dims, config.node_count(), owner.data(), first.data(),
                                  &extra, &count, msg, sizeof msg) != RT_OK)
        throw UserError(std::string("--map-file: ") + msg, 2);
    replicas.first.clear();
    replicas.extra.assign(extra, extra + count);
    if (count) replicas.first = std::move(first);
    std::free(extra);
}

// The table needs only the grid's size: a bad one is named before the scene is read.
void check_table(const MachineConfig &config)
{
    std::vector<int32_t> owner;
    ReplicaTable replicas;
    read_map_file(config, config.cells.data(), owner, replicas);
}

nlohmann::json fill(const SimConfig &config, rt_scene *, const rt_grid *grid, std::vector<int32_t> &owner,
                    ReplicaTable &replicas)
{
    int dims[3];
    rt_grid_dims(grid, dims);
    read_map_file(config, dims, owner, replicas);
    return {{"file", config.map_file}};
}

}  // namespace

extern const Mapping kFileMapping;
const Mapping kFileMapping = {
    "file",                  // name
    "",                      // forms in --map's help: none, --map-file chooses it
    MappingParameter::none,  // parameter
    "",                      // its name
    0,                       // its largest value
    true,                    // from_file
    false,                   // measured
    check_table,             // check_inputs
    fill,                    // fill
    unfolded,                // remap_fold
    nullptr,                 // no_remap
};

}  // namespace torusrt
