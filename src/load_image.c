/* load_image.c - the cost image (per pixel) and the load map (per cell and owner). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "rt_canvas.h"
#include "rt_load_image.h"
#include "rt_png.h"

static const uint8_t black[3] = {0, 0, 0};

static rt_status finish(rt_canvas *c, FILE *fp, const char *name, char *msg, size_t msg_len)
{
    if (!c) {
        if (msg && msg_len) snprintf(msg, msg_len, "%s: out of memory for the picture", name);
        return RT_ERR_NOMEM;
    }
    rt_status st = rt_png_write_stream(fp, name, c->width, c->height, c->rgb, msg, msg_len);
    rt_canvas_free(c);
    return st;
}

static double max_of(const double *v, size_t n)
{
    double m = 0;
    for (size_t i = 0; i < n; i++) m = fmax(m, v[i]);
    return m;
}

rt_status rt_cost_image_write(FILE *fp, const char *name, uint32_t w, uint32_t h, const double *cost, char *msg,
                              size_t msg_len)
{
    int s = h < 256 ? (int)((256 + h - 1) / h) : 1; /* small images are enlarged */
    double hi = max_of(cost, (size_t)w * h);
    rt_canvas *c = rt_canvas_new(w * (uint32_t)s + 150, h * (uint32_t)s > 120 ? h * (uint32_t)s : 120);
    if (c) {
        uint8_t col[3];
        for (uint32_t y = 0; y < h; y++)
            for (uint32_t x = 0; x < w; x++) {
                rt_heat_colour(hi > 0 ? cost[(size_t)y * w + x] / hi : 0, col);
                rt_canvas_rect(c, (int)x * s, (int)y * s, s, s, col);
            }
        rt_canvas_heat_bar(c, (int)w * s + 10, 4, 16, (int)c->height - 8, 0.0, hi, "us");
    }
    return finish(c, fp, name, msg, msg_len);
}

/* Work summed along axis `a` into a plane of the other two axes (u fastest). */
static void project(const int d[3], const double *work, int a, double *plane)
{
    int u = a == 0 ? 1 : 0, v = a == 2 ? 1 : 2;
    for (int i = 0; i < d[u] * d[v]; i++) plane[i] = 0;
    for (int z = 0; z < d[2]; z++)
        for (int y = 0; y < d[1]; y++)
            for (int x = 0; x < d[0]; x++) {
                int p[3] = {x, y, z};
                plane[p[u] + d[u] * p[v]] += work[x + d[0] * (y + (size_t)d[1] * z)];
            }
}

/* Lays out the three projections (heat) and the owners of the middle z slice. */
static void draw_load(rt_canvas *c, const int d[3], const double *work, const int32_t *owner, int nodes, int s,
                      double *planes[3], double hi)
{
    const char *names[3] = {"sum over x", "sum over y", "sum over z"};
    int x0 = 4;
    uint8_t col[3];
    for (int a = 0; a < 3; a++) {
        int u = a == 0 ? 1 : 0, v = a == 2 ? 1 : 2;
        project(d, work, a, planes[a]);
        for (int j = 0; j < d[v]; j++)
            for (int i = 0; i < d[u]; i++) {
                rt_heat_colour(hi > 0 ? planes[a][i + d[u] * j] / hi : 0, col);
                rt_canvas_rect(c, x0 + i * s, 20 + j * s, s, s, col);
            }
        rt_canvas_text(c, x0, 4, 2, names[a], black);
        x0 += d[u] * s + 12;
    }
    rt_canvas_heat_bar(c, x0, 20, 16, (int)c->height - 60 > 40 ? (int)c->height - 60 : 40, 0.0, hi, "us");
    x0 += 120;
    int z = d[2] / 2;
    char label[32];
    snprintf(label, sizeof label, "owners z=%d", z);
    rt_canvas_text(c, x0, 4, 2, label, black);
    for (int y = 0; y < d[1]; y++)
        for (int x = 0; x < d[0]; x++) {
            rt_node_colour(owner[x + d[0] * (y + (size_t)d[1] * z)], col);
            rt_canvas_rect(c, x0 + x * s, 20 + y * s, s, s, col);
        }
    int ly = 20 + d[1] * s + 8, lx = x0; /* legend: a swatch and the number of each node */
    for (int n = 0; n < nodes && ly + 12 <= (int)c->height; n++) {
        rt_node_colour(n, col);
        rt_canvas_rect(c, lx, ly, 10, 10, col);
        snprintf(label, sizeof label, "%d", n);
        rt_canvas_text(c, lx + 12, ly, 2, label, black);
        lx += 48;
        if (lx + 48 > x0 + d[0] * s + 200) lx = x0, ly += 14;
    }
}

rt_status rt_load_map_write(FILE *fp, const char *name, const int d[3], const double *work, const int32_t *owner, int nodes,
                            char *msg, size_t msg_len)
{
    int big = d[0] > d[1] ? d[0] : d[1];
    big = big > d[2] ? big : d[2];
    int s = big < 96 ? 192 / big : 2;
    if (s < 2) s = 2;
    size_t cells = (size_t)d[0] * d[1] * d[2];
    double *planes[3] = {malloc(sizeof(double) * (size_t)d[1] * d[2]), malloc(sizeof(double) * (size_t)d[0] * d[2]),
                         malloc(sizeof(double) * (size_t)d[0] * d[1])};
    double hi = 0;
    for (int a = 0; a < 3 && planes[a]; a++) {
        project(d, work, a, planes[a]);
        int u = a == 0 ? 1 : 0, v = a == 2 ? 1 : 2;
        hi = fmax(hi, max_of(planes[a], (size_t)d[u] * d[v]));
    }
    int legend_rows = (nodes + 3) / 4;
    uint32_t width = (uint32_t)((d[1] + 3 * d[0]) * s + 4 + 36 + 120 + 210);
    uint32_t height = (uint32_t)(20 + big * s + 12 + 14 * (legend_rows < 40 ? legend_rows : 40) + 8);
    rt_canvas *c = planes[0] && planes[1] && planes[2] && cells ? rt_canvas_new(width, height) : NULL;
    if (c) draw_load(c, d, work, owner, nodes, s, planes, hi);
    for (int a = 0; a < 3; a++) free(planes[a]);
    return finish(c, fp, name, msg, msg_len);
}
