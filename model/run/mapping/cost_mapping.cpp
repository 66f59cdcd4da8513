// cost_mapping.cpp - the pilot and the Scotch mapping behind --map cost.
#include "cost_mapping.h"

#include <algorithm>
#include <cstdlib>
#include <new>

#include "rt_cost_map.h"
#include "run_stage.h"
#include "user_error.h"
#include "wall_clock.h"

namespace torusrt {

namespace {

// Runs the pilot at the pilot size (the scene's resolution is restored afterwards).
rt_cost_pilot run_pilot(const MachineConfig &config, rt_scene *scene, const rt_grid *grid)
{
    const rt_camera *cam = rt_scene_camera(scene);
    unsigned w = cam->width, h = cam->height;
    bool resize = config.pilot_size[0] > 0;
    if (resize && rt_scene_set_resolution(scene, config.pilot_size[0], config.pilot_size[1]) != RT_OK)
        throw UserError("--pilot-size: not a valid image size", 2);
    rt_cost_pilot pilot;
    char msg[RT_MSG_LEN] = "";
    rt_status st = rt_cost_pilot_run(scene, grid, &config.step, &config.timing, &pilot, msg, sizeof msg);
    if (resize) rt_scene_set_resolution(scene, w, h);
    const char *map = config.mapping == RT_MAP_SCATTER ? "--map scatter" : "--map cost";
    if (st != RT_OK) throw UserError(std::string(map) + ": pilot run: " + msg);
    return pilot;
}

// Copies of the hottest cells within --replicate's budget (none at 0): the replica table, and
// the predicted busiest node's work with them in the facts.
void replicate_cells(const MachineConfig &config, const rt_cost_pilot &pilot, const rt_scene *scene,
                     const rt_grid *grid, const std::vector<int32_t> &owner, ReplicaTable &replicas,
                     rt_cost_map_facts &facts)
{
    replicas.first.clear();
    replicas.extra.clear();
    if (!(config.replicate > 0)) return;
    std::vector<uint32_t> first(pilot.cells + 1);
    int32_t *extra = nullptr;
    size_t count = 0;
    char msg[RT_MSG_LEN] = "";
    rt_replica_rule rule = config.replica_choice == ReplicaRule::hash ? RT_REPLICA_HASH : RT_REPLICA_NEAREST;
    const rt_topology topo = config.network();
    if (rt_cost_replicate(&pilot, scene, grid, &topo, rule, owner.data(), config.replicate, &config.memory_layout,
                          first.data(), &extra, &count, &facts, msg, sizeof msg) != RT_OK)
        throw UserError(std::string("--replicate: ") + msg);
    if (count) {
        replicas.first = std::move(first);
        replicas.extra.assign(extra, extra + count);
    }
    std::free(extra);
}

// The balanced scatter, with its pieces of the hottest cells within --replicate's budget; the
// busiest node's predicted work without the pieces in unreplicated_max_us.
rt_status scatter_cells(const MachineConfig &config, const rt_cost_pilot &pilot, const rt_scene *scene,
                        const rt_grid *grid, std::vector<int32_t> &owner, ReplicaTable &replicas,
                        rt_cost_map_facts &facts, double &unreplicated_max_us, char *msg, size_t msg_len)
{
    const rt_topology topo = config.network();
    std::vector<uint32_t> first(pilot.cells + 1);
    int32_t *extra = nullptr;
    size_t count = 0;
    rt_status st = rt_cost_map_scatter(&pilot, scene, grid, &topo, 0, &config.memory_layout, owner.data(), first.data(),
                                       &extra, &count, &facts, msg, msg_len);
    std::free(extra);
    extra = nullptr;
    unreplicated_max_us = facts.max_node_work_us;
    replicas.first.clear();
    replicas.extra.clear();
    if (st != RT_OK || !(config.replicate > 0)) return st;
    st = rt_cost_map_scatter(&pilot, scene, grid, &topo, config.replicate, &config.memory_layout, owner.data(),
                             first.data(), &extra, &count, &facts, msg, msg_len);
    if (st == RT_OK && count) {
        replicas.first = std::move(first);
        replicas.extra.assign(extra, extra + count);
    }
    std::free(extra);
    return st;
}

}  // namespace

nlohmann::json cost_mapping(const MachineConfig &config, rt_scene *scene, const rt_grid *grid,
                            std::vector<int32_t> &owner, ReplicaTable &replicas)
{
    double t0 = wall_clock_s();
    rt_cost_pilot pilot = run_pilot(config, scene, grid);
    double t1 = wall_clock_s();
    rt_cost_map_facts facts;
    char msg[RT_MSG_LEN] = "";
    double edge_us = rt_cost_edge_us(&config.timing);
    const bool scatter = config.mapping == RT_MAP_SCATTER;
    double unreplicated_max_us = 0;
    rt_status st = RT_OK;
    if (scatter) {
        st = scatter_cells(config, pilot, scene, grid, owner, replicas, facts, unreplicated_max_us, msg, sizeof msg);
    } else {
        const rt_topology topo = config.network();
        st = rt_cost_map_folded(&pilot, &topo, edge_us, config.block, owner.data(), &facts, msg, sizeof msg);
        unreplicated_max_us = facts.max_node_work_us;
        try {
            if (st == RT_OK) replicate_cells(config, pilot, scene, grid, owner, replicas, facts);
        } catch (...) {
            rt_cost_pilot_release(&pilot);
            throw;
        }
    }
    double t2 = wall_clock_s();
    double pilot_us = pilot.total_us, max_cell_us = 0;
    for (size_t c = 0; c < pilot.cells; c++) max_cell_us = std::max(max_cell_us, pilot.work_us[c]);
    uint64_t faces = pilot.ops.handovers_sent;
    rt_cost_pilot_release(&pilot);
    if (st == RT_ERR_NOMEM) {  // the system refused Scotch or the graph an allocation: cli_main's message
        set_run_stage(std::string("mapping the cells with Scotch (") + (scatter ? "--map scatter" : "--map cost") +
                      ")");
        throw std::bad_alloc();
    }
    if (st != RT_OK) throw UserError(std::string(scatter ? "--map scatter: " : "--map cost: ") + msg);
    const rt_camera *cam = rt_scene_camera(scene);
    unsigned pw = config.pilot_size[0] ? config.pilot_size[0] : cam->width;
    unsigned ph = config.pilot_size[0] ? config.pilot_size[1] : cam->height;
    return {{"pilot_size", {pw, ph}},
            {"pilot_modelled_s", pilot_us * 1e-6},
            {"pilot_face_crossings", faces},
            {"pilot_max_cell_work_s", max_cell_us * 1e-6},
            {"pilot_wall_s", t1 - t0},
            {"mapper", scatter ? "scatter" : "scotch"},
            {"fold", config.block},
            {"mapper_wall_s", t2 - t1},
            {"edge_us_per_packet", edge_us},
            {"predicted_max_node_work_s", facts.max_node_work_us * 1e-6},
            {"predicted_max_node_work_unreplicated_s", unreplicated_max_us * 1e-6},
            {"replicate", config.replicate},
            {"predicted_mean_node_work_s", facts.mean_node_work_us * 1e-6},
            {"predicted_cut_packets", facts.cut_packets},
            {"predicted_cut_hops", facts.cut_hops}};
}

}  // namespace torusrt
