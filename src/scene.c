/* scene.c - building and reading the scene model. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "polygon_inside.h"
#include "scene_internal.h"

/* Grows *buf to hold at least `need` items of `size` bytes. */
static rt_status grow(void **buf, size_t *capacity, size_t need, size_t size)
{
    if (need <= *capacity) return RT_OK;
    size_t cap = *capacity ? *capacity : 16;
    while (cap < need) cap *= 2;
    void *p = realloc(*buf, cap * size);
    if (!p) return RT_ERR_NOMEM;
    *buf = p;
    *capacity = cap;
    return RT_OK;
}

/* Coordinates and sizes beyond this would overflow squared distances: rejected as invalid. */
#define SCENE_MAX_MAGNITUDE 1e30

static int sane(double x) { return isfinite(x) && fabs(x) <= SCENE_MAX_MAGNITUDE; }
static int finite3(rt_vec3 v) { return sane(v.x) && sane(v.y) && sane(v.z); }

static rt_box empty_box(void)
{
    rt_box b = {rt_vec(INFINITY, INFINITY, INFINITY), rt_vec(-INFINITY, -INFINITY, -INFINITY)};
    return b;
}

static void box_add(rt_box *b, rt_vec3 p)
{
    b->lo = rt_vec(fmin(b->lo.x, p.x), fmin(b->lo.y, p.y), fmin(b->lo.z, p.z));
    b->hi = rt_vec(fmax(b->hi.x, p.x), fmax(b->hi.y, p.y), fmax(b->hi.z, p.z));
}

rt_material rt_material_default(void)
{
    rt_material m = {rt_vec(1, 1, 1), 1.0, 0.0, 0.0, 0.0, 1.0};
    return m;
}

rt_scene *rt_scene_new(void)
{
    rt_scene *s = calloc(1, sizeof *s);
    return s;
}

void rt_scene_free(rt_scene *s)
{
    if (!s) return;
    free(s->lights);
    free(s->materials);
    free(s->objects);
    free(s->vertices);
    free(s);
}

/* A copy of `n` items of `size` bytes (NULL for none); 0 if memory runs out. */
static int copy_array(void **dst, const void *src, size_t n, size_t size)
{
    *dst = NULL;
    if (!n) return 1;
    *dst = malloc(n * size);
    if (!*dst) return 0;
    memcpy(*dst, src, n * size);
    return 1;
}

rt_scene *rt_scene_clone(const rt_scene *s)
{
    rt_scene *c = malloc(sizeof *c);
    if (!c) return NULL;
    *c = *s;
    int ok = copy_array((void **)&c->lights, s->lights, s->light_count, sizeof *s->lights);
    ok = copy_array((void **)&c->materials, s->materials, ok ? s->material_count : 0, sizeof *s->materials) && ok;
    ok = copy_array((void **)&c->objects, s->objects, ok ? s->object_count : 0, sizeof *s->objects) && ok;
    ok = copy_array((void **)&c->vertices, s->vertices, ok ? s->vertex_count : 0, sizeof *s->vertices) && ok;
    c->light_capacity = s->light_count;
    c->material_capacity = s->material_count;
    c->object_capacity = s->object_count;
    c->vertex_capacity = s->vertex_count;
    if (!ok) {
        rt_scene_free(c);
        return NULL;
    }
    return c;
}

rt_status rt_scene_set_view(rt_scene *s, rt_vec3 from, rt_vec3 at, rt_vec3 up, double angle_deg, uint32_t width,
                            uint32_t height)
{
    if (!finite3(from) || !finite3(at) || !finite3(up) || !isfinite(angle_deg)) return RT_ERR_INVALID;
    if (!(angle_deg > 0.0 && angle_deg < 180.0)) return RT_ERR_INVALID;
    if (width == 0 || height == 0) return RT_ERR_INVALID;
    if (width > RT_SCENE_MAX_RESOLUTION || height > RT_SCENE_MAX_RESOLUTION) return RT_ERR_LIMIT;
    s->camera.from = from;
    s->camera.at = at;
    s->camera.up = rt_vec_rescaled(up); /* a tiny or huge 'up' keeps its direction */
    s->camera.angle = angle_deg;
    s->camera.width = width;
    s->camera.height = height;
    s->has_view = 1;
    return RT_OK;
}

