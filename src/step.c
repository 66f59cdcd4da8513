/* step.c - the packet step (docs/design.md section 2): walk the cells one processor
 * owns, find the nearest hit, shade it and make the next packets. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "grid_internal.h"
#include "intersect.h"
#include "rt_step.h"
#include "scene_internal.h"

rt_step_params rt_step_params_default(void)
{
    rt_step_params p;
    memset(&p, 0, sizeof p);
    p.max_depth = 8;
    p.min_weight = 1.0 / 512.0;
    return p;
}

rt_status rt_step_result_init(rt_step_result *r, const rt_scene *scene)
{
    memset(r, 0, sizeof *r);
    size_t lights = rt_scene_light_count(scene);
    r->contrib = malloc(RT_STEP_MAX_CONTRIB(lights) * sizeof *r->contrib);
    r->created = malloc(RT_STEP_MAX_CREATED(lights) * sizeof *r->created);
    if (!r->contrib || !r->created) {
        rt_step_result_release(r);
        return RT_ERR_NOMEM;
    }
    r->contrib_capacity = RT_STEP_MAX_CONTRIB(lights);
    r->created_capacity = RT_STEP_MAX_CREATED(lights);
    return RT_OK;
}

void rt_step_result_release(rt_step_result *r)
{
    free(r->contrib);
    free(r->created);
    memset(r, 0, sizeof *r);
}

uint32_t rt_packet_cell(const rt_grid *grid, const rt_packet *p) { return rt_grid_index(grid->dims, p->dda.cell); }

/* Adds a frame-buffer contribution unless it is black (no write then). */
static void contribute(rt_step_result *out, const rt_packet *p, rt_vec3 rgb)
{
    if (rt_vec_is_zero(rgb)) return;
    rt_contribution *c = &out->contrib[out->contrib_count++];
    c->x = p->x;
    c->y = p->y;
    c->rgb = rgb;
    out->ops.fb_writes++;
}

/* What a packet adds when it leaves the object space with nothing hit. */
static rt_vec3 escape_value(const rt_scene *scene, const rt_packet *p)
{
    return p->kind == RT_PACKET_SHADOW ? p->weight : rt_vec_mul(p->weight, scene->background);
}

/* Sends a new packet on its way: it starts in the cell its origin's ray
 * enters; a ray that never meets the object space contributes at once. */
static void launch(const rt_scene *scene, const rt_grid *grid, const rt_step_params *params, rt_packet *np,
                   rt_step_result *out)
{
    if (params->brute_force) {
        memset(&np->dda, 0, sizeof np->dda);
        out->created[out->created_count++] = *np;
        out->ops.packets_created++;
        return;
    }
    out->ops.dda_steps++;
    if (rt_dda_start(grid, np->origin, np->dir, 0.0, &np->dda)) {
        out->created[out->created_count++] = *np;
        out->ops.packets_created++;
    } else {
        contribute(out, np, escape_value(scene, np));
    }
}

static int worth_a_ray(const rt_step_params *params, int depth, rt_vec3 weight)
{
    return depth <= params->max_depth && rt_vec_max_component(weight) >= params->min_weight && !rt_vec_is_zero(weight);
}

/* What the shading of one hit needs to know of the surface there. */
typedef struct surface {
    const rt_material *m;
    rt_vec3 nf;    /* shading normal toward the ray */
    rt_vec3 refl;  /* mirror direction */
    rt_vec3 above; /* secondary rays start here, off the surface on the ray's side */
    rt_vec3 below; /* and here on the far side (refraction) */
    rt_vec3 pt;    /* the hit point */
    rt_vec3 gf;    /* geometric normal toward the ray */
    int entering;  /* the ray enters the object */
    int smooth;    /* the shading normal is not the geometric one (`pp` triangles) */
} surface;

/* Where a new ray along `dir` starts. Off a smooth triangle it starts on the side of the plane
 * it heads for: a shading normal tilted from the face sends shadow and mirror rays through the
 * plane, and from the other side they would hit their own triangle. */
