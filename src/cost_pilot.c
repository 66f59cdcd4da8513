/* cost_pilot.c - per-cell work and per-face traffic from a pilot run of the renderer. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "rt_cost_map.h"
#include "rt_framebuffer.h"
#include "rt_render.h"

/* The per-object counter: each list entry's work, and the objects the current step tested. */
typedef struct object_counter {
    size_t *first;     /* per cell: its first entry in entry_us (cells + 1) */
    double *entry_us;  /* per cell-list entry, in the grid's order */
    uint32_t *tests;   /* per object: tests in the current step */
    uint32_t *touched; /* the objects tested in the current step */
    size_t touched_count;
    uint64_t step_tests;
} object_counter;

typedef struct pilot_ctx {
    rt_cost_pilot *pilot;
    const rt_timing *timing;
    const rt_grid *grid;
    object_counter *objects; /* NULL: not counted */
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

static void on_test(void *vctx, uint32_t object)
{
    object_counter *k = vctx;
    if (k->tests[object]++ == 0) k->touched[k->touched_count++] = object;
    k->step_tests++;
}

/* The step's work beyond its next-cell determinations and cell-step packet work, shared by the
 * objects it tested. */
static void share_among_objects(pilot_ctx *ctx, uint32_t cell, const rt_op_counts *work, double step_us)
{
    object_counter *k = ctx->objects;
    double share = step_us - (double)work->dda_steps * ctx->timing->dda_step_us -
                   (double)work->cell_steps * ctx->timing->cell_step_packet_us;
    size_t n = 0;
    const uint32_t *list = rt_grid_cell_objects(ctx->grid, cell, &n);
    for (size_t t = 0; t < k->touched_count; t++) {
        uint32_t o = k->touched[t];
        for (size_t i = 0; i < n && share > 0; i++)
            if (list[i] == o) k->entry_us[k->first[cell] + i] += share * k->tests[o] / (double)k->step_tests;
        k->tests[o] = 0;
    }
    k->touched_count = 0;
    k->step_tests = 0;
}

static void on_step(void *vctx, uint32_t cell, const rt_packet *packet, const rt_step_result *r)
{
    (void)packet;
    pilot_ctx *ctx = vctx;
    rt_op_counts work = r->ops;
    work.handovers_sent = work.handovers_received = 0; /* the mapping decides those */
    double us = rt_timing_step_us(ctx->timing, &work);
    ctx->pilot->work_us[cell] += us;
    if (ctx->objects) share_among_objects(ctx, cell, &work, us);
    if (r->fate == RT_FATE_FORWARDED) {
        int f = face_between(ctx->pilot->dims, cell, r->next_cell);
        if (f >= 0) ctx->pilot->traffic[(size_t)cell * RT_CELL_FACES + (size_t)f]++;
    }
}

static void counter_free(object_counter *k)
{
    free(k->first);
    free(k->entry_us);
    free(k->tests);
    free(k->touched);
}

static int counter_init(object_counter *k, const rt_scene *scene, const rt_grid *grid)
{
    size_t cells = rt_grid_cell_count(grid), objects = rt_scene_object_count(scene);
    memset(k, 0, sizeof *k);
    k->first = malloc((cells + 1) * sizeof *k->first);
    k->entry_us = calloc(rt_grid_list_entries(grid) + 1, sizeof *k->entry_us);
    k->tests = calloc(objects + 1, sizeof *k->tests);
    k->touched = malloc((objects + 1) * sizeof *k->touched);
    if (!k->first || !k->entry_us || !k->tests || !k->touched) return 0;
    k->first[0] = 0;
    for (size_t c = 0; c < cells; c++) {
        size_t n = 0;
        rt_grid_cell_objects(grid, c, &n);
        k->first[c + 1] = k->first[c] + n;
    }
    return 1;
}

static int by_object_then_cell(const void *a, const void *b)
{
    const rt_object_cell_us *x = a, *y = b;
    if (x->object != y->object) return x->object < y->object ? -1 : 1;
    return x->cell < y->cell ? -1 : x->cell > y->cell;
}

/* The counter's entries with work, as the pilot's object_us. */
static int counter_collect(const object_counter *k, const rt_grid *grid, rt_cost_pilot *out)
{
    size_t cells = rt_grid_cell_count(grid), n = 0;
    for (size_t e = 0; e < k->first[cells]; e++) n += k->entry_us[e] > 0;
    out->object_us = malloc((n + 1) * sizeof *out->object_us);
    if (!out->object_us) return 0;
    for (size_t c = 0; c < cells; c++) {
        size_t count = 0;
        const uint32_t *list = rt_grid_cell_objects(grid, c, &count);
        for (size_t i = 0; i < count; i++) {
            double us = k->entry_us[k->first[c] + i];
            if (us > 0) out->object_us[out->object_us_count++] = (rt_object_cell_us){list[i], (uint32_t)c, us};
        }
    }
    qsort(out->object_us, out->object_us_count, sizeof *out->object_us, by_object_then_cell);
    return 1;
}

static rt_status pilot_run(const rt_scene *scene, const rt_grid *grid, const rt_step_params *params,
                           const rt_timing *timing, int by_object, rt_cost_pilot *out, char *msg, size_t msg_len)
{
    memset(out, 0, sizeof *out);
    rt_grid_dims(grid, out->dims);
    out->cells = rt_grid_cell_count(grid);
    out->work_us = calloc(out->cells, sizeof *out->work_us);
    out->traffic = calloc(out->cells * RT_CELL_FACES, sizeof *out->traffic);
    int32_t *self = malloc(out->cells * sizeof *self);
    const rt_camera *cam = rt_scene_camera(scene);
    rt_framebuffer *fb = rt_framebuffer_new(cam->width, cam->height);
    object_counter counter;
    int counted = by_object ? counter_init(&counter, scene, grid) : (memset(&counter, 0, sizeof counter), 1);
    rt_status st = RT_ERR_NOMEM;
    if (out->work_us && out->traffic && self && fb && counted) {
        for (size_t c = 0; c < out->cells; c++) self[c] = (int32_t)c; /* every cell its own owner */
        rt_render_options o = rt_render_options_default();
        o.step = *params;
        o.step.brute_force = 0;
        o.cell_owner = self;
        pilot_ctx ctx = {out, timing, grid, by_object ? &counter : NULL};
        if (by_object) {
            o.step.on_test = on_test;
            o.step.on_test_ctx = &counter;
        }
        o.on_step = on_step;
        o.on_step_ctx = &ctx;
        rt_render_stats stats;
        st = rt_render(scene, grid, &o, fb, &stats, msg, msg_len);
        out->ops = stats.ops;
    } else if (msg && msg_len) {
        snprintf(msg, msg_len, "out of memory for the pilot run (%zu cells)", out->cells);
    }
    for (size_t c = 0; st == RT_OK && c < out->cells; c++) out->total_us += out->work_us[c];
    if (st == RT_OK && by_object && !counter_collect(&counter, grid, out)) {
        st = RT_ERR_NOMEM;
        if (msg && msg_len) snprintf(msg, msg_len, "out of memory for the pilot's per-object work");
    }
    counter_free(&counter);
    free(self);
    rt_framebuffer_free(fb);
    if (st != RT_OK) rt_cost_pilot_release(out);
    return st;
}

rt_status rt_cost_pilot_run(const rt_scene *scene, const rt_grid *grid, const rt_step_params *params,
                            const rt_timing *timing, rt_cost_pilot *out, char *msg, size_t msg_len)
{
    return pilot_run(scene, grid, params, timing, 0, out, msg, msg_len);
}

rt_status rt_cost_pilot_run_by_object(const rt_scene *scene, const rt_grid *grid, const rt_step_params *params,
                                      const rt_timing *timing, rt_cost_pilot *out, char *msg, size_t msg_len)
{
    return pilot_run(scene, grid, params, timing, 1, out, msg, msg_len);
}

void rt_cost_pilot_release(rt_cost_pilot *p)
{
    free(p->object_us);
    free(p->work_us);
    free(p->traffic);
    memset(p, 0, sizeof *p);
}

uint64_t rt_cost_pilot_bytes(const rt_grid *grid, size_t objects, uint32_t width, uint32_t height, int by_object)
{
    uint64_t cells = rt_grid_cell_count(grid);
    /* work_us, traffic and the self-owner table, as pilot_run allocates them */
    uint64_t bytes = cells * (sizeof(double) + RT_CELL_FACES * sizeof(uint64_t) + sizeof(int32_t));
    bytes += rt_framebuffer_bytes(width, height);
    if (by_object) /* counter_init's tables, and object_us at most one record per list entry */
        bytes += (cells + 1) * sizeof(size_t) +
                 (rt_grid_list_entries(grid) + 1) * (sizeof(double) + sizeof(rt_object_cell_us)) +
                 (objects + 1) * 2 * sizeof(uint64_t);
    return bytes;
}

double rt_cost_edge_us(const rt_timing *t)
{
    return t->handover_send_us + t->handover_receive_us + rt_timing_link_packet_us(t);
}
