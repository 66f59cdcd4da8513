// migration.cpp - bytes, hops and link time of a change of mapping.
#include "migration.h"

#include <algorithm>
#include <cmath>

namespace torusrt {

double link_transfer_us(const rt_timing &timing, uint64_t bytes)
{
    if (bytes == 0) return 0;
    if (timing.link_bytes_per_us > 0) return static_cast<double>(bytes) / timing.link_bytes_per_us;
    double pieces = timing.packet_bytes > 0 ? std::ceil(static_cast<double>(bytes) / timing.packet_bytes) : 1;
    return pieces * timing.link_us;
}

uint64_t cell_move_bytes(const rt_scene *scene, const rt_grid *grid, size_t cell)
{
    size_t n = 0;
    const uint32_t *objs = rt_grid_cell_objects(grid, cell, &n);
    uint64_t bytes = 4 + 4 * static_cast<uint64_t>(n);
    for (size_t i = 0; i < n; i++) bytes += rt_scene_object_bytes(scene, objs[i]);
    return bytes;
}

LinkLoad::LinkLoad(const Routing &routing, int nodes)
    : m_routing(routing), m_link_bytes(static_cast<size_t>(nodes) * static_cast<size_t>(routing.ports()), 0)
{
}

void LinkLoad::send(int from, int to, uint64_t bytes, uint32_t tie_key)
{
    int hops = 0;
    for (int at = from; at != to; hops++) {
        int dir = m_routing.next_direction(at, to, tie_key);
        m_link_bytes[static_cast<size_t>(at) * static_cast<size_t>(m_routing.ports()) + static_cast<size_t>(dir)] +=
            bytes;
        at = m_routing.neighbour(at, dir);
    }
    m_byte_hops += bytes * static_cast<uint64_t>(hops);
    m_max_hops = std::max(m_max_hops, hops);
}

void LinkLoad::finish(const rt_timing &timing, MigrationCost &m) const
{
    m.byte_hops = m_byte_hops;
    m.max_hops = m_max_hops;
    m.busiest_link_bytes = m_link_bytes.empty() ? 0 : *std::max_element(m_link_bytes.begin(), m_link_bytes.end());
    double busiest_us = 0;
    for (uint64_t b : m_link_bytes) busiest_us = std::max(busiest_us, link_transfer_us(timing, b));
    m.time_s = busiest_us * 1e-6;
}

namespace {

// Per node, which objects it holds under `owner`.
std::vector<std::vector<bool>> holdings(const rt_grid *grid, size_t objects, int nodes,
                                        const std::vector<int32_t> &owner)
{
    std::vector<std::vector<bool>> holds(static_cast<size_t>(nodes));
    for (size_t c = 0; c < owner.size(); c++) {
        auto &h = holds[static_cast<size_t>(owner[c])];
        if (h.empty()) h.assign(objects, false);
        size_t n = 0;
        const uint32_t *objs = rt_grid_cell_objects(grid, c, &n);
        for (size_t i = 0; i < n; i++) h[objs[i]] = true;
    }
    return holds;
}

}  // namespace

MigrationCost migration_cost(const rt_scene *scene, const rt_grid *grid, const Routing &routing, int nodes,
                             const rt_timing &timing, const std::vector<int32_t> &old_owner,
                             const std::vector<int32_t> &new_owner)
{
    MigrationCost m;
    size_t objects = rt_scene_object_count(scene);
    std::vector<std::vector<bool>> holds = holdings(grid, objects, nodes, old_owner);
    LinkLoad links(routing, nodes);
    for (size_t c = 0; c < new_owner.size(); c++) {
        int from = old_owner[c], to = new_owner[c];
        if (from == to) continue;
        auto &h = holds[static_cast<size_t>(to)];
        if (h.empty()) h.assign(objects, false);
        size_t n = 0;
        const uint32_t *objs = rt_grid_cell_objects(grid, c, &n);
        uint64_t bytes = 4 + 4 * static_cast<uint64_t>(n);
        m.list_bytes += bytes;
        for (size_t i = 0; i < n; i++) {
            if (h[objs[i]]) continue;
            h[objs[i]] = true;
            uint64_t ob = rt_scene_object_bytes(scene, objs[i]);
            m.objects++;
            m.object_bytes += ob;
            bytes += ob;
        }
        m.cells++;
        links.send(from, to, bytes, static_cast<uint32_t>(c));
    }
    links.finish(timing, m);
    return m;
}

}  // namespace torusrt
