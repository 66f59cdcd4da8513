/* load_map.c - the load map: the cells' work, the owners of a slice, and the work per node. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "rt_load_map.h"

static const uint8_t black[3] = {0, 0, 0}, grey[3] = {160, 160, 160}, red[3] = {220, 0, 0};

typedef struct {
    double work;
    int node;
} node_load;

void rt_node_work(const int d[3], const double *work, const int32_t *owner, int nodes, double *node_us)
{
    rt_node_work_replicas(d, work, owner, NULL, nodes, node_us);
}

void rt_node_work_replicas(const int d[3], const double *work, const int32_t *owner, const rt_replicas *replicas,
                           int nodes, double *node_us)
{
    for (int n = 0; n < nodes; n++) node_us[n] = 0;
    size_t cells = (size_t)d[0] * d[1] * d[2];
    for (uint32_t i = 0; i < (uint32_t)cells; i++) {
        uint32_t extras = rt_replicas_extra_count(replicas, i);
        double share = work[i] / (extras + 1);
        if (owner[i] >= 0 && owner[i] < nodes) node_us[owner[i]] += share;
        for (uint32_t k = 0; k < extras; k++) {
            int32_t o = replicas->extra[replicas->first[i] + k];
            if (o >= 0 && o < nodes) node_us[o] += share;
        }
    }
}

/* The replica mark: a white diagonal with a black edge, top left to bottom right of a cell. */
static void mark_replicated(rt_canvas *c, int x, int y, int s)
{
    const uint8_t white[3] = {255, 255, 255};
    for (int k = 0; k < s; k++) {
        rt_canvas_rect(c, x + k, y + k, 1, 1, white);
        if (k + 1 < s) rt_canvas_rect(c, x + k + 1, y + k, 1, 1, black);
    }
}

/* 1 if any cell of column (x, y) has an extra owner. */
static int column_replicated(const int d[3], const rt_replicas *replicas, int x, int y)
{
    for (int z = 0; replicas && z < d[2]; z++)
        if (rt_replicas_extra_count(replicas, (uint32_t)(x + d[0] * (y + (size_t)d[1] * z)))) return 1;
    return 0;
}

static int busiest_first(const void *a, const void *b)
{
    const node_load *x = a, *y = b;
    if (x->work != y->work) return x->work < y->work ? 1 : -1;
    return x->node - y->node;
}

/* Panel 1: the work summed along z over x (right) and y (down), with its colour bar. */
static void draw_cells(rt_canvas *c, const int d[3], const double *work, const rt_replicas *replicas, int x0, int y0,
                       int s, double *plane)
{
    double hi = 0;
    for (int i = 0; i < d[0] * d[1]; i++) plane[i] = 0;
    for (int z = 0; z < d[2]; z++)
        for (int i = 0; i < d[0] * d[1]; i++) plane[i] += work[i + (size_t)d[0] * d[1] * z];
    for (int i = 0; i < d[0] * d[1]; i++) hi = fmax(hi, plane[i]);
    uint8_t col[3];
    for (int y = 0; y < d[1]; y++)
        for (int x = 0; x < d[0]; x++) {
            rt_heat_colour(hi > 0 ? plane[x + d[0] * y] / hi : 0, col);
            rt_canvas_rect(c, x0 + x * s, y0 + y * s, s, s, col);
            if (column_replicated(d, replicas, x, y)) mark_replicated(c, x0 + x * s, y0 + y * s, s);
        }
    rt_canvas_text(c, x0, y0 - 14, 2, "work per cell, sum over z", black);
    if (replicas) rt_canvas_text(c, x0, y0 - 22, 1, "white diagonal: a column holding a replicated cell", black);
    rt_canvas_heat_bar(c, x0 + d[0] * s + 8, y0, 14, d[1] * s, 0.0, hi, "us");
}

