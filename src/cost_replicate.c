/* cost_replicate.c - copies of the hottest cells on more nodes, within a memory budget per node
 * (rt_cost_replicate in rt_cost_map.h). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cost_internal.h"
#include "rt_cost_map.h"
#include "scene_internal.h"

/* The most bits the per-node "holds this object / material" marks may take (256 MiB). */
#define MARK_BITS_MAX ((uint64_t)1 << 31)

typedef struct replicate_state {
    const rt_cost_pilot *pilot;
    const rt_scene *scene;
    const rt_grid *grid;
    const int32_t *owner;
    rt_memory_layout layout;
    int nodes;
    const rt_topology *topo; /* the nodes' network */
    rt_replica_rule rule;
    int32_t *own;       /* scratch: one cell's owners, the candidate last */
    double *inflow;     /* scratch: per owner, pilot packets entering the cell that reach it */
    double *cur, *next; /* scratch: per owner, its predicted share of the cell now and with the candidate */
    double *load;       /* per node: predicted work, each cell's work split evenly over its owners */
    double *room;       /* per node: bytes of the budget left */
    uint32_t *owners;   /* per cell: owners (1 + extra) */
    int32_t *head;      /* per cell: first extra owner's pair, -1 none */
    int32_t *pair_node; /* per pair: the extra owner */
    int32_t *pair_next; /* per pair: the cell's next pair, -1 none */
    size_t pairs, pair_cap;
    unsigned char *held_obj, *held_mat; /* per node: bit marks of the objects and materials it holds */
    unsigned char *done;                /* per cell: no further copy of it helps */
} replicate_state;

static int bit(const unsigned char *m, uint64_t i) { return (m[i >> 3] >> (i & 7)) & 1; }
static void set_bit(unsigned char *m, uint64_t i) { m[i >> 3] |= (unsigned char)(1u << (i & 7)); }

static int holds(const replicate_state *s, uint32_t c, int32_t n)
{
    if (s->owner[c] == n) return 1;
    for (int32_t p = s->head[c]; p >= 0; p = s->pair_next[p])
        if (s->pair_node[p] == n) return 1;
    return 0;
}

/* Marks cell c's objects and materials as held by node n. */
static void hold_cell(replicate_state *s, uint32_t c, int32_t n)
{
    size_t count;
    const uint32_t *list = rt_grid_cell_objects(s->grid, c, &count);
    for (size_t j = 0; j < count; j++) {
        set_bit(s->held_obj, (uint64_t)n * s->scene->object_count + list[j]);
        set_bit(s->held_mat, (uint64_t)n * s->scene->material_count + s->scene->objects[list[j]].material);
    }
}

/* Bytes node n must add to hold cell c: its list, and the objects and materials it lacks. */
static double copy_bytes(const replicate_state *s, uint32_t c, int32_t n)
{
    size_t count;
    const uint32_t *list = rt_grid_cell_objects(s->grid, c, &count);
    double bytes = s->layout.cell_header_bytes + (double)s->layout.list_entry_bytes * (double)count;
    for (size_t j = 0; j < count; j++) {
        uint32_t ob = list[j], m = s->scene->objects[ob].material;
        if (!bit(s->held_obj, (uint64_t)n * s->scene->object_count + ob))
            bytes += rt_memory_object_bytes(s->scene, ob, &s->layout);
        int seen = bit(s->held_mat, (uint64_t)n * s->scene->material_count + m);
        for (size_t i = 0; i < j && !seen; i++) seen = s->scene->objects[list[i]].material == m;
        if (!seen) bytes += rt_scene_material_bytes();
    }
    return bytes;
}

/* Cell c's owners into s->own (primary first); their count. */
static int owners_of(const replicate_state *s, uint32_t c)
{
    int k = 0;
    s->own[k++] = s->owner[c];
    for (int32_t p = s->head[c]; p >= 0; p = s->pair_next[p]) s->own[k++] = s->pair_node[p];
    return k;
}

/* Predicted share of cell c's work at each of its k owners s->own[0..k-1], into share[]. Under
 * hash an even split. Under nearest, the packets the pilot saw enter c through each face go to
 * the owner nearest the node holding the neighbouring cell (its primary owner; ties to the
 * lowest node, as the model's rule), and each owner's share is its part of those packets (an
 * even split when none enter). */
static void owner_shares(const replicate_state *s, uint32_t c, int k, double *share)
{
    double w = s->pilot->work_us[c], total = 0;
    for (int i = 0; i < k; i++) s->inflow[i] = 0;
    for (int f = 0; s->rule == RT_REPLICA_NEAREST && f < RT_CELL_FACES; f++) {
        long nb = rt_cost_neighbour(s->pilot->dims, (long)c, f);
        if (nb < 0) continue;
        double in = (double)s->pilot->traffic[nb * RT_CELL_FACES + (f ^ 1)];
        if (in <= 0) continue;
        int best = 0, best_hops = rt_topology_hops(s->topo, s->owner[nb], s->own[0]);
        for (int i = 1; i < k; i++) {
            int h = rt_topology_hops(s->topo, s->owner[nb], s->own[i]);
            if (h < best_hops || (h == best_hops && s->own[i] < s->own[best])) best = i, best_hops = h;
        }
        s->inflow[best] += in;
        total += in;
    }
    for (int i = 0; i < k; i++) share[i] = total > 0 ? w * s->inflow[i] / total : w / k;
}

