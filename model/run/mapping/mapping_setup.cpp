// mapping_setup.cpp - one place that turns the mapping options into the owner table.
#include "mapping_setup.h"

#include <algorithm>
#include <cstdlib>
#include <vector>

#include "cost_mapping.h"
#include "output_files.h"
#include "rt_cost_map.h"
#include "rt_load_image.h"
#include "rt_map_file.h"
#include "rt_mapping.h"
#include "rt_text.h"
#include "user_error.h"

namespace torusrt {

namespace {

nlohmann::json cells_per_node(const std::vector<int32_t> &owner, int nodes)
{
    std::vector<long> count(nodes, 0);
    for (int32_t o : owner) count[o]++;
    auto mm = std::minmax_element(count.begin(), count.end());
    return {{"min", *mm.first}, {"max", *mm.second}};
}

// Throws the memory budget's UserError, naming `option`, unless `bytes` for `what` fit in what
// the run has left; they are freed again before the run reserves its own.
void check_passing(const rt_budget &budget, uint64_t bytes, const std::string &option, const std::string &what)
{
    rt_budget trial = budget;
    char msg[RT_MSG_LEN] = "";
    if (rt_budget_reserve(&trial, bytes, what.c_str(), msg, sizeof msg) != RT_OK) throw UserError(option + ": " + msg);
}

std::string size_text(unsigned w, unsigned h) { return std::to_string(w) + "x" + std::to_string(h); }

// The pilot of --map cost or scatter at its size, with the mapper's tables, against the budget.
void check_cost_mapping_budget(const SimConfig &config, const rt_scene *scene, const rt_grid *grid)
{
    const rt_camera *cam = rt_scene_camera(scene);
    unsigned w = config.pilot_size[0] ? config.pilot_size[0] : cam->width;
    unsigned h = config.pilot_size[0] ? config.pilot_size[1] : cam->height;
    size_t cells = rt_grid_cell_count(grid);
    bool scatter = config.mapping == RT_MAP_SCATTER;
    uint64_t bytes = rt_cost_pilot_bytes(grid, rt_scene_object_count(scene), w, h, 0) +
                     (scatter ? rt_cost_scatter_bytes(cells) : rt_cost_map_bytes(cells));
    check_passing(config.memory, bytes, scatter ? "--map scatter" : "--map cost",
                  "the pilot of " + size_text(w, h) + " pixels and the mapping of " + std::to_string(cells) + " cells");
}

}  // namespace

void read_map_file(const SimConfig &config, const int dims[3], std::vector<int32_t> &owner)
{
    ReplicaTable ignored;
    read_map_file(config, dims, owner, ignored);
}

void read_map_file(const SimConfig &config, const int dims[3], std::vector<int32_t> &owner, ReplicaTable &replicas)
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

nlohmann::json prepare_mapping(SimConfig &config, rt_scene *scene, const rt_grid *grid)
{
    int dims[3];
    rt_grid_dims(grid, dims);
    int nodes = config.node_count();
    char msg[RT_MSG_LEN] = "";
    // The owner table and the machine's copy of it (run_frames) stay for the whole run.
    size_t cells = rt_grid_cell_count(grid);
    if (rt_budget_reserve(&config.memory, 2 * uint64_t(cells) * sizeof(int32_t),
                          ("the cell -> node tables of " + std::to_string(cells) + " cells").c_str(), msg,
                          sizeof msg) != RT_OK)
        throw UserError(msg);
    std::vector<int32_t> owner(cells);
    nlohmann::json j = {{"kind", mapping_name(config.mapping)}};
    if (config.mapping == RT_MAP_FILE) {
        ReplicaTable replicas;
        read_map_file(config, dims, owner, replicas);
        config.replica_first = std::move(replicas.first);
        config.replica_extra = std::move(replicas.extra);
        j["file"] = config.map_file;
    } else if (config.measured_mapping()) {
        check_cost_mapping_budget(config, scene, grid);
        ReplicaTable replicas;
        j.update(cost_mapping(config, scene, grid, owner, replicas));
        config.replica_first = std::move(replicas.first);
        config.replica_extra = std::move(replicas.extra);
    } else if (rt_mapping_fill(dims, config.ips.data(), config.mapping, config.block, owner.data(), msg, sizeof msg) !=
               RT_OK) {
        throw UserError(std::string("--map: ") + msg, 2);
    } else {
        place_on_nodes(config.network(), owner);
    }
    j["cells_per_node"] = cells_per_node(owner, nodes);
    config.owner_table = std::move(owner);
    return j;
}

namespace {

void write_mapping(const SimConfig &config, const rt_grid *grid, const std::string &path, const std::string &shown)
{
    if (path.empty()) return;
    int dims[3];
    rt_grid_dims(grid, dims);
    write_stream_file(path, shown, "--write-map", [&](FILE *fp, char *msg, size_t msg_len) {
        rt_replicas replicas = config.replica_table();
        return rt_map_file_write_replicas(fp, shown.c_str(), dims, config.node_count(), config.owner_table.data(),
                                          config.replicated() ? &replicas : nullptr, msg, msg_len);
    });
}

// The load map's caption: the scene's file name, the machine and its mapping, in the picture's
// letters (printable ASCII; other bytes as \xNN).
std::string load_map_caption(const SimConfig &config)
{
    const std::string &scene = config.scene_path;
    std::string base = scene.substr(scene.find_last_of('/') == std::string::npos ? 0 : scene.find_last_of('/') + 1);
    char shown[128];
    rt_escape_bytes(base.data(), base.size(), 1, shown, sizeof shown);
    std::string machine = std::to_string(config.ips[0]) + "x" + std::to_string(config.ips[1]) + "x" +
                          std::to_string(config.ips[2]) + " " + config.topology;
    if (config.cluster > 1) machine += ", " + std::to_string(config.cluster) + " processors per node";
    std::string mapping = mapping_name(config.mapping);
    if (config.mapping == RT_MAP_BLOCK_CYCLIC || (config.mapping == RT_MAP_COST && config.block > 1))
        mapping += ":" + std::to_string(config.block);
    if (config.replicate > 0) mapping += ", replicated cells";
    return std::string(shown) + ", " + machine + ", " + mapping + " mapping";
}

void write_load_map(const SimConfig &config, rt_scene *scene, const rt_grid *grid, const std::string &path,
                    const std::string &shown)
{
    if (path.empty()) return;
    const rt_camera *cam = rt_scene_camera(scene);
    check_passing(config.memory, rt_cost_pilot_bytes(grid, rt_scene_object_count(scene), cam->width, cam->height, 0),
                  "--load-map", "its pilot of " + size_text(cam->width, cam->height) + " pixels");
    rt_cost_pilot pilot;
    char msg[RT_MSG_LEN] = "";
    if (rt_cost_pilot_run(scene, grid, &config.step, &config.timing, &pilot, msg, sizeof msg) != RT_OK)
        throw UserError(std::string("--load-map: pilot run: ") + msg);
    try {
        write_stream_file(path, shown, "--load-map", [&](FILE *fp, char *why, size_t why_len) {
            rt_replicas replicas = config.replica_table();
            return rt_load_map_write_replicas(fp, shown.c_str(), pilot.dims, pilot.work_us, config.owner_table.data(),
                                              config.replicated() ? &replicas : nullptr, config.node_count(),
                                              load_map_caption(config).c_str(), why, why_len);
        });
    } catch (...) {
        rt_cost_pilot_release(&pilot);
        throw;
    }
    rt_cost_pilot_release(&pilot);
}

}  // namespace

void write_mapping_outputs(const SimConfig &config, rt_scene *scene, const rt_grid *grid, OutputSet &outputs,
                           std::optional<OutputSet::Id> write_map, std::optional<OutputSet::Id> load_map)
{
    if (write_map) write_mapping(config, grid, outputs.staged(*write_map), outputs.path(*write_map));
    if (load_map) write_load_map(config, scene, grid, outputs.staged(*load_map), outputs.path(*load_map));
}

}  // namespace torusrt
