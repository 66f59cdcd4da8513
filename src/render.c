/* render.c - the sequential reference renderer: pixel by pixel, one FIFO of packet steps. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "rt_render.h"
#include "scene_internal.h"

rt_render_options rt_render_options_default(void)
{
    rt_render_options o;
    memset(&o, 0, sizeof o);
    o.step = rt_step_params_default();
    return o;
}

/* A growable ring buffer of packets. */
typedef struct queue {
    rt_packet *items;
    size_t head, count, capacity;
} queue;

static int queue_push(queue *q, const rt_packet *p)
{
    if (q->count == q->capacity) {
        size_t cap = q->capacity ? q->capacity * 2 : 256;
        rt_packet *n = malloc(cap * sizeof *n);
        if (!n) return 0;
        for (size_t i = 0; i < q->count; i++) n[i] = q->items[(q->head + i) % q->capacity];
        free(q->items);
        q->items = n;
        q->head = 0;
        q->capacity = cap;
    }
    q->items[(q->head + q->count) % q->capacity] = *p;
    q->count++;
    return 1;
}

static rt_packet queue_pop(queue *q)
{
    rt_packet p = q->items[q->head];
    q->head = (q->head + 1) % q->capacity;
    q->count--;
    return p;
}

/* One packet's steps: one, or with owners one per owner it passes through. */
static rt_status step_packet(const rt_scene *scene, const rt_grid *grid, const rt_render_options *options,
                             rt_packet *cur, rt_step_result *r, queue *q, rt_framebuffer *fb,
                             rt_render_stats *stats)
{
    for (;;) {
        uint32_t cell = options->step.brute_force ? 0 : rt_packet_cell(grid, cur);
        int32_t me = options->cell_owner && !options->step.brute_force ? options->cell_owner[cell] : 0;
        rt_status status = rt_step(scene, grid, options->cell_owner, me, &options->step, cur, r);
        if (status) return status;
        rt_ops_add(&stats->ops, &r->ops);
        if (options->on_step) options->on_step(options->on_step_ctx, cell, cur, r);
        for (size_t i = 0; i < r->contrib_count; i++)
            rt_framebuffer_add(fb, r->contrib[i].x, r->contrib[i].y, r->contrib[i].rgb);
        for (size_t i = 0; i < r->created_count; i++) {
            stats->packets.created[r->created[i].kind]++;
            if (!queue_push(q, &r->created[i])) return RT_ERR_NOMEM;
        }
        if (r->fate != RT_FATE_FORWARDED) {
            stats->packets.consumed[cur->kind]++;
            return RT_OK;
        }
        stats->packets.forwarded++;
    }
}

rt_status rt_render(const rt_scene *scene, const rt_grid *grid, const rt_render_options *options,
                    rt_framebuffer *fb, rt_render_stats *stats, char *msg, size_t msg_len)
{
    memset(stats, 0, sizeof *stats);
    const rt_camera *cam = rt_scene_camera(scene);
    if (rt_framebuffer_width(fb) != cam->width || rt_framebuffer_height(fb) != cam->height) {
        if (msg) snprintf(msg, msg_len, "frame buffer size does not match the image size");
        return RT_ERR_INVALID;
    }
    rt_step_result r;
    if (rt_step_result_init(&r, scene) != RT_OK) {
        if (msg) snprintf(msg, msg_len, "out of memory");
        return RT_ERR_NOMEM;
    }
    queue q = {0};
    rt_status status = RT_OK;
    uint64_t total = (uint64_t)cam->width * cam->height, done = 0;
    rt_vec3 background = rt_scene_background(scene);
    for (uint32_t y = 0; y < cam->height && status == RT_OK; y++) {
        for (uint32_t x = 0; x < cam->width && status == RT_OK; x++) {
            rt_packet p;
            int enters;
            rt_primary_packet(scene, grid, x, y, &p, &enters);
            if (options->step.brute_force) enters = 1; /* the oracle ignores the grid */
            if (!enters) {
                stats->packets.primary_missed++;
                rt_framebuffer_add(fb, x, y, background);
                continue;
            }
            stats->packets.created[RT_PACKET_RAY]++;
            if (!queue_push(&q, &p)) status = RT_ERR_NOMEM;
            while (q.count && status == RT_OK) {
                if (q.count > stats->queue_high_water) stats->queue_high_water = q.count;
                rt_packet cur = queue_pop(&q);
                status = step_packet(scene, grid, options, &cur, &r, &q, fb, stats);
            }
            done++;
            if (options->progress && (done % 1024 == 0 || done == total))
                options->progress(options->progress_ctx, done, total);
        }
    }
    free(q.items);
    rt_step_result_release(&r);
    if (status != RT_OK) {
        if (msg) snprintf(msg, msg_len, "render failed: %s", rt_status_name(status));
        return status;
    }
    for (int k = 0; k < RT_PACKET_KINDS; k++) {
        if (stats->packets.created[k] != stats->packets.consumed[k]) {
            if (msg)
                snprintf(msg, msg_len, "packet conservation violated: kind %d created %llu consumed %llu", k,
                         (unsigned long long)stats->packets.created[k],
                         (unsigned long long)stats->packets.consumed[k]);
            return RT_ERR_INVALID;
        }
    }
    return RT_OK;
}
