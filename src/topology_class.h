/* topology_class.h - what a topology registers: its name and its functions (rt_topology.h says
 * what each returns). One file per topology defines one or more of these; topology_registry.c
 * lists them by name. */
#ifndef RT_TOPOLOGY_CLASS_H
#define RT_TOPOLOGY_CLASS_H

#include <stddef.h>
#include <stdint.h>

#include "rt_topology.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct rt_topology_class {
    const char *name;          /* the name rt_topology_make takes */
    rt_topology_kind kind;     /* torus, mesh or a plug-in */
    const char *one_axis_name; /* a machine with one axis of more than one node ("ring"), or NULL */
    int channels;              /* virtual channels per link the deadlock-free scheme needs */
    /* Checks topo->dims and sets topo->ports; RT_ERR_INVALID with a message on a shape it cannot take. */
    rt_status (*init)(rt_topology *topo, char *msg, size_t msg_len);
    const char *(*port_name)(const rt_topology *topo, int port);
    int (*neighbour)(const rt_topology *topo, int node, int port);
    int (*node_at)(const rt_topology *topo, const int c[3]);
    void (*position)(const rt_topology *topo, int node, int c[3]);
    int (*hops)(const rt_topology *topo, int a, int b);
    int (*first_port)(const rt_topology *topo, int from, int to, rt_route_ties ties, uint32_t tie_key);
    int (*has_ties)(const rt_topology *topo);
    int (*port_dimension)(const rt_topology *topo, int port);
    int (*crosses_dateline)(const rt_topology *topo, int node, int port);
    /* Builds into `arch` (an initialised SCOTCH_Arch) Scotch's architecture of the machine grown
     * `fold` times along every axis of more than one node (fold 1: the machine itself, its
     * terminals numbered as the nodes); 0 or Scotch's non-zero result, `*call` naming the call. */
    int (*scotch_arch)(const rt_topology *topo, int fold, void *arch, const char **call);
    /* The node a terminal of the grown architecture folds onto. */
    int (*fold_terminal)(const rt_topology *topo, int fold, long terminal);
} rt_topology_class;

/* Scotch's architecture and its terminals' nodes, as the topology's class gives them. */
int rt_topology_scotch_arch(const rt_topology *topo, int fold, void *arch, const char **call);
int rt_topology_fold_terminal(const rt_topology *topo, int fold, long terminal);

#ifdef __cplusplus
}
#endif
#endif
