/* cost_internal.h - cell and node geometry shared by the cost mapper and its replication pass. */
#ifndef RT_COST_INTERNAL_H
#define RT_COST_INTERNAL_H

#include <stdint.h>

#include "rt_topology.h"

/* Neighbour of cell c through face f (-x, +x, -y, +y, -z, +z) of a dims grid, -1 at its boundary. */
long rt_cost_neighbour(const int dims[3], long c, int f);

/* The busiest and mean node work of a one-owner table, and the pilot's packets it cuts
 * (and their hops); all zero when out of memory. */
struct rt_cost_pilot;
struct rt_cost_map_facts;
void rt_cost_map_facts_of(const struct rt_cost_pilot *p, const rt_topology *topo, const int32_t *owner,
                          struct rt_cost_map_facts *facts);

#endif
