// flow_control.h - the deadlock-free flow-control scheme (--flow classes): the class a packet
// belongs to and the virtual channel it uses on each link. docs/model.md gives the argument.
//
// Every bounded buffer (IP and dispatcher input queues, link buffers) is split by class, and a
// link's by channel too. A primary has class 0; every packet a step hands on (created or
// forwarded) has the class of the packet taken up + 1, and + 1 more for each earlier output of
// the same step whose first buffer would be the same (so each output of a step needs one slot
// of its own, and capacity 1 is enough). Within each dimension of its route a packet uses
// channel 0 until it crosses the dimension's dateline (on a torus the ring's wrap-around link;
// the topology says which links are datelines, rt_topology.h), channel 1 from there on, and
// channel 0 again when it turns into the next dimension. A processor takes up a packet only
// once every output has a slot reserved in the buffer it goes to first; a dispatcher only once
// the chosen processor's queue has room. So a packet in an input queue of class k waits only
// on buffers of class k + 1, and a packet on a link of class k only on the next link of its
// dimension-order route (same class) or on the input queue at its end (same class, which waits
// only on class k + 1): the buffer dependency graph has no cycle.
#pragma once

#include <cstdint>

#include "routing.h"
#include "sim_config.h"
#include "timed_packet.h"

namespace torusrt {

// Class of every packet (created or forwarded) a step of a class-`cls` packet hands on.
inline uint32_t output_class(FlowControl f, uint32_t cls) { return f == FlowControl::none ? 0 : cls + 1; }
// Channel of `p` on the link leaving `node` through port `dir` (dateline rule; 0 where the
// topology has no dateline, as on a mesh).
inline uint8_t link_channel(FlowControl f, const Routing &r, const TimedPacket &p, int node, int dir)
{
    if (f == FlowControl::none) return 0;
    uint8_t vc = p.last_dir >= 0 && r.same_dimension(p.last_dir, dir) ? p.vc : 0;
    return r.wraps(node, dir) ? 1 : vc;
}
// Most classes a run can use. A ray or shadow is forwarded at most F = (cx - 1) + (cy - 1) +
// (cz - 1) times (each forward crosses a cell boundary, and a ray crosses each boundary plane
// once), one class each; the step that creates from a ray adds at most lights + 2. A shade
// tree has rays of depth 0..max_depth and then shadows, so the deepest class is at most
// (max_depth + 1) (F + lights + 2) + F.
inline uint64_t class_bound(const SimConfig &c, uint32_t lights)
{
    if (c.flow == FlowControl::none) return 1;
    uint64_t f = static_cast<uint64_t>(c.cells[0] - 1 + c.cells[1] - 1 + c.cells[2] - 1);
    return (static_cast<uint64_t>(c.step.max_depth) + 1) * (f + lights + 2) + f + 1;
}

}  // namespace torusrt