rt_status rt_scene_set_resolution(rt_scene *s, uint32_t width, uint32_t height)
{
    if (width == 0 || height == 0) return RT_ERR_INVALID;
    if (width > RT_SCENE_MAX_RESOLUTION || height > RT_SCENE_MAX_RESOLUTION) return RT_ERR_LIMIT;
    s->camera.width = width;
    s->camera.height = height;
    return RT_OK;
}

rt_status rt_scene_set_background(rt_scene *s, rt_vec3 rgb)
{
    if (!finite3(rgb)) return RT_ERR_INVALID;
    s->background = rgb;
    return RT_OK;
}

rt_status rt_scene_set_ambient(rt_scene *s, rt_vec3 rgb)
{
    if (!finite3(rgb)) return RT_ERR_INVALID;
    s->ambient = rgb;
    return RT_OK;
}

rt_status rt_scene_add_light(rt_scene *s, rt_vec3 position, const rt_vec3 *rgb)
{
    if (!finite3(position) || (rgb && !finite3(*rgb))) return RT_ERR_INVALID;
    if (s->light_count >= RT_SCENE_MAX_LIGHTS) return RT_ERR_LIMIT;
    if (grow((void **)&s->lights, &s->light_capacity, s->light_count + 1, sizeof *s->lights)) return RT_ERR_NOMEM;
    rt_light_entry *e = &s->lights[s->light_count++];
    e->light.position = position;
    e->light.color = rgb ? *rgb : rt_vec(1, 1, 1);
    e->has_color = rgb != NULL;
    s->finished = 0;
    return RT_OK;
}

/* NFF bounds none of the numbers; only what shading needs is checked: a
 * Shine below 0 makes pow(0, Shine) infinite, and ior divides only where
 * T > 0 (SPD's opaque surfaces say `0`). */
static int material_valid(const rt_material *m)
{
    return finite3(m->color) && sane(m->kd) && sane(m->ks) && isfinite(m->shine) && sane(m->t) && isfinite(m->ior) &&
           m->shine >= 0.0 && (m->t <= 0.0 || m->ior > 0.0);
}

rt_status rt_scene_set_material(rt_scene *s, const rt_material *m)
{
    if (!material_valid(m)) return RT_ERR_INVALID;
    if (grow((void **)&s->materials, &s->material_capacity, s->material_count + 1, sizeof *s->materials))
        return RT_ERR_NOMEM;
    s->materials[s->material_count++] = *m;
    s->has_material = 1;
    if (m->t > 0.0) s->has_transmission = 1;
    return RT_OK;
}

/* Appends an object slot with the current material (the default one if none was set). */
static rt_status new_object(rt_scene *s, rt_object **out)
{
    if (s->object_count >= RT_SCENE_MAX_OBJECTS) return RT_ERR_LIMIT;
    if (!s->has_material) {
        rt_material d = rt_material_default();
        rt_status st = rt_scene_set_material(s, &d);
        if (st) return st;
        s->used_default = 1;
    }
    if (grow((void **)&s->objects, &s->object_capacity, s->object_count + 1, sizeof *s->objects)) return RT_ERR_NOMEM;
    rt_object *o = &s->objects[s->object_count];
    memset(o, 0, sizeof *o);
    o->material = (uint32_t)(s->material_count - 1);
    *out = o;
    return RT_OK;
}

void rt_scene_derive_sphere(rt_object *o)
{
    double radius = o->u.sphere.radius;
    rt_vec3 r = rt_vec(radius, radius, radius);
    o->bounds.lo = rt_vec_sub(o->u.sphere.center, r);
    o->bounds.hi = rt_vec_add(o->u.sphere.center, r);
}

