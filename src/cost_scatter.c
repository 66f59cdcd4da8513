/* cost_scatter.c - the pilot's cells dealt to the least loaded node, hottest first, with the
 * hottest cells cut into pieces on several nodes within a memory budget (rt_cost_map_scatter in
 * rt_cost_map.h). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cost_internal.h"
#include "rt_cost_map.h"

/* One piece of a cell's work: the whole cell, or 1/k of it when the cell is cut into k. */
typedef struct piece {
    double us;
    uint32_t cell;
    uint32_t index; /* 0: the cell's primary piece */
} piece;

uint64_t rt_cost_scatter_bytes(size_t cells)
{
    /* want, pieces, their owners, start and count (rt_cost_map_scatter), and `first` */
    return (uint64_t)(cells + 1) *
           (sizeof(uint32_t) + sizeof(piece) + sizeof(int32_t) + sizeof(size_t) + sizeof(uint32_t) + sizeof(uint32_t));
}

/* The nodes as a binary min-heap by (load, pieces held, node number). */
typedef struct node_heap {
    int32_t *at;  /* heap order */
    double *load; /* per node */
    uint32_t *held;
    int size;
} node_heap;

static int lighter(const node_heap *h, int32_t a, int32_t b)
{
    if (h->load[a] != h->load[b]) return h->load[a] < h->load[b];
    if (h->held[a] != h->held[b]) return h->held[a] < h->held[b];
    return a < b;
}

static void sift_down(node_heap *h, int i)
{
    for (;;) {
        int l = 2 * i + 1, r = l + 1, m = i;
        if (l < h->size && lighter(h, h->at[l], h->at[m])) m = l;
        if (r < h->size && lighter(h, h->at[r], h->at[m])) m = r;
        if (m == i) return;
        int32_t t = h->at[i];
        h->at[i] = h->at[m];
        h->at[m] = t;
        i = m;
    }
}

static void sift_up(node_heap *h, int i)
{
    while (i > 0) {
        int parent = (i - 1) / 2;
        if (!lighter(h, h->at[i], h->at[parent])) return;
        int32_t t = h->at[i];
        h->at[i] = h->at[parent];
        h->at[parent] = t;
        i = parent;
    }
}

static int32_t heap_pop(node_heap *h)
{
    int32_t top = h->at[0];
    h->at[0] = h->at[--h->size];
    sift_down(h, 0);
    return top;
}

static void heap_push(node_heap *h, int32_t v)
{
    h->at[h->size++] = v;
    sift_up(h, h->size - 1);
}

/* Hottest first; equal work in cell order, a cell's pieces in order. */
static int hotter(const void *a, const void *b)
{
    const piece *x = a, *y = b;
    if (x->us != y->us) return x->us > y->us ? -1 : 1;
    if (x->cell != y->cell) return x->cell < y->cell ? -1 : 1;
    return x->index < y->index ? -1 : x->index > y->index;
}

/* Pieces of cell c: 1, or ceil(work / (mean / 2)) (at most `nodes`) when cutting. */
static uint32_t pieces_of(double work_us, double mean_us, int nodes, int cut)
{
    if (!cut || !(work_us > 0.5 * mean_us)) return 1;
    double k = ceil(work_us / (0.5 * mean_us));
    return k >= nodes ? (uint32_t)nodes : (uint32_t)k;
}

typedef struct deal {
    int32_t *owners; /* per cell, from start[c]: its owners, the primary first */
    size_t *start;   /* per cell: its first slot in owners (as many slots as its first cut) */
    uint32_t *count; /* per cell: owners so far */
} deal;

static int cell_holds(const deal *d, uint32_t c, int32_t v)
{
    for (uint32_t i = 0; i < d->count[c]; i++)
        if (d->owners[d->start[c] + i] == v) return 1;
    return 0;
}

/* Deals the pieces, each to the lightest node that does not hold its cell yet. */
static rt_status deal_pieces(const piece *pieces, size_t n_pieces, int nodes, deal *d, double *load)
{
    node_heap h = {malloc((size_t)nodes * sizeof(int32_t)), load, calloc((size_t)nodes, sizeof(uint32_t)), 0};
    int32_t *aside = malloc((size_t)nodes * sizeof *aside);
    if (!h.at || !h.held || !aside) {
        free(h.at);
        free(h.held);
        free(aside);
        return RT_ERR_NOMEM;
    }
    for (int32_t v = 0; v < nodes; v++) heap_push(&h, v);
    for (size_t i = 0; i < n_pieces; i++) {
        const piece *p = &pieces[i];
        int set_aside = 0;
        int32_t v = heap_pop(&h);
        while (cell_holds(d, p->cell, v)) { /* a cell has at most `nodes` pieces: one is free */
            aside[set_aside++] = v;
            v = heap_pop(&h);
        }
        d->owners[d->start[p->cell] + d->count[p->cell]++] = v;
        load[v] += p->us;
        h.held[v]++;
        heap_push(&h, v);
        while (set_aside > 0) heap_push(&h, aside[--set_aside]);
    }
    free(h.at);
    free(h.held);
    free(aside);
    return RT_OK;
}

