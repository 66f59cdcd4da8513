/* cost_pilot.c - per-cell work and per-face traffic from a pilot run of the renderer. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "rt_cost_map.h"
#include "rt_framebuffer.h"
#include "rt_render.h"

typedef struct pilot_ctx {
    rt_cost_pilot *pilot;
    const rt_timing *timing;
} pilot_ctx;

/* Face of `from` that leads to the neighbouring cell `to` (-1 if not a neighbour). */
static int face_between(const int dims[3], uint32_t from, uint32_t to)
{
    int a[3] = {(int)(from % (uint32_t)dims[0]), (int)(from / (uint32_t)dims[0] % (uint32_t)dims[1]),
                (int)(from / ((uint32_t)dims[0] * (uint32_t)dims[1]))};
    int b[3] = {(int)(to % (uint32_t)dims[0]), (int)(to / (uint32_t)dims[0] % (uint32_t)dims[1]),
                (int)(to / ((uint32_t)dims[0] * (uint32_t)dims[1]))};
    for (int k = 0; k < 3; k++) {
        int d = b[k] - a[k];
        if (d == 0) continue;
        for (int j = 0; j < 3; j++)
            if (j != k && a[j] != b[j]) return -1;
        return d == -1 ? 2 * k : d == 1 ? 2 * k + 1 : -1;
    }
    return -1;
}

static void on_step(void *vctx, uint32_t cell, const rt_packet *packet, const rt_step_result *r)
{
    (void)packet;
    pilot_ctx *ctx = vctx;
    rt_op_counts work = r->ops;
    work.handovers_sent = work.handovers_received = 0; /* the mapping decides those */
    ctx->pilot->work_us[cell] += rt_timing_step_us(ctx->timing, &work);
    if (r->fate == RT_FATE_FORWARDED) {
        int f = face_between(ctx->pilot->dims, cell, r->next_cell);
        if (f >= 0) ctx->pilot->traffic[(size_t)cell * RT_CELL_FACES + (size_t)f]++;
    }
}

rt_status rt_cost_pilot_run(const rt_scene *scene, const rt_grid *grid, const rt_step_params *params,
                            const rt_timing *timing, rt_cost_pilot *out, char *msg, size_t msg_len)
{
    memset(out, 0, sizeof *out);
    rt_grid_dims(grid, out->dims);
    out->cells = rt_grid_cell_count(grid);
    out->work_us = calloc(out->cells, sizeof *out->work_us);
    out->traffic = calloc(out->cells * RT_CELL_FACES, sizeof *out->traffic);
    int32_t *self = malloc(out->cells * sizeof *self);
    const rt_camera *cam = rt_scene_camera(scene);
    rt_framebuffer *fb = rt_framebuffer_new(cam->width, cam->height);
    rt_status st = RT_ERR_NOMEM;
    if (out->work_us && out->traffic && self && fb) {
        for (size_t c = 0; c < out->cells; c++) self[c] = (int32_t)c; /* every cell its own owner */
        rt_render_options o = rt_render_options_default();
        o.step = *params;
        o.step.brute_force = 0;
        o.cell_owner = self;
        pilot_ctx ctx = {out, timing};
        o.on_step = on_step;
        o.on_step_ctx = &ctx;
        rt_render_stats stats;
        st = rt_render(scene, grid, &o, fb, &stats, msg, msg_len);
        out->ops = stats.ops;
    } else if (msg && msg_len) {
        snprintf(msg, msg_len, "out of memory for the pilot run (%zu cells)", out->cells);
    }
    for (size_t c = 0; st == RT_OK && c < out->cells; c++) out->total_us += out->work_us[c];
    free(self);
    rt_framebuffer_free(fb);
    if (st != RT_OK) rt_cost_pilot_release(out);
    return st;
}

void rt_cost_pilot_release(rt_cost_pilot *p)
{
    free(p->work_us);
    free(p->traffic);
    memset(p, 0, sizeof *p);
}

double rt_cost_edge_us(const rt_timing *t)
{
    return t->handover_send_us + t->handover_receive_us + rt_timing_link_packet_us(t);
}
