// cluster_memory.cpp - placement of objects over a node's processors and the memory figures.
#include "cluster_memory.h"

#include <algorithm>
#include <new>
#include <unordered_set>

#include "rt_memory.h"

namespace torusrt {

std::vector<uint32_t> cluster_node_objects(const rt_grid *grid, const int32_t *cell_owner, int node,
                                           const rt_replicas *replicas)
{
    std::vector<bool> seen;
    std::vector<uint32_t> out;
    size_t cells = rt_grid_cell_count(grid);
    for (size_t c = 0; c < cells; c++) {
        if (!rt_replicas_holds(replicas, cell_owner, static_cast<uint32_t>(c), node)) continue;
        size_t count = 0;
        const uint32_t *list = rt_grid_cell_objects(grid, c, &count);
        for (size_t i = 0; i < count; i++) {
            if (list[i] >= seen.size()) seen.resize(list[i] + 1, false);
            if (seen[list[i]]) continue;
            seen[list[i]] = true;
            out.push_back(list[i]);
        }
    }
    std::sort(out.begin(), out.end());
    return out;
}

int shared_holder(const std::vector<uint32_t> &node_objects, uint32_t object, int m)
{
    auto it = std::lower_bound(node_objects.begin(), node_objects.end(), object);
    if (it == node_objects.end() || *it != object) return -1;
    return static_cast<int>((it - node_objects.begin()) % m);
}

ClusterMemoryFigures cluster_memory_figures(const rt_scene *scene, const rt_grid *grid, const int32_t *cell_owner,
                                            int nodes, int m, const rt_memory_layout *layout,
                                            const rt_replicas *replicas)
{
    ClusterMemoryFigures f;
    std::vector<rt_memory_use> use(nodes);
    if (rt_memory_per_owner_replicas(scene, grid, cell_owner, replicas, nodes, layout, use.data()) != RT_OK)
        throw std::bad_alloc();
    f.replicated_per_node.resize(nodes);
    f.shared_per_ip.assign(nodes, std::vector<uint64_t>(m, 0));
    for (int n = 0; n < nodes; n++) {
        f.replicated_per_node[n] = rt_memory_total(&use[n]);
        f.replicated_per_processor = std::max(f.replicated_per_processor, f.replicated_per_node[n]);
        f.shared_list_bytes = std::max(f.shared_list_bytes, use[n].list_bytes);
        std::vector<uint32_t> objects = cluster_node_objects(grid, cell_owner, n, replicas);
        std::vector<std::unordered_set<const rt_material *>> materials(m);
        for (size_t j = 0; j < objects.size(); j++) {
            int k = static_cast<int>(j % m);
            f.shared_per_ip[n][k] += rt_memory_object_bytes(scene, objects[j], layout);
            if (materials[k].insert(rt_scene_object_material(scene, objects[j])).second)
                f.shared_per_ip[n][k] += rt_scene_material_bytes();
        }
        for (int k = 0; k < m; k++) {
            f.shared_per_ip[n][k] += use[n].list_bytes;
            f.shared_per_processor = std::max(f.shared_per_processor, f.shared_per_ip[n][k]);
        }
    }
    return f;
}

nlohmann::json cluster_memory_report(const ClusterMemoryFigures &f, DataMode data, int processors,
                                     uint64_t pixel_partitioned)
{
    uint64_t n = static_cast<uint64_t>(processors);
    uint64_t per = data == DataMode::replicated ? f.replicated_per_processor : f.shared_per_processor;
    return {{"max_per_ip_bytes", per},
            {"total_bytes", per * n},
            {"pixel_partitioned_bytes", pixel_partitioned},
            {"data", data_mode_name(data)},
            {"replicated_per_processor_bytes", f.replicated_per_processor},
            {"replicated_total_bytes", f.replicated_per_processor * n},
            {"shared_per_processor_bytes", f.shared_per_processor},
            {"shared_total_bytes", f.shared_per_processor * n},
            {"shared_cell_list_bytes", f.shared_list_bytes},
            {"placement", "shared: the j-th object (ascending index) listed by a node's cells goes to its "
                          "processor j mod m; replicated: every processor holds all its node's objects"}};
}

}  // namespace torusrt
