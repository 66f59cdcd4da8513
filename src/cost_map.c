/* cost_map.c - the weighted cell graph and its Scotch mapping onto the nodes' topology. */
#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <scotch.h>

#include "cost_internal.h"
#include "rt_cost_map.h"
#include "topology_class.h"

/* Integer weights: the largest weight and the largest weight total Scotch gets. */
#define WEIGHT_MAX (1 << 20)
#define TOTAL_MAX (1 << 30)

typedef struct cell_graph {
    SCOTCH_Num *verttab, *velotab, *edgetab, *edlotab;
    SCOTCH_Num vertnbr, edgenbr;
} cell_graph;

static void graph_free(cell_graph *g)
{
    free(g->verttab);
    free(g->velotab);
    free(g->edgetab);
    free(g->edlotab);
}

/* Neighbour of cell c through face f, -1 at the grid's boundary. */
long rt_cost_neighbour(const int d[3], long c, int f)
{
    long x = c % d[0], y = c / d[0] % d[1], z = c / ((long)d[0] * d[1]);
    long p[3] = {x, y, z};
    p[f / 2] += (f % 2) ? 1 : -1;
    if (p[f / 2] < 0 || p[f / 2] >= d[f / 2]) return -1;
    return p[0] + d[0] * (p[1] + (long)d[1] * p[2]);
}

/* Packets across the face f of c, both ways. */
static double face_packets(const rt_cost_pilot *p, long c, int f, long nb)
{
    return (double)p->traffic[c * RT_CELL_FACES + f] + (double)p->traffic[nb * RT_CELL_FACES + (f ^ 1)];
}

static SCOTCH_Num scaled(double v, double scale)
{
    double w = floor(v * scale + 0.5);
    return w < 1 ? 1 : (SCOTCH_Num)w;
}

/* Builds the CSR graph with one common scale for work and traffic (both microseconds). */
static rt_status build_graph(const rt_cost_pilot *p, double edge_us, cell_graph *g)
{
    memset(g, 0, sizeof *g);
    g->vertnbr = (SCOTCH_Num)p->cells;
    double wmax = 0, wsum = 0, emax = 0, esum = 0;
    for (long c = 0; c < (long)p->cells; c++) {
        wmax = fmax(wmax, p->work_us[c]);
        wsum += p->work_us[c];
        for (int f = 0; f < RT_CELL_FACES; f++) {
            long nb = rt_cost_neighbour(p->dims, c, f);
            if (nb < 0) continue;
            double e = face_packets(p, c, f, nb) * edge_us;
            emax = fmax(emax, e);
            esum += e;
            g->edgenbr++;
        }
    }
    double big = fmax(wmax, emax), total = fmax(wsum, esum);
    double scale =
        big > 0 ? fmin(WEIGHT_MAX / big, (TOTAL_MAX - 2.0 * (double)g->edgenbr - 2.0 * (double)p->cells) / total) : 1;
    g->verttab = malloc(((size_t)g->vertnbr + 1) * sizeof *g->verttab);
    g->velotab = malloc((size_t)g->vertnbr * sizeof *g->velotab);
    g->edgetab = malloc(((size_t)g->edgenbr + 1) * sizeof *g->edgetab);
    g->edlotab = malloc(((size_t)g->edgenbr + 1) * sizeof *g->edlotab);
    if (!g->verttab || !g->velotab || !g->edgetab || !g->edlotab) return RT_ERR_NOMEM;
    SCOTCH_Num e = 0;
    for (long c = 0; c < (long)p->cells; c++) {
        g->verttab[c] = e;
        g->velotab[c] = scaled(p->work_us[c], scale);
        for (int f = 0; f < RT_CELL_FACES; f++) {
            long nb = rt_cost_neighbour(p->dims, c, f);
            if (nb < 0) continue;
            g->edgetab[e] = (SCOTCH_Num)nb;
            g->edlotab[e++] = scaled(face_packets(p, c, f, nb) * edge_us, scale);
        }
    }
    g->verttab[g->vertnbr] = e;
    return RT_OK;
}

uint64_t rt_cost_map_bytes(size_t cells)
{
    uint64_t n = cells;
    /* verttab, velotab, edgetab and edlotab (at most six faces a cell), and the part tables */
    uint64_t graph = (2 * (n + 1) + 2 * (RT_CELL_FACES * n + 1)) * sizeof(SCOTCH_Num);
    return 2 * graph + 3 * n * sizeof(SCOTCH_Num);
}

