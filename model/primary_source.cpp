// primary_source.cpp - entry nodes of the primary rays, and their packets made on demand.
#include "primary_source.h"

#include <algorithm>

#include "rt_packet.h"
#include "rt_step.h"

namespace torusrt {

PrimarySource::PrimarySource(const rt_scene *scene, const rt_grid *grid, const int32_t *owner, int nodes,
                             const sc_core::sc_time &inject, const ReplicaChoice *replicas)
    : m_scene(scene), m_grid(grid), m_replicas(replicas), m_inject(inject), m_pixels(nodes), m_next(nodes, 0)
{
    plan(owner);
}

void PrimarySource::restart(const int32_t *owner, const sc_core::sc_time &offset)
{
    m_offset = offset;
    for (auto &list : m_pixels) std::vector<uint32_t>().swap(list);
    std::fill(m_next.begin(), m_next.end(), 0);
    m_missed.clear();
    m_entering = 0;
    plan(owner);
}

void PrimarySource::plan(const int32_t *owner)
{
    const rt_camera *cam = rt_scene_camera(m_scene);
    m_width = cam->width;
    uint32_t pixel = 0;
    for (uint32_t y = 0; y < cam->height; y++)
        for (uint32_t x = 0; x < cam->width; x++, pixel++) {
            rt_packet p;
            int enters = 0;
            rt_primary_packet(m_scene, m_grid, x, y, &p, &enters);
            if (!enters) {
                m_missed.push_back(pixel);
                continue;
            }
            uint32_t cell = rt_packet_cell(m_grid, &p);
            m_pixels[m_replicas ? m_replicas->choose(-1, cell, p) : owner[cell]].push_back(pixel);
            m_entering++;
        }
}

TimedPacket PrimarySource::peek(int node) const
{
    uint32_t pixel = m_pixels[node][m_next[node]];
    TimedPacket t{};
    int enters = 0;
    rt_primary_packet(m_scene, m_grid, pixel % m_width, pixel / m_width, &t.packet, &enters);
    t.stamp = inject_time(pixel);
    t.from_host = true;
    return t;
}

TimedPacket PrimarySource::take(int node)
{
    TimedPacket t = peek(node);
    drop(node);
    return t;
}

void PrimarySource::drop(int node)
{
    m_next[node]++;
    if (!pending(node)) {  // the node's list is spent: give its memory back
        std::vector<uint32_t>().swap(m_pixels[node]);
        m_next[node] = 0;
    }
}

}  // namespace torusrt
