/* rt_topology.h - the network joining the nodes: which node each port reaches, minimal routes,
 * hop distance, the deadlock-free channel rule, and where cells' grid coordinates land.
 *
 * Usage:
 *   rt_topology topo;
 *   int dims[3] = {4, 4, 4};
 *   if (rt_topology_make("torus", dims, &topo, msg, sizeof msg) != RT_OK) fail(msg);
 *   for (int at = from; at != to;)
 *       at = rt_topology_neighbour(&topo, at, rt_topology_first_port(&topo, at, to, RT_TIES_SPLIT, key));
 *
 * A topology is chosen by name from a registry (rt_topology_name_at lists it): "torus" and
 * "mesh" (rings or lines along each of the three axes) and the plug-ins docs/topologies.md lists.
 * Every topology has nodes 0 .. nodes - 1 and the same ports on every node (a port may lead
 * nowhere: neighbour -1). Cell mappings deal cells over a dims[0] x dims[1] x dims[2] grid of
 * positions; rt_topology_node_at places a position on a node. Routes are deterministic: the
 * first port toward a node depends only on the two nodes, the tie rule and the tie key.
 * Functions taking a node or port take valid ones (0 .. nodes - 1, 0 .. ports - 1) unless said.
 */
#ifndef RT_TOPOLOGY_H
#define RT_TOPOLOGY_H

#include <stddef.h>
#include <stdint.h>

#include "rt_status.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The most ports a node has (a 12-cube: 4096 nodes). */
#define RT_TOPOLOGY_MAX_PORTS 12

/* The topologies whose routes a caller may work out itself from grid positions (the model's
 * per-hop code does, as rt_topology_first_port would); any other is reached only through the
 * functions below. */
typedef enum rt_topology_kind {
    RT_TOPOLOGY_TORUS = 0, /* a ring along each axis of more than one node */
    RT_TOPOLOGY_MESH = 1,  /* a line along each axis of more than one node */
    RT_TOPOLOGY_OTHER = 2  /* a registered plug-in */
} rt_topology_kind;

/* Which way a route goes when two ways are equally short (a ring's opposite node). */
typedef enum rt_route_ties {
    RT_TIES_SPLIT = 0, /* + for an even tie key, - for an odd one */
    RT_TIES_PLUS = 1   /* always + */
} rt_route_ties;

struct rt_topology_class;

/* A topology: a plain value, made by rt_topology_make, copied freely, never freed. */
typedef struct rt_topology {
    const struct rt_topology_class *cls; /* the registered implementation (topology_class.h) */
    rt_topology_kind kind;               /* which one */
    int dims[3];                         /* grid positions per axis (--ips); their product is nodes */
    int nodes;                           /* node count */
    int ports;                           /* ports per node, at most RT_TOPOLOGY_MAX_PORTS */
} rt_topology;

/* Makes the topology registered as `name` on a dims[0] x dims[1] x dims[2] grid. RT_ERR_INVALID
 * with a message (unknown name, a dimension below 1, a shape the topology cannot take). */
rt_status rt_topology_make(const char *name, const int dims[3], rt_topology *topo, char *msg, size_t msg_len);

/* The i-th registered name, or NULL past the last. */
const char *rt_topology_name_at(int i);

/* The topology's registered name. */
const char *rt_topology_name(const rt_topology *topo);

/* What a machine with one axis of more than one node is called ("ring", "line"), or NULL. */
const char *rt_topology_one_axis_name(const rt_topology *topo);

/* A port's name in reports and link names (the torus's "xp" .. "zm"); "none" out of range. */
const char *rt_topology_port_name(const rt_topology *topo, int port);

/* The node one hop from `node` through `port`, or -1 when the port leads nowhere. */
int rt_topology_neighbour(const rt_topology *topo, int node, int port);

/* The node at grid position c (0 <= c[k] < dims[k]); mappings place cells through it. */
int rt_topology_node_at(const rt_topology *topo, const int c[3]);

/* The grid position of `node` (the inverse of rt_topology_node_at). */
void rt_topology_position(const rt_topology *topo, int node, int c[3]);

/* The node of a mapping's position id px + PX * (py + PY * pz) (rt_mapping_fill's ids). */
int rt_topology_node_of_grid_id(const rt_topology *topo, int id);

/* Hops of the route from a to b (the same whichever way a tie goes). */
int rt_topology_hops(const rt_topology *topo, int a, int b);

/* The first port of the route from `from` toward `to`, or -1 when from == to. A tie between
 * equally short ways is broken by `ties` on `tie_key`. */
int rt_topology_first_port(const rt_topology *topo, int from, int to, rt_route_ties ties, uint32_t tie_key);

/* Whether some route can tie (the tie rule matters on this topology and shape): 1 or 0. */
int rt_topology_has_ties(const rt_topology *topo);

/* The dimension a port moves along: a route keeps its channel while it stays in one. */
int rt_topology_port_dimension(const rt_topology *topo, int port);

/* Virtual channels per link the deadlock-free scheme needs: 2 where a dimension is a ring
 * (channel 1 from its dateline on), else 1. */
int rt_topology_channels(const rt_topology *topo);

/* Whether the link leaving `node` through `port` is its ring's dateline (a packet crossing it
 * takes channel 1 until it leaves the dimension): 1 or 0 (always 0 with one channel). */
int rt_topology_crosses_dateline(const rt_topology *topo, int node, int port);

#ifdef __cplusplus
}
#endif
#endif