/* A failed Scotch call; Scotch's own message is printed above. Its allocations are malloc's, so
 * errno (cleared before the calls) tells an allocation refused: RT_ERR_NOMEM. */
static rt_status scotch_fail(char *msg, size_t msg_len, const char *call)
{
    int nomem = errno == ENOMEM;
    if (msg && msg_len)
        snprintf(msg, msg_len, "Scotch: %s failed (%ssee its message above)", call, nomem ? "out of memory; " : "");
    return nomem ? RT_ERR_NOMEM : RT_ERR_INVALID;
}

/* A single-threaded, deterministic Scotch context with a fixed seed bound to `graph`. */
static rt_status bind_context(SCOTCH_Context *ctx, SCOTCH_Graph *graph, SCOTCH_Graph *bound, char *msg, size_t msg_len)
{
    if (SCOTCH_contextInit(ctx) != 0) return scotch_fail(msg, msg_len, "SCOTCH_contextInit");
    if (SCOTCH_contextOptionSetNum(ctx, SCOTCH_OPTIONNUMDETERMINISTIC, 1) != 0 ||
        SCOTCH_contextOptionSetNum(ctx, SCOTCH_OPTIONNUMRANDOMFIXEDSEED, 1) != 0)
        return scotch_fail(msg, msg_len, "SCOTCH_contextOptionSetNum");
    SCOTCH_contextRandomSeed(ctx, 1);
    SCOTCH_contextRandomReset(ctx);
    if (SCOTCH_contextThreadSpawn(ctx, 1, NULL) != 0) return scotch_fail(msg, msg_len, "SCOTCH_contextThreadSpawn");
    if (SCOTCH_graphInit(bound) != 0) return scotch_fail(msg, msg_len, "SCOTCH_graphInit");
    if (SCOTCH_contextBindGraph(ctx, graph, bound) != 0) {
        SCOTCH_graphExit(bound);
        return scotch_fail(msg, msg_len, "SCOTCH_contextBindGraph");
    }
    return RT_OK;
}

/* A remapping's inputs: the old owner of every vertex and the cost of moving it. */
typedef struct remap_args {
    SCOTCH_Num *old_part; /* NULL: a plain mapping */
    SCOTCH_Num *move_load;
} remap_args;

/* Maps the bound graph onto the topology grown `fold` times (or remaps it from the old partition). */
static rt_status map_onto(SCOTCH_Graph *graph, const rt_topology *topo, int fold, const remap_args *remap,
                          SCOTCH_Num *parttab, char *msg, size_t msg_len)
{
    SCOTCH_Arch arch;
    SCOTCH_Strat strat;
    rt_status st = RT_OK;
    const char *call = "SCOTCH_archInit";
    SCOTCH_archInit(&arch);
    if (rt_topology_scotch_arch(topo, fold, &arch, &call) != 0) st = scotch_fail(msg, msg_len, call);
    SCOTCH_stratInit(&strat);
    SCOTCH_Num parts = st == RT_OK ? SCOTCH_archSize(&arch) : 1;
    SCOTCH_Num flags = SCOTCH_STRATQUALITY | SCOTCH_STRATBALANCE | (remap->old_part ? SCOTCH_STRATREMAP : 0);
    if (st == RT_OK && SCOTCH_stratGraphMapBuild(&strat, flags, parts, 0.03) != 0)
        st = scotch_fail(msg, msg_len, "SCOTCH_stratGraphMapBuild");
    if (st == RT_OK && !remap->old_part && SCOTCH_graphMap(graph, &arch, &strat, parttab) != 0)
        st = scotch_fail(msg, msg_len, "SCOTCH_graphMap");
    /* Moving a vertex costs its migration load (times a ratio of 1), in the edge loads' units. */
    if (st == RT_OK && remap->old_part &&
        SCOTCH_graphRemap(graph, &arch, remap->old_part, 1.0, remap->move_load, &strat, parttab) != 0)
        st = scotch_fail(msg, msg_len, "SCOTCH_graphRemap");
    SCOTCH_stratExit(&strat);
    SCOTCH_archExit(&arch);
    return st;
}

