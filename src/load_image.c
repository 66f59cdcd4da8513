/* load_image.c - the cost image (per pixel) and the load map (per cell and owner). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "rt_canvas.h"
#include "rt_load_image.h"
#include "rt_load_map.h"
#include "rt_png.h"

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

/* The cost image's pixel scale: small images are enlarged. */
static uint32_t cost_image_scale(uint32_t h) { return h < 256 ? (256 + h - 1) / h : 1; }

uint64_t rt_cost_image_canvas_bytes(uint32_t w, uint32_t h)
{
    uint32_t s = cost_image_scale(h);
    uint64_t height = (uint64_t)h * s > 120 ? (uint64_t)h * s : 120;
    return ((uint64_t)w * s + 150) * height * 3;
}

rt_status rt_cost_image_write(FILE *fp, const char *name, uint32_t w, uint32_t h, const double *cost, char *msg,
                              size_t msg_len)
{
    int s = (int)cost_image_scale(h);
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

rt_status rt_load_map_write(FILE *fp, const char *name, const int d[3], const double *work, const int32_t *owner,
                            int nodes, char *msg, size_t msg_len)
{
    return finish(rt_load_map_draw(d, work, owner, nodes), fp, name, msg, msg_len);
}

rt_status rt_load_map_write_replicas(FILE *fp, const char *name, const int d[3], const double *work,
                                     const int32_t *owner, const rt_replicas *replicas, int nodes, const char *caption,
                                     char *msg, size_t msg_len)
{
    return finish(rt_load_map_draw_replicas(d, work, owner, replicas, nodes, caption), fp, name, msg, msg_len);
}
