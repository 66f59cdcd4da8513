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
    uint64_t wanted; /* bytes a growth the budget refused asked for (old + new array) */
} queue;

/* 0 when memory runs out, -1 when the budget does not allow the queue to grow. */
static int queue_push(queue *q, const rt_packet *p, rt_budget *budget)
{
    if (q->count == q->capacity) {
        size_t cap = q->capacity ? q->capacity * 2 : 256;
        /* Old and new arrays live together while packets are copied: both count. */
        q->wanted = (uint64_t)(cap + q->capacity) * sizeof *p;
        uint64_t more = rt_budget_packets_allowed(budget, sizeof *p);
        if ((uint64_t)cap > more) cap = (size_t)more;
        if (cap <= q->capacity) return -1;
        if (rt_budget_reserve(budget, (uint64_t)cap * sizeof *p, "", NULL, 0)) return -1;
        rt_packet *n = malloc(cap * sizeof *n);
        if (!n) return 0;
        for (size_t i = 0; i < q->count; i++) n[i] = q->items[(q->head + i) % q->capacity];
        if (budget && budget->limit) budget->used -= (uint64_t)q->capacity * sizeof *p;
        free(q->items);
        q->items = n;
        q->head = 0;
        q->capacity = cap;
    }
    q->items[(q->head + q->count) % q->capacity] = *p;
    q->count++;
    return 1;
}

static rt_status push_status(int pushed) { return pushed > 0 ? RT_OK : pushed < 0 ? RT_ERR_LIMIT : RT_ERR_NOMEM; }

static rt_packet queue_pop(queue *q)
{
    rt_packet p = q->items[q->head];
    q->head = (q->head + 1) % q->capacity;
    q->count--;
    return p;
}

/* One packet's steps: one, or with owners one per owner it passes through. */
static rt_status step_packet(const rt_scene *scene, const rt_grid *grid, const rt_render_options *options,
                             rt_packet *cur, rt_step_result *r, queue *q, rt_framebuffer *fb, rt_render_stats *stats)
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
            rt_status pushed = push_status(queue_push(q, &r->created[i], options->budget));
            if (pushed != RT_OK) return pushed;
        }
        if (r->fate != RT_FATE_FORWARDED) {
            stats->packets.consumed[cur->kind]++;
            return RT_OK;
        }
        stats->packets.forwarded++;
    }
}

rt_status rt_render(const rt_scene *scene, const rt_grid *grid, const rt_render_options *options, rt_framebuffer *fb,
                    rt_render_stats *stats, char *msg, size_t msg_len)
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
            status = push_status(queue_push(&q, &p, options->budget));
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
    /* The queue is gone: give its reservation back. */
    if (options->budget && options->budget->limit) options->budget->used -= (uint64_t)q.capacity * sizeof(rt_packet);
    if (status == RT_ERR_LIMIT) {
        char what[160];
        snprintf(what, sizeof what,
                 "the work queue, full with %zu packets of %zu bytes, growing (old and new arrays "
                 "while packets are copied)",
                 q.count, sizeof(rt_packet));
        return rt_budget_exceeded(options->budget, what, q.wanted, msg, msg_len);
    }
    if (status != RT_OK) {
        if (msg) snprintf(msg, msg_len, "render failed: %s", rt_status_name(status));
        return status;
    }
    for (int k = 0; k < RT_PACKET_KINDS; k++) {
        if (stats->packets.created[k] != stats->packets.consumed[k]) {
            if (msg)
                snprintf(msg, msg_len, "packet conservation violated: kind %d created %llu consumed %llu", k,
                         (unsigned long long)stats->packets.created[k], (unsigned long long)stats->packets.consumed[k]);
            return RT_ERR_INVALID;
        }
    }
    return RT_OK;
}
