// replica_choice.h - which owner of a replicated cell a packet goes to (--replica-choice).
// A packet is given its destination once, by the node that hands it on (or by the host, for a
// primary). Under `nearest`: the owner fewest hops away by the machine's dimension-order
// routing, ties to the lowest node number (the node itself when it holds the cell). Under
// `hash`: the owner rt_replica_hash(x, y, depth) mod (owners) picks, owners in ascending order,
// for every new packet (made by a step in the cell, or a primary) and every packet forwarded
// into the cell; a walking packet never leaves a cell its node holds (the kernel walks it on).
// The host is on no ring: a primary entering a replicated cell takes the hash rule under both.
// Cells without extra owners go to owner[cell], as without a replica table.
#pragma once

#include <cstdint>

#include "routing.h"
#include "rt_packet.h"
#include "rt_replicas.h"
#include "sim_config.h"

namespace torusrt {

class ReplicaChoice {
  public:
    // The tables must outlive the choice; `routing` gives the hop counts of `nearest`.
    ReplicaChoice(const int32_t *owner, const rt_replicas &replicas, const Routing &routing, ReplicaRule rule)
        : m_owner(owner), m_replicas(replicas), m_routing(routing), m_rule(rule)
    {
    }
    // The node packet `p`, in cell `cell`, goes to from node `from` (-1: from the host).
    int32_t choose(int from, uint32_t cell, const rt_packet &p) const;
    const rt_replicas *table() const { return &m_replicas; }

  private:
    int32_t nearest(int from, uint32_t cell) const;

    const int32_t *m_owner;
    rt_replicas m_replicas;
    const Routing &m_routing;
    ReplicaRule m_rule;
};

}  // namespace torusrt