/* The hottest cell node b holds that is not done (b's largest predicted share), or -1. */
static long hottest_cell(const replicate_state *s, int32_t b)
{
    long best = -1;
    double best_share = 0;
    for (uint32_t c = 0; c < (uint32_t)s->pilot->cells; c++) {
        if (s->done[c] || !holds(s, c, b)) continue;
        int k = owners_of(s, c);
        owner_shares(s, c, k, s->cur);
        double share = 0;
        for (int i = 0; i < k; i++)
            if (s->own[i] == b) share = s->cur[i];
        if (share > best_share) {
            best = (long)c;
            best_share = share;
        }
    }
    return best;
}

/* The busiest load among c's k owners and candidate m (s->own[k]) with m as an owner too. */
static double load_with(replicate_state *s, uint32_t c, int k)
{
    owner_shares(s, c, k + 1, s->next);
    double most = 0;
    for (int i = 0; i <= k; i++) {
        double before = i < k ? s->cur[i] : 0;
        most = fmax(most, s->load[s->own[i]] - before + s->next[i]);
    }
    return most;
}

/* The node whose copy of c leaves the least busiest load among the cell's owners and that has
 * room for it, or -1; *after is that load. s->own holds c's k owners. */
static int32_t best_new_owner(replicate_state *s, uint32_t c, int k, double *after, double *bytes)
{
    int32_t best = -1;
    owner_shares(s, c, k, s->cur);
    for (int32_t n = 0; n < s->nodes; n++) {
        if (holds(s, c, n)) continue;
        s->own[k] = n;
        double most = load_with(s, c, k);
        if (best >= 0 && most >= *after) continue;
        double b = copy_bytes(s, c, n);
        if (b > s->room[n]) continue;
        best = n;
        *after = most;
        *bytes = b;
    }
    return best;
}

/* Adds node m as an owner of c: the owners' loads by their shares, m's room and marks. */
static int add_owner(replicate_state *s, uint32_t c, int32_t m, double bytes)
{
    if (s->pairs == s->pair_cap) {
        size_t cap = s->pair_cap ? 2 * s->pair_cap : 256;
        int32_t *node = realloc(s->pair_node, cap * sizeof *node);
        if (node) s->pair_node = node;
        int32_t *next = realloc(s->pair_next, cap * sizeof *next);
        if (next) s->pair_next = next;
        if (!node || !next) return 0;
        s->pair_cap = cap;
    }
    int k = owners_of(s, c);
    owner_shares(s, c, k, s->cur);
    s->own[k] = m;
    owner_shares(s, c, k + 1, s->next);
    for (int i = 0; i < k; i++) s->load[s->own[i]] += s->next[i] - s->cur[i];
    s->load[m] += s->next[k];
    s->room[m] -= bytes;
    s->pair_node[s->pairs] = m;
    s->pair_next[s->pairs] = s->head[c];
    s->head[c] = (int32_t)s->pairs++;
    s->owners[c]++;
    hold_cell(s, c, m);
    return 1;
}

/* One greedy round: a copy of the busiest node's hottest cell that lowers it. 0: none does. */
static int replicate_once(replicate_state *s, int *nomem)
{
    int32_t b = 0;
    for (int32_t n = 1; n < s->nodes; n++)
        if (s->load[n] > s->load[b]) b = n;
    for (;;) {
        long cell = hottest_cell(s, b);
        if (cell < 0) return 0;
        uint32_t c = (uint32_t)cell;
        int k = owners_of(s, c);
        double after = 0, bytes = 0;
        int32_t m = k < s->nodes ? best_new_owner(s, c, k, &after, &bytes) : -1;
        /* The copy must leave every owner of the cell, the new one too, below b's load now. */
        if (m < 0 || after >= s->load[b]) {
            s->done[c] = 1;
            continue;
        }
        if (!add_owner(s, c, m, bytes)) {
            *nomem = 1;
            return 0;
        }
        return 1;
    }
}

static void state_free(replicate_state *s)
{
    free(s->load);
    free(s->room);
    free(s->owners);
    free(s->head);
    free(s->pair_node);
    free(s->pair_next);
    free(s->held_obj);
    free(s->held_mat);
    free(s->done);
    free(s->own);
    free(s->inflow);
    free(s->cur);
    free(s->next);
}