/* Scotch 7.0 frees a coarse graph twice when an allocation fails inside its multilevel mapping
 * (kgraphMapMl, then kgraphExit: glibc aborts the process), so Scotch must not run short. The
 * memory it may take is asked for and given back before it runs: 48 MiB plus 512 bytes a cell
 * bounds the growth of the address space over SCOTCH_graphMap with a margin of 1.4 or more
 * (measured: 4.5 MiB at 4096 cells, 33 at 32768, 72 at 110592, 98 at 262144, 255 at 884736, 473
 * at 2097152). Through a volatile pointer, so that the compiler keeps the allocation. */
static size_t scotch_work_bytes(size_t cells) { return ((size_t)48 << 20) + cells * 512; }

static int scotch_headroom(size_t cells)
{
    void *(*volatile allocate)(size_t) = malloc;
    void *probe = allocate(scotch_work_bytes(cells));
    free(probe);
    return probe != NULL;
}

/* Runs Scotch on the graph; parttab gets a terminal of the grown topology per cell. */
static rt_status scotch_map(cell_graph *g, const rt_topology *topo, int fold, const remap_args *remap,
                            SCOTCH_Num *parttab, char *msg, size_t msg_len)
{
    SCOTCH_Graph graph, bound;
    SCOTCH_Context ctx;
    if (!scotch_headroom((size_t)g->vertnbr)) {
        if (msg && msg_len)
            snprintf(msg, msg_len, "Scotch: out of memory (%lu MiB asked for its work on %lu cells)",
                     (unsigned long)(scotch_work_bytes((size_t)g->vertnbr) >> 20), (unsigned long)g->vertnbr);
        return RT_ERR_NOMEM;
    }
    SCOTCH_randomSeed(1); /* the global generator too, for any path that uses it */
    SCOTCH_randomReset();
    errno = 0; /* scotch_fail reads it */
    if (SCOTCH_graphInit(&graph) != 0) return scotch_fail(msg, msg_len, "SCOTCH_graphInit");
    rt_status st = RT_OK;
    if (SCOTCH_graphBuild(&graph, 0, g->vertnbr, g->verttab, NULL, g->velotab, NULL, g->edgenbr, g->edgetab,
                          g->edlotab) != 0)
        st = scotch_fail(msg, msg_len, "SCOTCH_graphBuild");
    else if (SCOTCH_graphCheck(&graph) != 0) st = scotch_fail(msg, msg_len, "SCOTCH_graphCheck");
    if (st == RT_OK) {
        st = bind_context(&ctx, &graph, &bound, msg, msg_len);
        if (st == RT_OK) {
            st = map_onto(&bound, topo, fold, remap, parttab, msg, msg_len);
            SCOTCH_graphExit(&bound);
        }
        SCOTCH_contextExit(&ctx);
    }
    SCOTCH_graphExit(&graph);
    return st;
}

void rt_cost_map_facts_of(const rt_cost_pilot *p, const rt_topology *topo, const int32_t *owner,
                          rt_cost_map_facts *facts)
{
    int n = topo->nodes;
    double *work = calloc((size_t)n, sizeof *work);
    memset(facts, 0, sizeof *facts);
    if (!work) return;
    for (long c = 0; c < (long)p->cells; c++) {
        work[owner[c]] += p->work_us[c];
        for (int f = 1; f < RT_CELL_FACES; f += 2) { /* each face once */
            long nb = rt_cost_neighbour(p->dims, c, f);
            if (nb < 0 || owner[nb] == owner[c]) continue;
            double k = face_packets(p, c, f, nb);
            facts->cut_packets += k;
            facts->cut_hops += k * rt_topology_hops(topo, owner[c], owner[nb]);
        }
    }
    for (int i = 0; i < n; i++) facts->max_node_work_us = fmax(facts->max_node_work_us, work[i]);
    facts->mean_node_work_us = p->total_us / n;
    free(work);
}

rt_status rt_cost_map(const rt_cost_pilot *p, const rt_topology *topo, double edge_us, int32_t *owner,
                      rt_cost_map_facts *facts, char *msg, size_t msg_len)
{
    return rt_cost_map_folded(p, topo, edge_us, 1, owner, facts, msg, msg_len);
}

