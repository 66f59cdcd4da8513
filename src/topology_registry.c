/* topology_registry.c - the topologies by name, and the calls that reach a topology's class. */
#include <stdio.h>
#include <string.h>

#include "rt_topology.h"
#include "topology_class.h"

extern const rt_topology_class rt_topology_torus_class, rt_topology_mesh_class, rt_topology_hypercube_class;

/* One line per topology: the names --topology takes, in the order help lists them. */
static const rt_topology_class *const registry[] = {
    &rt_topology_torus_class,
    &rt_topology_mesh_class,
    &rt_topology_hypercube_class,
};

static const int registry_count = (int)(sizeof registry / sizeof registry[0]);

const char *rt_topology_name_at(int i) { return i >= 0 && i < registry_count ? registry[i]->name : NULL; }

rt_status rt_topology_make(const char *name, const int dims[3], rt_topology *topo, char *msg, size_t msg_len)
{
    const rt_topology_class *cls = NULL;
    for (int i = 0; name && i < registry_count; i++)
        if (strcmp(registry[i]->name, name) == 0) cls = registry[i];
    if (!cls) {
        if (msg && msg_len) snprintf(msg, msg_len, "unknown topology '%s'", name ? name : "");
        return RT_ERR_INVALID;
    }
    if (dims[0] < 1 || dims[1] < 1 || dims[2] < 1) {
        if (msg && msg_len)
            snprintf(msg, msg_len, "%dx%dx%d nodes: each axis needs at least 1", dims[0], dims[1], dims[2]);
        return RT_ERR_INVALID;
    }
    memset(topo, 0, sizeof *topo);
    topo->cls = cls;
    topo->kind = cls->kind;
    long nodes = (long)dims[0] * dims[1] * dims[2];
    if (nodes > (1L << 30)) {
        if (msg && msg_len) snprintf(msg, msg_len, "%ld nodes: too many", nodes);
        return RT_ERR_INVALID;
    }
    for (int k = 0; k < 3; k++) topo->dims[k] = dims[k];
    topo->nodes = (int)nodes;
    return cls->init(topo, msg, msg_len);
}

const char *rt_topology_name(const rt_topology *t) { return t->cls->name; }
const char *rt_topology_one_axis_name(const rt_topology *t) { return t->cls->one_axis_name; }

const char *rt_topology_port_name(const rt_topology *t, int port)
{
    return port >= 0 && port < t->ports ? t->cls->port_name(t, port) : "none";
}

int rt_topology_neighbour(const rt_topology *t, int node, int port) { return t->cls->neighbour(t, node, port); }
int rt_topology_node_at(const rt_topology *t, const int c[3]) { return t->cls->node_at(t, c); }
void rt_topology_position(const rt_topology *t, int node, int c[3]) { t->cls->position(t, node, c); }

int rt_topology_node_of_grid_id(const rt_topology *t, int id)
{
    int c[3] = {id % t->dims[0], id / t->dims[0] % t->dims[1], id / (t->dims[0] * t->dims[1])};
    return t->cls->node_at(t, c);
}

int rt_topology_hops(const rt_topology *t, int a, int b) { return t->cls->hops(t, a, b); }

int rt_topology_first_port(const rt_topology *t, int from, int to, rt_route_ties ties, uint32_t tie_key)
{
    return t->cls->first_port(t, from, to, ties, tie_key);
}

int rt_topology_has_ties(const rt_topology *t) { return t->cls->has_ties(t); }
int rt_topology_port_dimension(const rt_topology *t, int port) { return t->cls->port_dimension(t, port); }
int rt_topology_channels(const rt_topology *t) { return t->cls->channels; }

int rt_topology_crosses_dateline(const rt_topology *t, int node, int port)
{
    return t->cls->crosses_dateline(t, node, port);
}

int rt_topology_scotch_arch(const rt_topology *t, int fold, void *arch, const char **call)
{
    return t->cls->scotch_arch(t, fold, arch, call);
}

int rt_topology_fold_terminal(const rt_topology *t, int fold, long terminal)
{
    return t->cls->fold_terminal(t, fold, terminal);
}