/* Loads, budgets and marks of the mapping without copies. */
static rt_status state_init(replicate_state *s, double fraction)
{
    size_t cells = s->pilot->cells, nodes = (size_t)s->nodes;
    uint64_t obj_bits = (uint64_t)nodes * s->scene->object_count, mat_bits = (uint64_t)nodes * s->scene->material_count;
    if (obj_bits > MARK_BITS_MAX || mat_bits > MARK_BITS_MAX) return RT_ERR_LIMIT;
    s->load = calloc(nodes, sizeof *s->load);
    s->room = calloc(nodes, sizeof *s->room);
    s->owners = malloc(cells * sizeof *s->owners);
    s->head = malloc(cells * sizeof *s->head);
    s->held_obj = calloc((size_t)(obj_bits / 8 + 1), 1);
    s->held_mat = calloc((size_t)(mat_bits / 8 + 1), 1);
    s->done = calloc(cells, 1);
    s->own = malloc((nodes + 1) * sizeof *s->own);
    s->inflow = malloc((nodes + 1) * sizeof *s->inflow);
    s->cur = malloc((nodes + 1) * sizeof *s->cur);
    s->next = malloc((nodes + 1) * sizeof *s->next);
    rt_memory_use *use = calloc(nodes, sizeof *use);
    rt_status st = RT_ERR_NOMEM;
    if (s->load && s->room && s->owners && s->head && s->held_obj && s->held_mat && s->done && s->own && s->inflow &&
        s->cur && s->next && use)
        st = rt_memory_per_owner_layout(s->scene, s->grid, s->owner, s->nodes, &s->layout, use);
    for (size_t n = 0; st == RT_OK && n < nodes; n++) s->room[n] = fraction * (double)rt_memory_total(&use[n]);
    for (uint32_t c = 0; st == RT_OK && c < (uint32_t)cells; c++) {
        s->owners[c] = 1;
        s->head[c] = -1;
        s->load[s->owner[c]] += s->pilot->work_us[c];
        hold_cell(s, c, s->owner[c]);
    }
    free(use);
    return st;
}

/* The pairs as the table of rt_replicas.h: per cell, its extra owners ascending. */
static rt_status write_table(const replicate_state *s, uint32_t *first, int32_t **extra, size_t *extra_count)
{
    size_t cells = s->pilot->cells;
    *extra = malloc((s->pairs ? s->pairs : 1) * sizeof **extra);
    if (!*extra) return RT_ERR_NOMEM;
    first[0] = 0;
    for (uint32_t c = 0; c < (uint32_t)cells; c++) {
        uint32_t at = first[c], n = 0;
        for (int32_t p = s->head[c]; p >= 0; p = s->pair_next[p]) {
            int32_t v = s->pair_node[p];
            uint32_t i = n++;
            while (i > 0 && (*extra)[at + i - 1] > v) { /* insertion: ascending */
                (*extra)[at + i] = (*extra)[at + i - 1];
                i--;
            }
            (*extra)[at + i] = v;
        }
        first[c + 1] = at + n;
    }
    *extra_count = s->pairs;
    return RT_OK;
}

rt_status rt_cost_replicate(const rt_cost_pilot *pilot, const rt_scene *scene, const rt_grid *grid,
                            const rt_topology *topo, rt_replica_rule rule, const int32_t *owner, double fraction,
                            const rt_memory_layout *layout, uint32_t *first, int32_t **extra, size_t *extra_count,
                            rt_cost_map_facts *facts, char *msg, size_t msg_len)
{
    *extra = NULL;
    *extra_count = 0;
    int nodes = topo ? topo->nodes : 0;
    if (nodes < 1 || !(fraction >= 0) || pilot->cells != rt_grid_cell_count(grid)) {
        if (msg && msg_len) snprintf(msg, msg_len, "cost replication: bad arguments");
        return RT_ERR_INVALID;
    }
    replicate_state s;
    memset(&s, 0, sizeof s);
    s.pilot = pilot;
    s.scene = scene;
    s.grid = grid;
    s.owner = owner;
    s.nodes = nodes;
    s.topo = topo;
    s.rule = rule;
    s.layout = layout ? *layout : rt_memory_layout_default();
    rt_status st = state_init(&s, fraction);
    int nomem = 0;
    while (st == RT_OK && fraction > 0 && replicate_once(&s, &nomem)) {}
    if (st == RT_OK && nomem) st = RT_ERR_NOMEM;
    if (st == RT_OK) st = write_table(&s, first, extra, extra_count);
    if (st == RT_OK && facts) {
        facts->max_node_work_us = 0;
        for (int n = 0; n < nodes; n++) facts->max_node_work_us = fmax(facts->max_node_work_us, s.load[n]);
    }
    if (st == RT_ERR_LIMIT && msg && msg_len)
        snprintf(msg, msg_len, "cost replication: %d nodes x %zu objects is too many to track", nodes,
                 scene->object_count);
    else if (st != RT_OK && msg && msg_len) snprintf(msg, msg_len, "cost replication: out of memory");
    state_free(&s);
    return st;
}