/* The cell axes under and left of a d[0] x d[1] panel at (x0, y0). */
static void draw_axes(rt_canvas *c, const int d[3], int x0, int y0, int s)
{
    char label[32];
    int below = y0 + d[1] * s + 3;
    rt_canvas_text(c, x0, below, 1, "0", black);
    snprintf(label, sizeof label, "%d", d[0] - 1);
    rt_canvas_text(c, x0 + d[0] * s - 4 * (int)snprintf(NULL, 0, "%d", d[0] - 1), below, 1, label, black);
    rt_canvas_text(c, x0 + d[0] * s / 2 - 12, below, 1, "x ->", black);
    rt_canvas_text(c, x0 - 8, y0, 1, "0", black);
    snprintf(label, sizeof label, "%d", d[1] - 1);
    rt_canvas_text(c, x0 - 4 * (int)snprintf(NULL, 0, "%d", d[1] - 1) - 4, y0 + d[1] * s - 5, 1, label, black);
    rt_canvas_text(c, x0 - 8, y0 + d[1] * s / 2 - 2, 1, "y", black);
}

/* Panel 2: the owners of slice z, a line between cells of different owners, numbers that fit. */
static void draw_owners(rt_canvas *c, const int d[3], const int32_t *owner, const rt_replicas *replicas, int z, int x0,
                        int y0, int s)
{
    uint8_t col[3];
    char label[32];
    const int32_t *slice = owner + (size_t)d[0] * d[1] * z;
    for (int y = 0; y < d[1]; y++)
        for (int x = 0; x < d[0]; x++) {
            int32_t o = slice[x + d[0] * y];
            rt_node_colour(o, col);
            rt_canvas_rect(c, x0 + x * s, y0 + y * s, s, s, col);
            int len = snprintf(label, sizeof label, "%d", (int)o);
            if (4 * len - 1 <= s - 2 && s >= 8) {
                int light = col[0] * 3 + col[1] * 6 + col[2] > 1200;
                const uint8_t white[3] = {255, 255, 255};
                rt_canvas_text(c, x0 + x * s + (s - 4 * len + 1) / 2, y0 + y * s + (s - 5) / 2, 1, label,
                               light ? black : white);
            }
        }
    for (int y = 0; y < d[1]; y++)
        for (int x = 0; x < d[0]; x++) {
            int32_t o = slice[x + d[0] * y];
            if (x + 1 < d[0] && slice[x + 1 + d[0] * y] != o)
                rt_canvas_rect(c, x0 + (x + 1) * s - 1, y0 + y * s, 2, s, black);
            if (y + 1 < d[1] && slice[x + d[0] * (y + 1)] != o)
                rt_canvas_rect(c, x0 + x * s, y0 + (y + 1) * s - 1, s, 2, black);
            if (rt_replicas_extra_count(replicas, (uint32_t)(x + d[0] * (y + (size_t)d[1] * z))))
                mark_replicated(c, x0 + x * s, y0 + y * s, s);
        }
    snprintf(label, sizeof label, "owners of slice z=%d", z);
    if (replicas) rt_canvas_text(c, x0, y0 - 22, 1, "white diagonal: a replicated cell", black);
    rt_canvas_text(c, x0, y0 - 14, 2, label, black);
}

/* Panel 3: work per node, busiest first, one bar per node in its colour, the mean as a line;
 * the bars take 5/6 of the height, the busiest's label the rest, the mean's label the right. */