static int ascending(const void *a, const void *b)
{
    int32_t x = *(const int32_t *)a, y = *(const int32_t *)b;
    return x < y ? -1 : x > y;
}

/* The replica table of rt_replicas.h from the deal (owner[] = each cell's primary). */
static rt_status write_table(const deal *d, size_t cells, int32_t *owner, uint32_t *first, int32_t **extra,
                             size_t *extra_count)
{
    size_t total = 0;
    for (size_t c = 0; c < cells; c++) total += d->count[c] - 1;
    *extra = malloc((total ? total : 1) * sizeof **extra);
    if (!*extra) return RT_ERR_NOMEM;
    first[0] = 0;
    for (size_t c = 0; c < cells; c++) {
        const int32_t *own = &d->owners[d->start[c]];
        owner[c] = own[0];
        uint32_t n = d->count[c] - 1;
        memcpy(*extra + first[c], own + 1, n * sizeof **extra);
        qsort(*extra + first[c], n, sizeof **extra, ascending);
        first[c + 1] = first[c] + n;
    }
    *extra_count = total;
    return RT_OK;
}

/* Node v's data beyond its primary cells, against its budget; 1 if over. */
static int over_budget(const rt_memory_use *one, const rt_memory_use *with, int32_t v, double fraction)
{
    double plain = (double)rt_memory_total(&one[v]);
    return (double)rt_memory_total(&with[v]) - plain > fraction * plain;
}

/* owner[] as each cell's primary in the deal. */
static const int32_t *owner_of_deal(const deal *d, size_t cells, int32_t *owner)
{
    for (size_t c = 0; c < cells; c++) owner[c] = d->owners[d->start[c]];
    return owner;
}

/* Every node's data with the deal's copies (the table rebuilt into first / *extra). */
static rt_status count_with_copies(const rt_scene *scene, const rt_grid *grid, int nodes,
                                   const rt_memory_layout *layout, const deal *d, int32_t *owner, uint32_t *first,
                                   int32_t **extra, rt_memory_use *with)
{
    size_t count = 0;
    free(*extra);
    *extra = NULL;
    rt_status st = write_table(d, rt_grid_cell_count(grid), owner, first, extra, &count);
    rt_replicas r = {first, *extra};
    if (st == RT_OK) st = rt_memory_per_owner_replicas(scene, grid, owner, count ? &r : NULL, nodes, layout, with);
    return st;
}

/* Every node over budget drops its smallest copy (ties: the lowest cell); *dropped says whether
 * any was (the caller deals the pieces again, the cell cut that much less). */
static rt_status fit_budget(const rt_scene *scene, const rt_grid *grid, const rt_cost_pilot *pilot, int nodes,
                            double fraction, const rt_memory_layout *layout, deal *d, int32_t *owner, int *dropped)
{
    *dropped = 0;
    size_t cells = pilot->cells;
    rt_memory_use *one = calloc((size_t)nodes, sizeof *one), *with = calloc((size_t)nodes, sizeof *with);
    uint32_t *first = malloc((cells + 1) * sizeof *first);
    int32_t *extra = NULL;
    rt_status st = one && with && first ? RT_OK : RT_ERR_NOMEM;
    if (st == RT_OK) st = rt_memory_per_owner_layout(scene, grid, owner_of_deal(d, cells, owner), nodes, layout, one);
    if (st == RT_OK) st = count_with_copies(scene, grid, nodes, layout, d, owner, first, &extra, with);
    /* Each node's smallest copy (per cell and owner slot, one pass over the table). */
    long *pick = malloc((size_t)nodes * sizeof *pick);
    if (st == RT_OK && !pick) st = RT_ERR_NOMEM;
    for (int32_t v = 0; st == RT_OK && v < nodes; v++) pick[v] = -1;
    for (size_t c = 0; st == RT_OK && c < cells; c++)
        for (uint32_t i = 1; i < d->count[c]; i++) {
            int32_t v = d->owners[d->start[c] + i];
            if (pick[v] < 0 || pilot->work_us[c] / d->count[c] < pilot->work_us[pick[v]] / d->count[pick[v]])
                pick[v] = (long)c;
        }
    for (int32_t v = 0; st == RT_OK && v < nodes; v++) {
        if (pick[v] < 0 || !over_budget(one, with, v, fraction)) continue; /* the budget is about copies */
        size_t c = (size_t)pick[v];
        int32_t *own = &d->owners[d->start[c]];
        uint32_t slot = 1;
        while (own[slot] != v) slot++;
        memmove(own + slot, own + slot + 1, (d->count[c] - slot - 1) * sizeof *own);
        d->count[c]--;
        *dropped = 1;
    }
    free(pick);
    free(extra);
    free(first);
    free(one);
    free(with);
    return st;
}