rt_status rt_scene_add_sphere(rt_scene *s, rt_vec3 center, double radius)
{
    if (!finite3(center) || !sane(radius) || !(radius > 0.0)) return RT_ERR_INVALID;
    rt_object *o;
    rt_status st = new_object(s, &o);
    if (st) return st;
    o->kind = RT_OBJ_SPHERE;
    o->u.sphere.center = center;
    o->u.sphere.radius = radius;
    rt_scene_derive_sphere(o);
    s->object_count++;
    return RT_OK;
}

/* Newell's normal of a vertex loop (unnormalised; zero for zero area). */
static rt_vec3 newell_normal(const rt_vec3 *v, size_t n)
{
    rt_vec3 nrm = rt_vec(0, 0, 0);
    for (size_t i = 0; i < n; i++) {
        rt_vec3 a = v[i], b = v[(i + 1) % n];
        nrm.x += (a.y - b.y) * (a.z + b.z);
        nrm.y += (a.z - b.z) * (a.x + b.x);
        nrm.z += (a.x - b.x) * (a.y + b.y);
    }
    return nrm;
}

void rt_scene_derive_polygon(const rt_scene *s, rt_object *o)
{
    rt_polygon_data *p = &o->u.polygon;
    const rt_vec3 *v = s->vertices + p->first_vertex;
    size_t n = p->count;
    rt_vec3 nrm = newell_normal(v, n);
    double len = rt_vec_length(nrm);
    double scale = 0.0;
    for (size_t i = 0; i < n; i++) scale = fmax(scale, rt_vec_max_abs(rt_vec_sub(v[i], v[0])));
    /* Area is judged unsigned (the fan's triangle areas added up), so a self-crossing polygon
     * whose lobes cancel in Newell's sum (a symmetric bow-tie) still counts as having area;
     * its plane then comes from the largest fan triangle. */
    double area = 0.0, best = 0.0;
    rt_vec3 best_cross = rt_vec(0, 0, 0);
    for (size_t i = 1; i + 1 < n; i++) {
        rt_vec3 c = rt_vec_cross(rt_vec_sub(v[i], v[0]), rt_vec_sub(v[i + 1], v[0]));
        double a = rt_vec_length(c);
        area += a;
        if (a > best) {
            best = a;
            best_cross = c;
        }
    }
    double floor_area = 1e-14 * scale * scale;
    p->degenerate = !(area > 1e-300) || !(area > floor_area) || !isfinite(area);
    if (!p->degenerate && !(len > floor_area)) {
        nrm = best_cross;
        len = best;
    }
    p->normal = p->degenerate ? rt_vec(0, 0, 1) : rt_vec_scale(nrm, 1.0 / len);
    /* Plane offset from the centroid: the least biased point of a non-planar loop. */
    rt_vec3 c = rt_vec(0, 0, 0);
    for (size_t i = 0; i < n; i++) c = rt_vec_add(c, v[i]);
    c = rt_vec_scale(c, 1.0 / (double)n);
    p->offset = rt_vec_dot(p->normal, c);
    p->drop_axis = rt_dominant_axis(p->normal);
    o->bounds = empty_box();
    if (!p->degenerate)
        for (size_t i = 0; i < n; i++) box_add(&o->bounds, v[i]);
}

rt_status rt_scene_add_polygon(rt_scene *s, const rt_vec3 *v, size_t n)
{
    if (n < 3) return RT_ERR_INVALID;
    if (n > RT_SCENE_MAX_VERTICES) return RT_ERR_LIMIT;
    for (size_t i = 0; i < n; i++)
        if (!finite3(v[i])) return RT_ERR_INVALID;
    if (s->vertex_count + n > UINT32_MAX) return RT_ERR_LIMIT;
    if (grow((void **)&s->vertices, &s->vertex_capacity, s->vertex_count + n, sizeof *s->vertices)) return RT_ERR_NOMEM;
    rt_object *o;
    rt_status st = new_object(s, &o);
    if (st) return st;
    o->kind = RT_OBJ_POLYGON;
    rt_polygon_data *p = &o->u.polygon;
    p->first_vertex = (uint32_t)s->vertex_count;
    p->count = (uint32_t)n;
    memcpy(s->vertices + s->vertex_count, v, n * sizeof *v);
    s->vertex_count += n;
    rt_scene_derive_polygon(s, o);
    s->object_count++;
    return RT_OK;
}