static void draw_nodes(rt_canvas *c, const node_load *load, int nodes, int x0, int y0, int w, int h)
{
    double hi = nodes > 0 ? load[0].work : 0, sum = 0;
    for (int n = 0; n < nodes; n++) sum += load[n].work;
    double mean = nodes > 0 ? sum / nodes : 0, scale = hi > 0 ? h * 5.0 / 6.0 / hi : 0;
    char label[96], t1[32], t2[32];
    snprintf(label, sizeof label, "work per node, busiest first (%d nodes)", nodes);
    rt_canvas_text(c, x0, y0 - 14, 2, label, black);
    rt_canvas_rect(c, x0 - 1, y0, 1, h + 1, black);
    rt_canvas_rect(c, x0 - 1, y0 + h, w + 1, 1, black);
    uint8_t col[3];
    for (int px = 0; px < w && nodes > 0; px++) { /* the busiest node of each pixel column */
        int n = (int)((long long)px * nodes / w);
        int bar = (int)lround(load[n].work * scale);
        rt_node_colour(load[n].node, col);
        int edge = nodes <= w / 3 && (int)((long long)(px + 1) * nodes / w) != n; /* a gap between wide bars */
        rt_canvas_rect(c, x0 + px, y0 + h - bar, 1, bar, edge ? grey : col);
    }
    int my = y0 + h - (int)lround(mean * scale), ty = y0 + h - (int)lround(hi * scale);
    for (int px = 0; px < w; px += 6) rt_canvas_rect(c, x0 + px, my, 4, 2, red);
    rt_time_label(mean, t1, sizeof t1);
    snprintf(label, sizeof label, "mean %s", t1);
    rt_canvas_text(c, x0 + w + 6, my - 4, 2, label, red);
    for (int q = 1; q <= 3 && hi > 0; q++) { /* the quarters of the busiest, marked and labelled */
        int qy = y0 + h - (int)lround(hi * q / 4 * scale);
        rt_canvas_rect(c, x0 - 4, qy, 3, 1, black);
        rt_time_label(hi * q / 4, t1, sizeof t1);
        rt_canvas_text(c, x0 - 4 * (int)strlen(t1) - 6, qy - 2, 1, t1, black);
    }
    rt_time_label(hi, t1, sizeof t1);
    snprintf(t2, sizeof t2, "%.3f", mean > 0 ? hi / mean : 0);
    snprintf(label, sizeof label, "busiest: node %d, %s = %s x mean", nodes > 0 ? load[0].node : 0, t1, t2);
    rt_canvas_text(c, x0 + 4, ty - 13, 2, label, black);
    rt_canvas_rect(c, x0 - 4, ty, 3, 1, black);
    rt_canvas_text(c, x0 - 4 * (int)strlen(t1) - 6, ty - 2, 1, t1, black);
    rt_canvas_text(c, x0 - 8, y0 + h - 5, 1, "0", black);
    rt_canvas_text(c, x0, y0 + h + 4, 1, "nodes, busiest first ->", black);
}

rt_canvas *rt_load_map_draw(const int d[3], const double *work, const int32_t *owner, int nodes)
{
    return rt_load_map_draw_replicas(d, work, owner, NULL, nodes, NULL);
}

rt_canvas *rt_load_map_draw_replicas(const int d[3], const double *work, const int32_t *owner,
                                     const rt_replicas *replicas, int nodes, const char *caption)
{
    size_t cells = (size_t)d[0] * d[1] * d[2];
    int big = d[0] > d[1] ? d[0] : d[1];
    if (cells == 0 || nodes < 1) return NULL;
    int s = 240 / big;
    s = s < 2 ? 2 : s > 16 ? 16 : s;
    int left = 56, top = caption ? 44 : 24, bar_w = 110, chart_h = 160;
    int x2 = left + d[0] * s + bar_w;
    uint32_t width = (uint32_t)(x2 + d[0] * s + 24), chart_y = (uint32_t)(top + d[1] * s + 44);
    double *plane = malloc(sizeof(double) * (size_t)d[0] * d[1]);
    double *node_us = malloc(sizeof(double) * (size_t)nodes);
    node_load *load = malloc(sizeof(node_load) * (size_t)nodes);
    rt_canvas *c = plane && node_us && load ? rt_canvas_new(width, chart_y + (uint32_t)chart_h + 20) : NULL;
    if (c) {
        rt_node_work_replicas(d, work, owner, replicas, nodes, node_us);
        for (int n = 0; n < nodes; n++) load[n] = (node_load){node_us[n], n};
        qsort(load, (size_t)nodes, sizeof *load, busiest_first);
        if (caption) rt_canvas_text(c, 4, 4, 2, caption, black);
        draw_cells(c, d, work, replicas, left, top, s, plane);
        draw_axes(c, d, left, top, s);
        draw_owners(c, d, owner, replicas, d[2] / 2, x2, top, s);
        draw_axes(c, d, x2, top, s);
        draw_nodes(c, load, nodes, left, (int)chart_y, (int)width - left - 130, chart_h);
    }
    free(plane);
    free(node_us);
    free(load);
    return c;
}
