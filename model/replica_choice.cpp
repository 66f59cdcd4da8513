// replica_choice.cpp - the destination of a packet entering a replicated cell.
#include "replica_choice.h"

namespace torusrt {

int32_t ReplicaChoice::choose(int from, uint32_t cell, const rt_packet &p) const
{
    uint32_t extras = rt_replicas_extra_count(&m_replicas, cell);
    if (!extras) return m_owner[cell];
    if (from >= 0 && m_rule == ReplicaRule::nearest) return nearest(from, cell);
    // A packet handed over by a node that holds its cell came back to it; else the hash decides.
    if (from >= 0 && p.handed_over && rt_replicas_holds(&m_replicas, m_owner, cell, from)) return from;
    uint32_t index = rt_replica_hash(p.x, p.y, p.depth) % (extras + 1);
    return rt_replicas_owner_at(&m_replicas, m_owner, cell, index);
}

int32_t ReplicaChoice::nearest(int from, uint32_t cell) const
{
    int32_t best = m_owner[cell];
    int best_hops = m_routing.hops(from, best);
    for (uint32_t k = m_replicas.first[cell]; k < m_replicas.first[cell + 1]; k++) {
        int32_t node = m_replicas.extra[k];
        int h = m_routing.hops(from, node);
        if (h < best_hops || (h == best_hops && node < best)) {
            best = node;
            best_hops = h;
        }
    }
    return best;
}

}  // namespace torusrt