rt_status rt_cost_map_scatter(const rt_cost_pilot *pilot, const rt_scene *scene, const rt_grid *grid,
                              const rt_topology *topo, double fraction, const rt_memory_layout *layout, int32_t *owner,
                              uint32_t *first, int32_t **extra, size_t *extra_count, rt_cost_map_facts *facts,
                              char *msg, size_t msg_len)
{
    *extra = NULL;
    *extra_count = 0;
    long n_long = topo ? topo->nodes : 0;
    if (n_long < 1 || !pilot->work_us || !(fraction >= 0) || pilot->cells != rt_grid_cell_count(grid)) {
        if (msg && msg_len) snprintf(msg, msg_len, "scatter mapping: bad arguments");
        return RT_ERR_INVALID;
    }
    int nodes = (int)n_long;
    size_t cells = pilot->cells, n_pieces = 0;
    double mean = pilot->total_us / nodes;
    int any_cut = 0;
    uint32_t *want = malloc((cells ? cells : 1) * sizeof *want); /* pieces per cell */
    for (size_t c = 0; want && c < cells; c++) {
        want[c] = pieces_of(pilot->work_us[c], mean, nodes, fraction > 0);
        n_pieces += want[c];
        any_cut |= want[c] > 1;
    }
    piece *pieces = malloc((n_pieces ? n_pieces : 1) * sizeof *pieces);
    deal d = {malloc((n_pieces ? n_pieces : 1) * sizeof(int32_t)), malloc((cells ? cells : 1) * sizeof(size_t)),
              calloc(cells ? cells : 1, sizeof(uint32_t))};
    for (size_t c = 0, at = 0; want && d.start && c < cells; at += want[c], c++) d.start[c] = at;
    double *load = calloc((size_t)nodes, sizeof *load);
    rt_memory_layout lay = layout ? *layout : rt_memory_layout_default();
    rt_status st = want && pieces && d.owners && d.start && d.count && load ? RT_OK : RT_ERR_NOMEM;
    /* Deal, fit the budget; a dropped copy changes the pieces, so deal those again until none is
     * dropped (each round drops one at least, so it ends). */
    for (int dropped = 1; st == RT_OK && dropped;) {
        size_t i = 0;
        for (size_t c = 0; c < cells; c++)
            for (uint32_t j = 0; j < want[c]; j++) pieces[i++] = (piece){pilot->work_us[c] / want[c], (uint32_t)c, j};
        memset(d.count, 0, cells * sizeof *d.count);
        memset(load, 0, (size_t)nodes * sizeof *load);
        qsort(pieces, i, sizeof *pieces, hotter);
        st = deal_pieces(pieces, i, nodes, &d, load);
        dropped = 0;
        if (st == RT_OK && any_cut) st = fit_budget(scene, grid, pilot, nodes, fraction, &lay, &d, owner, &dropped);
        for (size_t c = 0; c < cells; c++) want[c] = d.count[c];
    }
    if (st == RT_OK) st = write_table(&d, cells, owner, first, extra, extra_count);
    if (st == RT_OK && facts) {
        rt_cost_map_facts_of(pilot, topo, owner, facts);
        memset(load, 0, (size_t)nodes * sizeof *load); /* the table's loads, copies dropped included */
        for (size_t c = 0; c < cells; c++)
            for (uint32_t i = 0; i < d.count[c]; i++) load[d.owners[d.start[c] + i]] += pilot->work_us[c] / d.count[c];
        facts->max_node_work_us = 0;
        for (int v = 0; v < nodes; v++) facts->max_node_work_us = fmax(facts->max_node_work_us, load[v]);
    }
    if (st != RT_OK) {
        free(*extra);
        *extra = NULL;
        *extra_count = 0;
        if (msg && msg_len) snprintf(msg, msg_len, "scatter mapping: out of memory");
    }
    free(want);
    free(pieces);
    free(d.owners);
    free(d.start);
    free(d.count);
    free(load);
    return st;
}
