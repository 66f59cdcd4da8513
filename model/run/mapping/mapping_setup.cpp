// mapping_setup.cpp - one place that turns the mapping options into the owner table.
#include "mapping_setup.h"

#include <algorithm>
#include <new>
#include <vector>

#include "mapping.h"
#include "output_files.h"
#include "pilot_mapping.h"
#include "rt_cost_map.h"
#include "rt_load_image.h"
#include "rt_map_file.h"
#include "rt_text.h"
#include "run_stage.h"
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

}  // namespace

nlohmann::json prepare_mapping(SimConfig &config, rt_scene *scene, const rt_grid *grid)
{
    int nodes = config.node_count();
    char msg[RT_MSG_LEN] = "";
    // The owner table and the machine's copy of it (run_frames) stay for the whole run.
    size_t cells = rt_grid_cell_count(grid);
    if (rt_budget_reserve(&config.memory, 2 * uint64_t(cells) * sizeof(int32_t),
                          ("the cell -> node tables of " + std::to_string(cells) + " cells").c_str(), msg,
                          sizeof msg) != RT_OK)
        throw UserError(msg);
    std::vector<int32_t> owner(cells);
    const Mapping &mapping = mapping_of(config);
    nlohmann::json j = {{"kind", mapping.name}};
    ReplicaTable replicas;
    j.update(mapping.fill(config, scene, grid, owner, replicas));
    config.replica_first = std::move(replicas.first);
    config.replica_extra = std::move(replicas.extra);
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
    std::string mapping = mapping_text(config);
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
    rt_status st = rt_cost_pilot_run(scene, grid, &config.step, &config.timing, &pilot, msg, sizeof msg);
    if (st == RT_ERR_NOMEM) {  // cli_main's message: the stage and --memory-budget
        set_run_stage("running the pilot of --load-map");
        throw std::bad_alloc();
    }
    if (st != RT_OK) throw UserError(std::string("--load-map: pilot run: ") + msg);
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