void rt_scene_derive_triangle(rt_object *o)
{
    rt_triangle_data *t = &o->u.triangle;
    rt_vec3 g = rt_vec_cross(rt_vec_sub(t->v[1], t->v[0]), rt_vec_sub(t->v[2], t->v[0]));
    double len = rt_vec_length(g);
    double scale = fmax(rt_vec_max_abs(rt_vec_sub(t->v[1], t->v[0])), rt_vec_max_abs(rt_vec_sub(t->v[2], t->v[0])));
    t->degenerate = !(len > 1e-300) || !(len > 1e-14 * scale * scale) || !isfinite(len);
    t->normal = t->degenerate ? rt_vec(0, 0, 1) : rt_vec_scale(g, 1.0 / len);
    /* A zero vertex normal falls back to the face normal. */
    for (int k = 0; k < 3; k++)
        if (rt_vec_is_zero(t->n[k])) t->n[k] = t->normal;
    rt_vec3 sum = rt_vec_add(t->n[0], rt_vec_add(t->n[1], t->n[2]));
    t->side = rt_vec_dot(sum, t->normal) < 0.0 ? -1.0 : 1.0;
    o->bounds = empty_box();
    if (!t->degenerate)
        for (int k = 0; k < 3; k++) box_add(&o->bounds, t->v[k]);
}

rt_status rt_scene_add_patch(rt_scene *s, const rt_vec3 *v, const rt_vec3 *normals, size_t n)
{
    if (n < 3) return RT_ERR_INVALID;
    if (n > RT_SCENE_MAX_VERTICES) return RT_ERR_LIMIT;
    for (size_t i = 0; i < n; i++)
        if (!finite3(v[i]) || !finite3(normals[i])) return RT_ERR_INVALID;
    if (s->object_count + (n - 2) > RT_SCENE_MAX_OBJECTS) return RT_ERR_LIMIT;
    /* A fan from vertex 0: triangles (0, i, i+1). */
    for (size_t i = 1; i + 1 < n; i++) {
        rt_object *o;
        rt_status st = new_object(s, &o);
        if (st) return st;
        o->kind = RT_OBJ_TRIANGLE;
        rt_triangle_data *t = &o->u.triangle;
        size_t idx[3] = {0, i, i + 1};
        for (int k = 0; k < 3; k++) {
            t->v[k] = v[idx[k]];
            t->n[k] = rt_vec_normalize(normals[idx[k]]);
        }
        rt_scene_derive_triangle(o);
        s->object_count++;
    }
    return RT_OK;
}

void rt_scene_derive_cone(rt_object *o)
{
    rt_cone_data *c = &o->u.cone;
    rt_vec3 axis = rt_vec_sub(c->apex, c->base);
    double h = rt_vec_length(axis);
    c->axis = rt_vec_scale(axis, 1.0 / h);
    c->height = h;
    c->slope = (c->apex_radius - c->base_radius) / h;
    /* Bounds of the two end discs: a disc of radius r around axis a spans r*sqrt(1-a_i^2) on axis i. */
    o->bounds = empty_box();
    const rt_vec3 centers[2] = {c->base, c->apex};
    const double radii[2] = {c->base_radius, c->apex_radius};
    for (int k = 0; k < 2; k++) {
        rt_vec3 e = rt_vec(radii[k] * sqrt(fmax(0.0, 1.0 - c->axis.x * c->axis.x)),
                           radii[k] * sqrt(fmax(0.0, 1.0 - c->axis.y * c->axis.y)),
                           radii[k] * sqrt(fmax(0.0, 1.0 - c->axis.z * c->axis.z)));
        box_add(&o->bounds, rt_vec_sub(centers[k], e));
        box_add(&o->bounds, rt_vec_add(centers[k], e));
    }
}

