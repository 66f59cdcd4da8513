// primary_source.h - the host's primary rays, handed out on demand. At the start the host walks
// the pixels once to learn where each primary ray enters the object space and keeps, per entry
// node, the pixel numbers (4 bytes each) in pixel order; the packet itself is made only when the
// node's input queue takes it up, so packet memory does not grow with the image. Pixel i (in
// row-major order) is injected at (i + 1) x host_inject: its packet's stamp. In an animation the
// source is planned again for every frame (restart), with the stamps offset by the frame's start.
#pragma once

#include <cstdint>
#include <systemc>
#include <vector>

#include "replica_choice.h"
#include "rt_grid.h"
#include "rt_scene.h"
#include "timed_packet.h"

namespace torusrt {

class PrimarySource {
  public:
    // `owner` maps a cell to its node; `nodes` entry nodes; `inject` = host time per pixel;
    // `replicas` picks the entry node of a primary entering a replicated cell (null: owner).
    PrimarySource(const rt_scene *scene, const rt_grid *grid, const int32_t *owner, int nodes,
                  const sc_core::sc_time &inject, const ReplicaChoice *replicas = nullptr);

    // Pixels whose ray misses the space (the host writes their background).
    const std::vector<uint32_t> &missed() const { return m_missed; }
    uint64_t entering() const { return m_entering; }
    sc_core::sc_time inject_time(uint32_t pixel) const { return m_offset + m_inject * static_cast<double>(pixel + 1); }
    // Plans a new frame: the scene's current camera, `owner` as it is now, stamps from `offset`.
    // Every earlier primary must have been taken.
    void restart(const int32_t *owner, const sc_core::sc_time &offset);
    uint32_t width() const { return m_width; }

    bool pending(int node) const { return m_next[node] < m_pixels[node].size(); }
    // Injection time of the node's next primary (pending(node) must hold).
    sc_core::sc_time next_time(int node) const { return inject_time(m_pixels[node][m_next[node]]); }
    // Makes the node's next primary packet (pending(node) must hold).
    TimedPacket take(int node);
    // The packet take() would make, without taking it.
    TimedPacket peek(int node) const;
    // Takes the node's next primary without making its packet (after a peek).
    void drop(int node);

  private:
    void plan(const int32_t *owner);

    const rt_scene *m_scene;
    const rt_grid *m_grid;
    const ReplicaChoice *m_replicas;
    sc_core::sc_time m_inject;
    sc_core::sc_time m_offset = sc_core::SC_ZERO_TIME;
    uint32_t m_width = 0;
    std::vector<std::vector<uint32_t>> m_pixels;  // per entry node, ascending
    std::vector<size_t> m_next;
    std::vector<uint32_t> m_missed;
    uint64_t m_entering = 0;
};

}  // namespace torusrt
