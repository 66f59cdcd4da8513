// routing.cpp - the model's face on the nodes' topology.
#include "routing.h"

#include <stdexcept>

namespace torusrt {

rt_topology make_topology(const std::array<int, 3> &dims, const std::string &name)
{
    rt_topology t;
    char msg[256] = "";
    if (rt_topology_make(name.c_str(), dims.data(), &t, msg, sizeof msg) != RT_OK) throw std::invalid_argument(msg);
    return t;
}

std::vector<std::string> topology_names()
{
    std::vector<std::string> names;
    for (int i = 0; rt_topology_name_at(i); i++) names.emplace_back(rt_topology_name_at(i));
    return names;
}

void place_on_nodes(const rt_topology &topology, std::vector<int32_t> &owner)
{
    for (int32_t &o : owner) o = rt_topology_node_of_grid_id(&topology, o);
}

Routing::Routing(const rt_topology &topology, RouteTies ties)
    : m_topo(topology), m_ties(ties), m_has_ties(rt_topology_has_ties(&topology) != 0),
      m_other_datelines(topology.kind == RT_TOPOLOGY_OTHER && rt_topology_channels(&topology) > 1)
{
    for (int p = 0; p < m_topo.ports; p++) m_dimension[static_cast<size_t>(p)] = rt_topology_port_dimension(&m_topo, p);
    m_coords.reserve(static_cast<size_t>(m_topo.nodes));
    for (int n = 0; n < m_topo.nodes; n++) {
        std::array<int, 3> c{};
        rt_topology_position(&m_topo, n, c.data());
        m_coords.push_back(c);
    }
}

std::array<int, 3> Routing::coords(int node) const { return m_coords[static_cast<size_t>(node)]; }

int Routing::node(const std::array<int, 3> &c) const { return rt_topology_node_at(&m_topo, c.data()); }

}  // namespace torusrt