static rt_vec3 start_point(const surface *s, rt_vec3 dir, rt_vec3 usual)
{
    if (!s->smooth) return usual;
    return rt_vec_dot(dir, s->gf) >= 0.0 ? s->above : s->below;
}

/* One shadow packet toward every light the surface faces (into `np`, reused). */
static void shadow_rays(const rt_scene *scene, const rt_grid *grid, const rt_step_params *params, const rt_packet *p,
                        const surface *s, rt_packet *np, rt_step_result *out)
{
    const rt_material *m = s->m;
    for (size_t j = 0; j < scene->light_count; j++) {
        const rt_light *lj = &scene->lights[j].light;
        rt_vec3 l = rt_vec_normalize(rt_vec_sub(lj->position, s->pt));
        double c = rt_vec_dot(s->nf, l);
        if (!(c > 0.0)) continue;
        rt_vec3 value = rt_vec_scale(m->color, m->kd * c);
        if (m->shine > 0.0) {
            /* Clamped to [0, 1] (rounding can pass 1), so any Shine gives a finite power. */
            double spec = m->ks * pow(fmin(1.0, fmax(0.0, rt_vec_dot(s->refl, l))), m->shine);
            value = rt_vec_add(value, rt_vec(spec, spec, spec));
        }
        value = rt_vec_mul(rt_vec_mul(p->weight, lj->color), value);
        if (rt_vec_is_zero(value)) continue;
        np->origin = start_point(s, l, s->above);
        rt_vec3 to = rt_vec_sub(lj->position, np->origin);
        double dist = rt_vec_length(to);
        np->kind = RT_PACKET_SHADOW;
        np->depth = p->depth;
        np->weight = value;
        if (!(dist > 0.0)) { /* the light sits on the surface: nothing can block it */
            contribute(out, np, value);
            continue;
        }
        np->dir = rt_vec_scale(to, 1.0 / dist);
        np->t_light = dist;
        launch(scene, grid, params, np, out);
    }
}

/* The reflected and the refracted ray, where they are worth tracing. */
static void secondary_rays(const rt_scene *scene, const rt_grid *grid, const rt_step_params *params, const rt_packet *p,
                           const surface *s, rt_packet *np, rt_step_result *out)
{
    const rt_material *m = s->m;
    rt_vec3 d = p->dir, w = p->weight;
    int depth = p->depth + 1;
    np->kind = RT_PACKET_RAY;
    np->depth = (uint16_t)depth;
    np->t_light = INFINITY;
    if (m->ks > 0.0) {
        rt_vec3 wr = rt_vec_scale(w, m->ks);
        if (worth_a_ray(params, depth, wr)) {
            out->ops.reflection_vectors++;
            np->weight = wr;
            np->origin = start_point(s, s->refl, s->above);
            np->dir = s->refl;
            launch(scene, grid, params, np, out);
        }
    }
    if (m->t > 0.0) {
        rt_vec3 wt = rt_vec_scale(w, m->t);
        if (worth_a_ray(params, depth, wt)) {
            out->ops.refraction_vectors++;
            double eta = s->entering ? 1.0 / m->ior : m->ior;
            double cosi = fmin(1.0, fmax(0.0, -rt_vec_dot(d, s->nf)));
            double k = 1.0 - eta * eta * (1.0 - cosi * cosi);
            np->weight = wt;
            if (k < 0.0) { /* total internal reflection */
                np->origin = start_point(s, s->refl, s->above);
                np->dir = s->refl;
            } else {
                np->dir = rt_vec_normalize(rt_vec_add(rt_vec_scale(d, eta), rt_vec_scale(s->nf, eta * cosi - sqrt(k))));
                np->origin = start_point(s, np->dir, s->below);
            }
            launch(scene, grid, params, np, out);
        }
    }
}

