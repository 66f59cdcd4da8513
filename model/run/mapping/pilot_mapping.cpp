// pilot_mapping.cpp - the pilot, and the Scotch or scatter mapping of its measurements.
#include "pilot_mapping.h"

#include <algorithm>
#include <cstdlib>
#include <new>

#include "rt_cost_map.h"
#include "run_stage.h"
#include "user_error.h"
#include "wall_clock.h"

namespace torusrt {

void check_passing(const rt_budget &budget, uint64_t bytes, const std::string &option, const std::string &what)
{
    rt_budget trial = budget;
    char msg[RT_MSG_LEN] = "";
    if (rt_budget_reserve(&trial, bytes, what.c_str(), msg, sizeof msg) != RT_OK) throw UserError(option + ": " + msg);
}

std::string size_text(unsigned w, unsigned h) { return std::to_string(w) + "x" + std::to_string(h); }

namespace {

const char *option_of(PilotMapper mapper) { return mapper == PilotMapper::scatter ? "--map scatter" : "--map cost"; }

// The pilot at its size, with the mapper's tables, against the budget.
void check_pilot_budget(const SimConfig &config, PilotMapper mapper, const rt_scene *scene, const rt_grid *grid)
{
    const rt_camera *cam = rt_scene_camera(scene);
    unsigned w = config.pilot_size[0] ? config.pilot_size[0] : cam->width;
    unsigned h = config.pilot_size[0] ? config.pilot_size[1] : cam->height;
    size_t cells = rt_grid_cell_count(grid);
    bool scatter = mapper == PilotMapper::scatter;
    uint64_t bytes = rt_cost_pilot_bytes(grid, rt_scene_object_count(scene), w, h, 0) +
                     (scatter ? rt_cost_scatter_bytes(cells) : rt_cost_map_bytes(cells));
    check_passing(config.memory, bytes, option_of(mapper),
                  "the pilot of " + size_text(w, h) + " pixels and the mapping of " + std::to_string(cells) + " cells");
}

// Runs the pilot at the pilot size (the scene's resolution is restored afterwards).
rt_cost_pilot run_pilot(const MachineConfig &config, PilotMapper mapper, rt_scene *scene, const rt_grid *grid)
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
    if (st == RT_ERR_NOMEM) {  // cli_main's message: the stage and --memory-budget
        set_run_stage(std::string("running the pilot of ") + option_of(mapper));
        throw std::bad_alloc();
    }
    if (st != RT_OK) throw UserError(std::string(option_of(mapper)) + ": pilot run: " + msg);
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

nlohmann::json pilot_mapping(const SimConfig &config, PilotMapper mapper, rt_scene *scene, const rt_grid *grid,
                             std::vector<int32_t> &owner, ReplicaTable &replicas)
{
    check_pilot_budget(config, mapper, scene, grid);
    double t0 = wall_clock_s();
    rt_cost_pilot pilot = run_pilot(config, mapper, scene, grid);
    double t1 = wall_clock_s();
    rt_cost_map_facts facts;
    char msg[RT_MSG_LEN] = "";
    double edge_us = rt_cost_edge_us(&config.timing);
    const bool scatter = mapper == PilotMapper::scatter;
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
        set_run_stage(std::string("mapping the cells with Scotch (") + option_of(mapper) + ")");
        throw std::bad_alloc();
    }
    if (st != RT_OK) throw UserError(std::string(option_of(mapper)) + ": " + msg);
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
