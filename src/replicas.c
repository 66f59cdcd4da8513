/* replicas.c - the replica table's hash rule and counts (rt_replicas.h). */
#include "rt_replicas.h"

uint32_t rt_replica_hash(uint32_t x, uint32_t y, uint32_t depth)
{
    uint32_t h = x * 0x9E3779B1u + y * 0x85EBCA77u + depth * 0xC2B2AE3Du;
    h ^= h >> 16;
    h *= 0x7FEB352Du;
    h ^= h >> 15;
    h *= 0x846CA68Bu;
    h ^= h >> 16;
    return h;
}

int32_t rt_replicas_owner_at(const rt_replicas *r, const int32_t *owner, uint32_t cell, uint32_t index)
{
    int32_t primary = owner[cell];
    uint32_t extras = rt_replicas_extra_count(r, cell);
    /* The primary owner takes its place among the extra owners in ascending order. */
    uint32_t below = 0;
    while (below < extras && r->extra[r->first[cell] + below] < primary) below++;
    if (index == below) return primary;
    return r->extra[r->first[cell] + (index < below ? index : index - 1)];
}

void rt_replicas_count(const rt_replicas *r, size_t cells, size_t *replicated_cells, size_t *copies)
{
    size_t n = 0;
    for (size_t c = 0; r && c < cells; c++) n += r->first[c + 1] > r->first[c];
    *replicated_cells = n;
    *copies = r ? r->first[cells] : 0;
}