rt_status rt_scene_add_cone(rt_scene *s, rt_vec3 base, double rb, rt_vec3 apex, double ra)
{
    if (!finite3(base) || !finite3(apex) || !sane(rb) || !sane(ra)) return RT_ERR_INVALID;
    if (rb < 0.0 || ra < 0.0 || (rb == 0.0 && ra == 0.0)) return RT_ERR_INVALID;
    rt_vec3 axis = rt_vec_sub(apex, base);
    double h = rt_vec_length(axis);
    if (!(h > 0.0) || !isfinite(h)) return RT_ERR_INVALID;
    rt_object *o;
    rt_status st = new_object(s, &o);
    if (st) return st;
    o->kind = RT_OBJ_CONE;
    o->u.cone = (rt_cone_data){.base = base, .apex = apex, .base_radius = rb, .apex_radius = ra};
    rt_scene_derive_cone(o);
    s->object_count++;
    return RT_OK;
}

rt_status rt_scene_finish(rt_scene *s, char *msg, size_t msg_len)
{
    if (!s->has_view) {
        if (msg) snprintf(msg, msg_len, "no view ('v') block: the scene has no camera");
        return RT_ERR_INVALID;
    }
    rt_vec3 w = rt_vec_sub(s->camera.at, s->camera.from);
    double wl = rt_vec_length(w);
    if (!(wl > 0.0) || !isfinite(wl)) {
        if (msg) snprintf(msg, msg_len, "degenerate camera: 'from' and 'at' are the same point");
        return RT_ERR_INVALID;
    }
    rt_vec3 u = rt_vec_cross(rt_vec_scale(w, 1.0 / wl), rt_vec_normalize(s->camera.up));
    if (!(rt_vec_length(u) > 1e-12)) {
        if (msg) snprintf(msg, msg_len, "degenerate camera: 'up' is zero or parallel to the view direction");
        return RT_ERR_INVALID;
    }
    double d = s->light_count ? 1.0 / sqrt((double)s->light_count) : 0.0;
    for (size_t i = 0; i < s->light_count; i++)
        if (!s->lights[i].has_color) s->lights[i].light.color = rt_vec(d, d, d);
    s->finished = 1;
    return RT_OK;
}

int rt_scene_used_default_material(const rt_scene *s) { return s->used_default; }
const rt_camera *rt_scene_camera(const rt_scene *s) { return &s->camera; }
rt_vec3 rt_scene_background(const rt_scene *s) { return s->background; }
rt_vec3 rt_scene_ambient(const rt_scene *s) { return s->ambient; }
size_t rt_scene_light_count(const rt_scene *s) { return s->light_count; }
const rt_light *rt_scene_light(const rt_scene *s, size_t i) { return i < s->light_count ? &s->lights[i].light : NULL; }
size_t rt_scene_object_count(const rt_scene *s) { return s->object_count; }
rt_object_kind rt_scene_object_kind(const rt_scene *s, size_t i) { return s->objects[i].kind; }
const rt_material *rt_scene_object_material(const rt_scene *s, size_t i)
{
    return &s->materials[s->objects[i].material];
}
rt_box rt_scene_object_bounds(const rt_scene *s, size_t i) { return s->objects[i].bounds; }
int rt_scene_has_transmission(const rt_scene *s) { return s->has_transmission; }

uint32_t rt_scene_material_bytes(void) { return 9u * 4u; }

uint32_t rt_scene_object_bytes(const rt_scene *s, size_t i)
{
    const rt_object *o = &s->objects[i];
    switch (o->kind) {
    case RT_OBJ_SPHERE: return 4u * 4u + 4u;                              /* centre, radius, material */
    case RT_OBJ_POLYGON: return 4u + 16u + 12u * o->u.polygon.count + 4u; /* count, plane, vertices, material */
    case RT_OBJ_TRIANGLE: return 3u * 24u + 12u + 4u;                     /* vertices+normals, face normal, material */
    case RT_OBJ_CONE: return 8u * 4u + 4u;                                /* two centres and radii, material */
    }
    return 0;
}