rt_status rt_cost_map_folded(const rt_cost_pilot *p, const rt_topology *topo, double edge_us, int fold, int32_t *owner,
                             rt_cost_map_facts *facts, char *msg, size_t msg_len)
{
    if (!topo || topo->nodes < 1 || !p->work_us || !(edge_us >= 0) || fold < 1 || fold > 64) {
        if (msg && msg_len) snprintf(msg, msg_len, "cost mapping: bad arguments");
        return RT_ERR_INVALID;
    }
    if (p->cells > (size_t)(TOTAL_MAX / 8)) {
        if (msg && msg_len)
            snprintf(msg, msg_len, "cost mapping: %zu cells is too many for Scotch's weights", p->cells);
        return RT_ERR_LIMIT;
    }
    rt_status st = RT_OK;
    if (topo->nodes == 1) {
        for (size_t c = 0; c < p->cells; c++) owner[c] = 0;
    } else {
        cell_graph g;
        SCOTCH_Num *part = malloc(p->cells * sizeof *part);
        st = build_graph(p, edge_us, &g);
        if (st == RT_OK && !part) st = RT_ERR_NOMEM;
        if (st == RT_ERR_NOMEM && msg && msg_len) snprintf(msg, msg_len, "cost mapping: out of memory");
        remap_args plain = {NULL, NULL};
        if (st == RT_OK) st = scotch_map(&g, topo, fold, &plain, part, msg, msg_len);
        for (size_t c = 0; st == RT_OK && c < p->cells; c++)
            owner[c] = (int32_t)rt_topology_fold_terminal(topo, fold, (long)part[c]);
        free(part);
        graph_free(&g);
    }
    if (st == RT_OK && facts) rt_cost_map_facts_of(p, topo, owner, facts);
    return st;
}

rt_status rt_cost_remap(const rt_cost_pilot *p, const rt_topology *topo, double edge_us, const int32_t *old_owner,
                        const double *move_us, int32_t *owner, rt_cost_map_facts *facts, char *msg, size_t msg_len)
{
    long n = topo ? topo->nodes : 0;
    if (n < 1 || !p->work_us || !(edge_us >= 0) || !old_owner || !move_us) {
        if (msg && msg_len) snprintf(msg, msg_len, "cost remapping: bad arguments");
        return RT_ERR_INVALID;
    }
    if (p->cells > (size_t)(TOTAL_MAX / 8)) {
        if (msg && msg_len)
            snprintf(msg, msg_len, "cost remapping: %zu cells is too many for Scotch's weights", p->cells);
        return RT_ERR_LIMIT;
    }
    if (n == 1) return rt_cost_map(p, topo, edge_us, owner, facts, msg, msg_len);
    cell_graph g;
    rt_status st = build_graph(p, edge_us, &g);
    SCOTCH_Num *part = malloc(p->cells * sizeof *part);
    SCOTCH_Num *old_part = malloc(p->cells * sizeof *old_part);
    SCOTCH_Num *move = malloc(p->cells * sizeof *move);
    if (st == RT_OK && (!part || !old_part || !move)) st = RT_ERR_NOMEM;
    if (st == RT_ERR_NOMEM && msg && msg_len) snprintf(msg, msg_len, "cost remapping: out of memory");
    if (st == RT_OK) {
        /* The graph's scale, recovered from the largest vertex weight, scales the move costs too. */
        double wmax = 0;
        SCOTCH_Num vmax = 1;
        for (size_t c = 0; c < p->cells; c++) {
            wmax = fmax(wmax, p->work_us[c]);
            if (g.velotab[c] > vmax) vmax = g.velotab[c];
        }
        double scale = wmax > 0 ? (double)vmax / wmax : 1;
        for (size_t c = 0; c < p->cells; c++) {
            SCOTCH_Num m = scaled(move_us[c], scale);
            move[c] = m > WEIGHT_MAX ? WEIGHT_MAX : m;
            old_part[c] = (old_owner[c] >= 0 && old_owner[c] < n) ? old_owner[c] : -1;
        }
        remap_args args = {old_part, move};
        st = scotch_map(&g, topo, 1, &args, part, msg, msg_len);
    }
    for (size_t c = 0; st == RT_OK && c < p->cells; c++)
        owner[c] = (int32_t)rt_topology_fold_terminal(topo, 1, (long)part[c]);
    free(part);
    free(old_part);
    free(move);
    graph_free(&g);
    if (st == RT_OK && facts) rt_cost_map_facts_of(p, topo, owner, facts);
    return st;
}
