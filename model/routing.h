// routing.h - the model's face on the nodes' topology (rt_topology.h): ports, neighbours, the
// first port of a packet's route, the dateline, hops. The topology decides all of them; the
// torus and the mesh have their per-hop rule written out here as well (the same as
// rt_topology_first_port, checked by routing_test), so that a hop on them makes no call.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "rt_topology.h"

namespace torusrt {

// The most ports a node has.
constexpr int kMaxPorts = RT_TOPOLOGY_MAX_PORTS;
// The torus's and mesh's port numbering: 2 * axis + (0 for +, 1 for -).
inline int direction(int axis, bool positive) { return 2 * axis + (positive ? 0 : 1); }

// Which way a packet goes round an even ring when both ways are equally short (the node
// opposite). split: + when the packet's tie key is even, - when odd, so a ring of two uses both
// of its links; plus: always +, so a ring of two uses one link each way, as two nodes joined by
// one link would. Either keeps a route minimal and in one direction per ring, which is what the
// dateline argument of flow_control.h needs.
enum class RouteTies { split, plus };
constexpr RouteTies kDefaultRouteTies = RouteTies::split;  // two links in a ring of two (docs/flow-control.md)

// The topology registered as `name` on `dims` nodes; std::invalid_argument with the registry's
// message when it cannot be made (the validator has checked a machine's).
rt_topology make_topology(const std::array<int, 3> &dims, const std::string &name);
// The registered topology names, in the registry's order.
std::vector<std::string> topology_names();
// Turns a table of rt_mapping_fill's grid position ids into the nodes at those positions.
void place_on_nodes(const rt_topology &topology, std::vector<int32_t> &owner);

class Routing {
  public:
    explicit Routing(const rt_topology &topology, RouteTies ties = kDefaultRouteTies);
    Routing(const std::array<int, 3> &dims, const std::string &topology, RouteTies ties = kDefaultRouteTies)
        : Routing(make_topology(dims, topology), ties)
    {
    }
    const rt_topology &topology() const { return m_topo; }
    int nodes() const { return m_topo.nodes; }
    int ports() const { return m_topo.ports; }
    const char *port_name(int port) const { return rt_topology_port_name(&m_topo, port); }
    // A node's position on the mapping's grid, and the node at a position.
    std::array<int, 3> coords(int node) const;
    int node(const std::array<int, 3> &c) const;
    // The node one hop from `node` through port `dir`, or -1 if there is no link (mesh edge,
    // or an axis with one node).
    int neighbour(int node, int dir) const { return rt_topology_neighbour(&m_topo, node, dir); }
    // Port of the first hop from `from` toward `to` (torus and mesh: x, then y, then z; on a
    // ring the shorter way, a tie by the RouteTies rule on `tie_key`), or -1 if from == to. A
    // tie can only arise at a packet's first hop on an axis, so the key decides the whole ring's way.
    int next_direction(int from, int to, uint32_t tie_key) const
    {
        return next_direction_by(from, to, [tie_key] { return tie_key; });
    }
    // The same with the key from `tie_key()`, called only when a tie arises: a hop then reads no
    // more of its packet than it needs.
    template <class TieKey> int next_direction_by(int from, int to, TieKey tie_key) const
    {
        const std::array<int, 3> &a = m_coords[static_cast<size_t>(from)], &b = m_coords[static_cast<size_t>(to)];
        for (int axis = 0; axis < 3; axis++) {
            if (a[axis] == b[axis]) continue;
            // One test on the torus's way, as a torus-only routine would make.
            if (m_topo.kind != RT_TOPOLOGY_TORUS)
                return m_topo.kind == RT_TOPOLOGY_MESH ? direction(axis, b[axis] > a[axis])
                                                       : other_first_port(from, to, tie_key);
            int p = m_topo.dims[axis];
            int forward = b[axis] - a[axis];
            if (forward < 0) forward += p;  // the hops going + round the ring
            if (forward != p - forward) return direction(axis, forward < p - forward);
            return direction(axis, m_ties == RouteTies::plus || tie_key() % 2 == 0);
        }
        return -1;  // positions are one per node: the same position is the same node
    }
    RouteTies ties() const { return m_ties; }
    // Whether the link leaving `node` through port `dir` is its dimension's dateline (on the
    // torus a ring's wrap-around link: from the last coordinate to 0 going +, from 0 to the
    // last going -).
    bool wraps(int node, int dir) const
    {
        if (m_topo.kind != RT_TOPOLOGY_TORUS)
            return m_other_datelines && rt_topology_crosses_dateline(&m_topo, node, dir) != 0;
        int axis = dir / 2;
        if (m_topo.dims[axis] < 2) return false;
        int c = m_coords[static_cast<size_t>(node)][axis];
        return dir % 2 == 0 ? c == m_topo.dims[axis] - 1 : c == 0;
    }
    // Whether two ports move along the same dimension (a route keeps its channel within one).
    bool same_dimension(int a, int b) const { return m_dimension[a] == m_dimension[b]; }
    // Hops from `from` to `to` (the same either way on a tie).
    int hops(int from, int to) const { return rt_topology_hops(&m_topo, from, to); }

  private:
    rt_route_ties c_ties() const { return m_ties == RouteTies::plus ? RT_TIES_PLUS : RT_TIES_SPLIT; }
    // A plug-in's first port, through the interface (its tie key read only if it can tie).
    template <class TieKey> int other_first_port(int from, int to, TieKey tie_key) const
    {
        return rt_topology_first_port(&m_topo, from, to, c_ties(), m_has_ties ? tie_key() : 0);
    }

    rt_topology m_topo;
    RouteTies m_ties;
    bool m_has_ties;
    bool m_other_datelines;                    // a plug-in whose scheme has datelines (more than one channel)
    std::array<int, kMaxPorts> m_dimension{};  // per port, the dimension it moves along
    // Every node's grid position, worked out once: a hop asks for two and divisions cost more.
    std::vector<std::array<int, 3>> m_coords;
};

}  // namespace torusrt