/* Shading at an accepted ray hit (docs/design.md section 3). */
static void shade(const rt_scene *scene, const rt_grid *grid, const rt_step_params *params, const rt_packet *p,
                  uint32_t obj, const rt_hit *hit, rt_step_result *out)
{
    surface s;
    s.m = &scene->materials[scene->objects[obj].material];
    rt_vec3 d = p->dir;
    s.pt = rt_vec_add(p->origin, rt_vec_scale(d, hit->t));
    rt_vec3 n_geo, n_shade;
    rt_object_normals(scene, obj, s.pt, hit, &n_geo, &n_shade);
    s.entering = rt_vec_dot(d, n_geo) < 0.0;
    s.smooth = scene->objects[obj].kind == RT_OBJ_TRIANGLE;
    /* The shading normal turns toward the ray by its own side, not the face's: where a `pp`
     * normal tilts far from its face (a thin triangle across a curved surface) the face's side
     * says nothing about it. Elsewhere both sides agree. */
    s.nf = rt_vec_dot(d, n_shade) < 0.0 ? n_shade : rt_vec_scale(n_shade, -1.0);
    rt_vec3 gf = s.entering ? n_geo : rt_vec_scale(n_geo, -1.0); /* geometric normal toward the ray */
    s.gf = gf;
    out->ops.shadings++;

    contribute(out, p, rt_vec_mul(rt_vec_mul(p->weight, s.m->color), scene->ambient));

    /* Secondary rays start off the surface by a distance relative to the
     * magnitudes that bound the hit point's rounding error. */
    double scale = fmax(fmax(rt_vec_max_abs(s.pt), rt_vec_max_abs(p->origin)), hit->t);
    double eps = RT_SURFACE_OFFSET * scale;
    s.above = rt_vec_add(s.pt, rt_vec_scale(gf, eps));
    s.below = rt_vec_sub(s.pt, rt_vec_scale(gf, eps));
    s.refl = rt_vec_normalize(rt_vec_sub(d, rt_vec_scale(s.nf, 2.0 * rt_vec_dot(d, s.nf))));

    rt_packet np;
    memset(&np, 0, sizeof np);
    np.x = p->x;
    np.y = p->y;
    shadow_rays(scene, grid, params, p, &s, &np, out);
    secondary_rays(scene, grid, params, p, &s, &np, out);
}

/* Nearest hit among `objs` of a ray; ties go to the lowest index. */
static int nearest_hit(const rt_scene *scene, const rt_step_params *params, const rt_packet *p, const uint32_t *objs,
                       size_t n, uint32_t *best_obj, rt_hit *best, rt_step_result *out)
{
    int found = 0;
    for (size_t i = 0; i < n; i++) {
        uint32_t o = objs ? objs[i] : (uint32_t)i;
        rt_hit h;
        if (params->on_test) params->on_test(params->on_test_ctx, o);
        if (rt_intersect_object(scene, o, p->origin, p->dir, 0.0, INFINITY, &h)) {
            out->ops.tests_hit++;
            if (!found || h.t < best->t || (h.t == best->t && o < *best_obj)) {
                *best = h;
                *best_obj = o;
                found = 1;
            }
        } else {
            out->ops.tests_missed++;
        }
    }
    return found;
}

/* 1 if any of `objs` blocks a shadow packet before its light. */
static int blocked(const rt_scene *scene, const rt_step_params *params, const rt_packet *p, const uint32_t *objs,
                   size_t n, rt_step_result *out)
{
    for (size_t i = 0; i < n; i++) {
        uint32_t o = objs ? objs[i] : (uint32_t)i;
        rt_hit h;
        if (params->on_test) params->on_test(params->on_test_ctx, o);
        if (rt_intersect_object(scene, o, p->origin, p->dir, 0.0, p->t_light, &h)) {
            out->ops.tests_hit++;
            return 1;
        }
        out->ops.tests_missed++;
    }
    return 0;
}

