/* topology_torus.c - the torus and the mesh: nodes on a PX x PY x PZ grid, id x + PX * (y + PY * z),
 * six ports (+ and - along each axis: 2 * axis + (0 for +, 1 for -)), dimension-order routes
 * (x, then y, then z). On the torus each axis is a ring and a route goes the shorter way round,
 * a tie (the opposite node of an even ring) by the tie rule; on the mesh each axis is a line. */
#include <stdlib.h>

#include <scotch.h>

#include "topology_class.h"

static int is_torus(const rt_topology *t) { return t->kind == RT_TOPOLOGY_TORUS; }

static rt_status grid_init(rt_topology *t, char *msg, size_t msg_len)
{
    (void)msg;
    (void)msg_len;
    t->ports = 6;
    return RT_OK;
}

static const char *grid_port_name(const rt_topology *t, int port)
{
    static const char *const names[6] = {"xp", "xm", "yp", "ym", "zp", "zm"};
    (void)t;
    return names[port];
}

static int grid_node_at(const rt_topology *t, const int c[3]) { return c[0] + t->dims[0] * (c[1] + t->dims[1] * c[2]); }

static void grid_position(const rt_topology *t, int node, int c[3])
{
    c[0] = node % t->dims[0];
    c[1] = node / t->dims[0] % t->dims[1];
    c[2] = node / (t->dims[0] * t->dims[1]);
}

static int grid_neighbour(const rt_topology *t, int node, int port)
{
    int axis = port / 2, step = port % 2 == 0 ? 1 : -1, p = t->dims[axis];
    if (p < 2) return -1;
    int c[3];
    grid_position(t, node, c);
    int v = c[axis] + step;
    if (v < 0 || v >= p) {
        if (!is_torus(t)) return -1;
        v = (v + p) % p;
    }
    c[axis] = v;
    return grid_node_at(t, c);
}

static int grid_hops(const rt_topology *t, int a, int b)
{
    int h = 0;
    for (int k = 0; k < 3; k++) {
        int n = t->dims[k], d = abs(a % n - b % n);
        h += is_torus(t) && n - d < d ? n - d : d;
        a /= n;
        b /= n;
    }
    return h;
}

static int grid_first_port(const rt_topology *t, int from, int to, rt_route_ties ties, uint32_t tie_key)
{
    int a[3], b[3];
    grid_position(t, from, a);
    grid_position(t, to, b);
    for (int axis = 0; axis < 3; axis++) {
        if (a[axis] == b[axis]) continue;
        if (!is_torus(t)) return 2 * axis + (b[axis] > a[axis] ? 0 : 1);
        int p = t->dims[axis], forward = b[axis] - a[axis];
        if (forward < 0) forward += p; /* the hops going + round the ring */
        if (forward != p - forward) return 2 * axis + (forward < p - forward ? 0 : 1);
        return 2 * axis + (ties == RT_TIES_PLUS || tie_key % 2 == 0 ? 0 : 1);
    }
    return -1;
}

static int grid_has_ties(const rt_topology *t)
{
    if (!is_torus(t)) return 0;
    for (int k = 0; k < 3; k++)
        if (t->dims[k] % 2 == 0) return 1;
    return 0;
}

static int grid_port_dimension(const rt_topology *t, int port)
{
    (void)t;
    return port / 2;
}

/* The ring's wrap-around link: from the last coordinate to 0 going +, from 0 to the last going -. */
static int grid_crosses_dateline(const rt_topology *t, int node, int port)
{
    int axis = port / 2;
    if (!is_torus(t) || t->dims[axis] < 2) return 0;
    int c[3];
    grid_position(t, node, c);
    return port % 2 == 0 ? c[axis] == t->dims[axis] - 1 : c[axis] == 0;
}

/* Positions per axis of the grown machine. */
static void grown(const rt_topology *t, int fold, int v[3])
{
    for (int k = 0; k < 3; k++) v[k] = t->dims[k] > 1 ? t->dims[k] * fold : 1;
}

/* Scotch numbers a 3-D torus's or mesh's terminals x fastest, as the node ids. */
static int grid_scotch_arch(const rt_topology *t, int fold, void *arch, const char **call)
{
    int v[3];
    grown(t, fold, v);
    *call = is_torus(t) ? "SCOTCH_archTorus3" : "SCOTCH_archMesh3";
    return is_torus(t) ? SCOTCH_archTorus3((SCOTCH_Arch *)arch, v[0], v[1], v[2])
                       : SCOTCH_archMesh3((SCOTCH_Arch *)arch, v[0], v[1], v[2]);
}

/* Each coordinate of the grown machine modulo the nodes'. */
static int grid_fold_terminal(const rt_topology *t, int fold, long terminal)
{
    int v[3];
    grown(t, fold, v);
    int x = (int)(terminal % v[0]), y = (int)(terminal / v[0] % v[1]), z = (int)(terminal / ((long)v[0] * v[1]));
    const int *n = t->dims;
    return x % n[0] + n[0] * (y % n[1] + n[1] * (z % n[2]));
}

#define GRID_CLASS(NAME, KIND, ONE_AXIS, CHANNELS)                                                                     \
    {                                                                                                                  \
        .name = NAME, .kind = KIND, .one_axis_name = ONE_AXIS, .channels = CHANNELS, .init = grid_init,                \
        .port_name = grid_port_name, .neighbour = grid_neighbour, .node_at = grid_node_at, .position = grid_position,  \
        .hops = grid_hops, .first_port = grid_first_port, .has_ties = grid_has_ties,                                   \
        .port_dimension = grid_port_dimension, .crosses_dateline = grid_crosses_dateline,                              \
        .scotch_arch = grid_scotch_arch, .fold_terminal = grid_fold_terminal                                           \
    }

/* The torus's dateline needs a second channel per link; the mesh has none. */
const rt_topology_class rt_topology_torus_class = GRID_CLASS("torus", RT_TOPOLOGY_TORUS, "ring", 2);
const rt_topology_class rt_topology_mesh_class = GRID_CLASS("mesh", RT_TOPOLOGY_MESH, "line", 1);
