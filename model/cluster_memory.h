// cluster_memory.h - object placement inside a cluster and the data memory each processor needs.
//
// Placement rule (shared data): within a node, the objects its cells list, taken once each in
// ascending object index, are dealt out in turn: the j-th (j = 0, 1, ...) to processor j mod m
// of that node. An object listed by cells of several nodes is placed in each of those nodes.
// Replicated data: every processor of a node holds all of that node's objects.
//
// Memory per processor (bytes, object and material sizes from rt_scene_object_bytes and
// rt_scene_material_bytes, cell lists as rt_memory.h: 4 bytes per cell + 4 per entry):
//   replicated: the node's objects + the materials they use + the node's cell lists
//               (= rt_memory_per_owner over nodes: what a flat-torus IP of that node holds);
//   shared:     its share of the node's objects + the materials those use + ALL the node's
//               cell lists (every processor walks every cell of its node).
// A system's figure is the largest per-processor amount x the number of processors (the
// paper's definition), beside pixel-partitioned (whole scene x the number of processors).
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <vector>

#include "rt_grid.h"
#include "rt_scene.h"
#include "sim_config.h"

namespace torusrt {

// Objects listed in any cell with cell_owner == node, once each, ascending.
// With `replicas`, the cells it holds as an extra owner too.
std::vector<uint32_t> cluster_node_objects(const rt_grid *grid, const int32_t *cell_owner, int node,
                                           const rt_replicas *replicas = nullptr);

// Which processor (0..m-1) of the node holds `object` under the placement rule; -1 if the node's
// cells do not list it. `node_objects` as from cluster_node_objects.
int shared_holder(const std::vector<uint32_t> &node_objects, uint32_t object, int m);

struct ClusterMemoryFigures {
    uint64_t replicated_per_processor = 0;             // largest over nodes
    uint64_t shared_per_processor = 0;                 // largest over nodes and processors
    uint64_t shared_list_bytes = 0;                    // cell lists of the node with most (in every shared figure)
    std::vector<uint64_t> replicated_per_node;         // per node
    std::vector<std::vector<uint64_t>> shared_per_ip;  // per node, per processor
};

// Figures for `nodes` nodes of `m` processors each. Throws std::bad_alloc when memory runs out.
ClusterMemoryFigures cluster_memory_figures(const rt_scene *scene, const rt_grid *grid, const int32_t *cell_owner,
                                            int nodes, int m, const rt_memory_layout *layout = nullptr,
                                            const rt_replicas *replicas = nullptr);

// The report's `memory` section for a clustered run: max_per_ip_bytes and total_bytes for the
// configured data mode, both modes' figures, and pixel_partitioned_bytes as passed in.
nlohmann::json cluster_memory_report(const ClusterMemoryFigures &figures, DataMode data, int processors,
                                     uint64_t pixel_partitioned);

}  // namespace torusrt
