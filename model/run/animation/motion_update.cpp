// motion_update.cpp - the units, update time and transfers of a moving scene's list update.
#include "motion_update.h"

#include <algorithm>

namespace torusrt {

std::vector<ObjectCell> moved_entries(const rt_grid *grid, const std::vector<uint8_t> &moved)
{
    std::vector<ObjectCell> out;
    size_t cells = rt_grid_cell_count(grid);
    for (size_t c = 0; c < cells; c++) {
        size_t n = 0;
        const uint32_t *objs = rt_grid_cell_objects(grid, c, &n);
        for (size_t i = 0; i < n; i++)
            if (objs[i] < moved.size() && moved[objs[i]]) out.push_back({objs[i], static_cast<uint32_t>(c)});
    }
    std::stable_sort(out.begin(), out.end(),
                     [](const ObjectCell &a, const ObjectCell &b) { return a.object < b.object; });
    return out;  // cells ascend within an object: the scan went by cell
}

namespace {

// One node's part of one moved object's update.
struct NodeChange {
    uint32_t gained = 0, lost = 0;  // entries added to and removed from the node's cells
    bool held = false;              // the node's cells listed the object before the update
};

// The half-space tests of the moved objects, dealt out as processor o mod P.
void count_units(const rt_grid *grid, const std::vector<uint8_t> &moved, int processors, const rt_timing &timing,
                 MotionUpdate &u)
{
    std::vector<uint64_t> per(static_cast<size_t>(processors), 0);
    for (size_t o = 0; o < moved.size(); o++) {
        if (!moved[o]) continue;
        uint64_t units = rt_grid_units_of_object(grid, o);
        u.objects_moved++;
        u.units += units;
        per[o % static_cast<size_t>(processors)] += units;
    }
    u.slowest_units = per.empty() ? 0 : *std::max_element(per.begin(), per.end());
    u.rebuild_units = rt_grid_units_serial(grid);
    u.rebuild_slowest_units = rt_grid_units_parallel(grid, processors);
    u.update_s = static_cast<double>(u.slowest_units) * timing.preprocess_unit_us * 1e-6;
}

// Object o's entries [b, b_end) before and [a, a_end) after, per node: what changed.
void node_changes(const std::vector<ObjectCell> &before, size_t b, size_t b_end, const std::vector<ObjectCell> &after,
                  size_t a, size_t a_end, const int32_t *owner, std::vector<NodeChange> &change,
                  std::vector<int> &touched)
{
    auto at = [&](uint32_t cell) -> NodeChange & {
        int node = owner[cell];
        NodeChange &c = change[static_cast<size_t>(node)];
        if (!c.gained && !c.lost && !c.held) touched.push_back(node);
        return c;
    };
    while (b < b_end || a < a_end) {
        if (a == a_end || (b < b_end && before[b].cell < after[a].cell)) {
            NodeChange &c = at(before[b++].cell);
            c.lost++, c.held = true;
        } else if (b == b_end || after[a].cell < before[b].cell) {
            at(after[a++].cell).gained++;
        } else {
            at(after[a].cell).held = true;
            a++, b++;
        }
    }
}

}  // namespace

MotionUpdate motion_update_cost(const rt_scene *scene, const rt_grid *grid, const std::vector<uint8_t> &moved,
                                const std::vector<ObjectCell> &before, const MotionMachine &machine)
{
    MotionUpdate u;
    int processors = machine.nodes * machine.processors_per_node;
    count_units(grid, moved, processors, machine.timing, u);
    std::vector<ObjectCell> after = moved_entries(grid, moved);
    std::vector<NodeChange> change(static_cast<size_t>(machine.nodes));
    std::vector<int> touched;
    LinkLoad links(machine.routing, machine.nodes);
    size_t b = 0, a = 0;
    while (b < before.size() || a < after.size()) {
        uint32_t o = b < before.size() && (a == after.size() || before[b].object <= after[a].object) ? before[b].object
                                                                                                     : after[a].object;
        size_t b_end = b, a_end = a;
        while (b_end < before.size() && before[b_end].object == o) b_end++;
        while (a_end < after.size() && after[a_end].object == o) a_end++;
        node_changes(before, b, b_end, after, a, a_end, machine.owner, change, touched);
        int handler = static_cast<int>(o % static_cast<uint32_t>(processors)) / machine.processors_per_node;
        for (int node : touched) {
            NodeChange &c = change[static_cast<size_t>(node)];
            uint64_t entries = c.gained + c.lost;
            if (node != handler && entries > 0) {
                uint64_t bytes = 4 * entries;
                u.entries_sent += entries;
                u.transfer.list_bytes += bytes;
                if (c.gained > 0 && !c.held) {
                    uint64_t record = rt_scene_object_bytes(scene, o);
                    u.transfer.objects++;
                    u.transfer.object_bytes += record;
                    bytes += record;
                }
                links.send(handler, node, bytes, static_cast<uint32_t>(o));
            }
            c = NodeChange{};
        }
        touched.clear();
        b = b_end, a = a_end;
    }
    links.finish(machine.timing, u.transfer);
    return u;
}

}  // namespace torusrt