static void step_brute_force(const rt_scene *scene, const rt_grid *grid, const rt_step_params *params, rt_packet *p,
                             rt_step_result *out)
{
    size_t n = scene->object_count;
    if (p->kind == RT_PACKET_SHADOW) {
        if (!blocked(scene, params, p, NULL, n, out)) contribute(out, p, p->weight);
        out->fate = RT_FATE_ABSORBED;
        return;
    }
    uint32_t obj = 0;
    rt_hit hit;
    if (nearest_hit(scene, params, p, NULL, n, &obj, &hit, out)) {
        shade(scene, grid, params, p, obj, &hit, out);
        out->fate = RT_FATE_ABSORBED;
    } else {
        contribute(out, p, escape_value(scene, p));
        out->fate = RT_FATE_LEFT;
    }
}

/* The next cell belongs to another owner: the packet goes on, marked as handed over. */
static void hand_over(rt_packet *p, uint32_t cell, rt_step_result *out)
{
    p->handed_over = 1;
    out->fate = RT_FATE_FORWARDED;
    out->next_cell = cell;
    out->ops.handovers_sent++;
}

rt_status rt_step(const rt_scene *scene, const rt_grid *grid, const int32_t *cell_owner, int32_t my_id,
                  const rt_step_params *params, rt_packet *p, rt_step_result *out)
{
    size_t lights = scene->light_count;
    if (out->contrib_capacity < RT_STEP_MAX_CONTRIB(lights) || out->created_capacity < RT_STEP_MAX_CREATED(lights))
        return RT_ERR_CAPACITY;
    if (p->kind >= RT_PACKET_KINDS) return RT_ERR_INVALID;
    memset(&out->ops, 0, sizeof out->ops);
    out->contrib_count = 0;
    out->created_count = 0;
    /* A packet another IP handed over costs a hand-over receive, a new one an analysis. */
    if (p->handed_over) out->ops.handovers_received = 1;
    else out->ops.packets_analysed = 1;
    p->handed_over = 0;

    if (params->brute_force) {
        step_brute_force(scene, grid, params, p, out);
        return RT_OK;
    }
    for (int a = 0; a < 3; a++)
        if (p->dda.cell[a] < 0 || p->dda.cell[a] >= grid->dims[a]) return RT_ERR_INVALID;

    uint32_t cell = rt_grid_index(grid->dims, p->dda.cell);
    /* Not ours: pass it on untouched. The replica table is read only off the primary owner. */
    if (cell_owner && cell_owner[cell] != my_id && !rt_replicas_holds(params->replicas, cell_owner, cell, my_id)) {
        hand_over(p, cell, out);
        return RT_OK;
    }
    for (;;) {
        double t_exit = rt_dda_t_exit(&p->dda);
        size_t n;
        const uint32_t *objs = rt_grid_cell_objects(grid, cell, &n);
        if (p->kind == RT_PACKET_RAY) {
            uint32_t obj = 0;
            rt_hit hit;
            /* A hit beyond this cell may be beaten by an object in a later cell. */
            if (nearest_hit(scene, params, p, objs, n, &obj, &hit, out) && hit.t <= t_exit) {
                shade(scene, grid, params, p, obj, &hit, out);
                out->fate = RT_FATE_ABSORBED;
                return RT_OK;
            }
        } else {
            if (blocked(scene, params, p, objs, n, out)) {
                out->fate = RT_FATE_ABSORBED;
                return RT_OK;
            }
            if (p->t_light <= t_exit) { /* the light is in this cell: reached */
                contribute(out, p, p->weight);
                out->fate = RT_FATE_ABSORBED;
                return RT_OK;
            }
        }
        out->ops.dda_steps++;
        if (!rt_dda_advance(grid, &p->dda, p->origin, p->dir)) {
            contribute(out, p, escape_value(scene, p));
            out->fate = RT_FATE_LEFT;
            return RT_OK;
        }
        out->ops.cell_steps++; /* the packet now names its next cell (docs/timing.md, cell_step_packet) */
        cell = rt_grid_index(grid->dims, p->dda.cell);
        if (cell_owner && cell_owner[cell] != my_id && !rt_replicas_holds(params->replicas, cell_owner, cell, my_id)) {
            hand_over(p, cell, out);
            return RT_OK;
        }
    }
}
