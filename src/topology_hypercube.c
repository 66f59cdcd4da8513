/* topology_hypercube.c - the binary hypercube: 2^d nodes, a link between every two ids that
 * differ in one bit, port i flipping bit i. The grid positions of --ips PX x PY x PZ (each a
 * power of two) take bits: the node at (x, y, z) is gray(x) | gray(y) << log2 PX |
 * gray(z) << (log2 PX + log2 PY), gray the reflected Gray code, which is cyclic: positions c and
 * c + 1 (mod P) are one hop apart, so the cyclic mapping keeps neighbouring cells one hop apart,
 * round the wrap too. Routes are e-cube: the lowest differing bit first, a minimal route of
 * popcount(a ^ b) hops with no tie. */
#include <stdio.h>

#include <scotch.h>

#include "topology_class.h"

static int log2_of(int p)
{
    int b = 0;
    while ((1 << b) < p) b++;
    return b;
}

static unsigned gray(unsigned c) { return c ^ (c >> 1); }

static unsigned gray_inverse(unsigned g)
{
    for (unsigned shift = 1; shift < 32; shift <<= 1) g ^= g >> shift;
    return g;
}

static rt_status cube_init(rt_topology *t, char *msg, size_t msg_len)
{
    for (int k = 0; k < 3; k++)
        if ((t->dims[k] & (t->dims[k] - 1)) != 0) {
            if (msg && msg_len)
                snprintf(msg, msg_len, "a hypercube needs a power of two nodes along every axis (%dx%dx%d)", t->dims[0],
                         t->dims[1], t->dims[2]);
            return RT_ERR_INVALID;
        }
    t->ports = log2_of(t->nodes);
    if (t->ports > RT_TOPOLOGY_MAX_PORTS) {
        if (msg && msg_len) snprintf(msg, msg_len, "a hypercube of at most %d dimensions", RT_TOPOLOGY_MAX_PORTS);
        return RT_ERR_INVALID;
    }
    return RT_OK;
}

static const char *cube_port_name(const rt_topology *t, int port)
{
    static const char *const names[RT_TOPOLOGY_MAX_PORTS] = {"d0", "d1", "d2", "d3", "d4",  "d5",
                                                             "d6", "d7", "d8", "d9", "d10", "d11"};
    (void)t;
    return names[port];
}

static int cube_neighbour(const rt_topology *t, int node, int port)
{
    (void)t;
    return node ^ (1 << port);
}

static int cube_node_at(const rt_topology *t, const int c[3])
{
    int bx = log2_of(t->dims[0]), by = log2_of(t->dims[1]);
    return (int)(gray((unsigned)c[0]) | gray((unsigned)c[1]) << bx | gray((unsigned)c[2]) << (bx + by));
}

static void cube_position(const rt_topology *t, int node, int c[3])
{
    unsigned n = (unsigned)node;
    for (int k = 0; k < 3; k++) {
        int b = log2_of(t->dims[k]);
        c[k] = (int)gray_inverse(n & ((1u << b) - 1));
        n >>= b;
    }
}

static int cube_hops(const rt_topology *t, int a, int b)
{
    (void)t;
    return __builtin_popcount((unsigned)(a ^ b));
}

static int cube_first_port(const rt_topology *t, int from, int to, rt_route_ties ties, uint32_t tie_key)
{
    (void)t;
    (void)ties;
    (void)tie_key;
    return from == to ? -1 : __builtin_ctz((unsigned)(from ^ to));
}

static int cube_has_ties(const rt_topology *t)
{
    (void)t;
    return 0;
}

static int cube_port_dimension(const rt_topology *t, int port)
{
    (void)t;
    return port;
}

/* E-cube routes take the dimensions in increasing order and each once: no cycle, no dateline. */
static int cube_crosses_dateline(const rt_topology *t, int node, int port)
{
    (void)t;
    (void)node;
    (void)port;
    return 0;
}

/* Bits the cube grows by for cost:K: ceil(log2 K) per axis of more than one node. */
static int grown_bits(const rt_topology *t, int fold)
{
    int axes = (t->dims[0] > 1) + (t->dims[1] > 1) + (t->dims[2] > 1);
    return axes * log2_of(fold);
}

/* Scotch's hypercube numbers its terminals so that the distance is the Hamming distance of
 * their numbers (topology_test checks it against the hops): terminal i is node i. */
static int cube_scotch_arch(const rt_topology *t, int fold, void *arch, const char **call)
{
    *call = "SCOTCH_archHcub";
    return SCOTCH_archHcub((SCOTCH_Arch *)arch, t->ports + grown_bits(t, fold));
}

/* A terminal of the grown cube folds onto the node of its low d bits. */
static int cube_fold_terminal(const rt_topology *t, int fold, long terminal)
{
    (void)fold;
    return (int)(terminal & ((1L << t->ports) - 1));
}

const rt_topology_class rt_topology_hypercube_class = {.name = "hypercube",
                                                       .kind = RT_TOPOLOGY_OTHER,
                                                       .one_axis_name = NULL,
                                                       .channels = 1,
                                                       .init = cube_init,
                                                       .port_name = cube_port_name,
                                                       .neighbour = cube_neighbour,
                                                       .node_at = cube_node_at,
                                                       .position = cube_position,
                                                       .hops = cube_hops,
                                                       .first_port = cube_first_port,
                                                       .has_ties = cube_has_ties,
                                                       .port_dimension = cube_port_dimension,
                                                       .crosses_dateline = cube_crosses_dateline,
                                                       .scotch_arch = cube_scotch_arch,
                                                       .fold_terminal = cube_fold_terminal};
