/* scene.c - the scene in memory: items, materials, lights, the view, and framing the view
 * around the objects. Every position and length is rounded with q9 as it is stored. */
#include "scene.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "nff_writer.h"

void scene_free(scene *sc)
{
    for (int i = 0; i < sc->nitems; ++i) {
        free(sc->items[i].verts);
        free(sc->items[i].normals);
    }
    free(sc->items);
}

void note(scene *sc, const char *fmt, ...)
{
    if (sc->nnotes >= MAX_NOTES) return;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(sc->notes[sc->nnotes++], NOTE_LEN, fmt, ap);
    va_end(ap);
}

static item *push_item(scene *sc, item_kind kind)
{
    if (sc->nitems == sc->cap) {
        int cap = sc->cap ? 2 * sc->cap : 64;
        item *p = realloc(sc->items, (size_t)cap * sizeof *p);
        if (!p) {
            sc->failed = 1;
            return NULL;
        }
        sc->items = p;
        sc->cap = cap;
    }
    item *it = &sc->items[sc->nitems++];
    memset(it, 0, sizeof *it);
    it->kind = kind;
    if (kind != IT_MATERIAL) sc->nobjects++;
    return it;
}

void view(scene *sc, vec3 from, vec3 at, vec3 up, double angle, int w, int h)
{
    sc->from = q9v(from);
    sc->at = q9v(at);
    sc->up = up;
    sc->angle = angle;
    sc->hither = 1e-3;
    sc->width = w;
    sc->height = h;
}

void background(scene *sc, double r, double g, double b)
{
    sc->bg[0] = r;
    sc->bg[1] = g;
    sc->bg[2] = b;
}

void ambient(scene *sc, double r, double g, double b)
{
    sc->has_ambient = 1;
    sc->ambient[0] = r;
    sc->ambient[1] = g;
    sc->ambient[2] = b;
}

void add_light(scene *sc, vec3 pos, double r, double g, double b)
{
    if (sc->nlights >= MAX_LIGHTS) return;
    light *l = &sc->lights[sc->nlights++];
    l->pos = q9v(pos);
    l->r = r;
    l->g = g;
    l->b = b;
}

/* `f r g b Kd Ks Shine T ior` for the objects that follow. */
void mat(scene *sc, double r, double g, double b, double kd, double ks, double shine, double t, double ior)
{
    item *it = push_item(sc, IT_MATERIAL);
    if (!it) return;
    material m = {r, g, b, kd, ks, shine, t, ior};
    it->mat = m;
}
void diffuse(scene *sc, double r, double g, double b, double kd) { mat(sc, r, g, b, kd, 0, 0, 0, 1); }

void sphere(scene *sc, vec3 c, double radius)
{
    item *it = push_item(sc, IT_SPHERE);
    if (!it) return;
    it->centre = q9v(c);
    it->radius = q9(radius);
}

void cone(scene *sc, vec3 base, double base_radius, vec3 apex, double apex_radius)
{
    item *it = push_item(sc, IT_CONE);
    if (!it) return;
    it->base = q9v(base);
    it->apex = q9v(apex);
    it->base_radius = q9(base_radius);
    it->apex_radius = q9(apex_radius);
}

/* Newell's normal of a vertex loop (not normalised). */
vec3 newell(int n, const vec3 *v)
{
    vec3 s = v3(0, 0, 0);
    for (int i = 0; i < n; ++i) {
        vec3 a = v[i], b = v[(i + 1) % n];
        s.x += (a.y - b.y) * (a.z + b.z);
        s.y += (a.z - b.z) * (a.x + b.x);
        s.z += (a.x - b.x) * (a.y + b.y);
    }
    return s;
}

/* A `p` (normals == NULL) or `pp` polygon; vertices are copied. */
void polygon_n(scene *sc, int n, const vec3 *v, const vec3 *normals)
{
    item *it = push_item(sc, normals ? IT_PATCH : IT_POLYGON);
    if (!it) return;
    it->nverts = n;
    it->verts = malloc((size_t)n * sizeof *it->verts);
    it->normals = normals ? malloc((size_t)n * sizeof *it->normals) : NULL;
    if (!it->verts || (normals && !it->normals)) {
        sc->failed = 1;
        it->nverts = 0;
        return;
    }
    for (int i = 0; i < n; ++i) {
        it->verts[i] = q9v(v[i]);
        if (normals) it->normals[i] = q9v(vnorm(normals[i]));
    }
}
void polygon(scene *sc, int n, const vec3 *v) { polygon_n(sc, n, v, NULL); }

/* Quad a, b, c, d (in that order: counter-clockwise seen from the front). */
void quad(scene *sc, vec3 a, vec3 b, vec3 c, vec3 d)
{
    vec3 v[4] = {a, b, c, d};
    polygon(sc, 4, v);
}

/* Quad in the plane y = y0 over [x0,x1] x [z0,z1], front facing +y. */
void floor_quad(scene *sc, double y0, double x0, double x1, double z0, double z1)
{
    quad(sc, v3(x0, y0, z1), v3(x1, y0, z1), v3(x1, y0, z0), v3(x0, y0, z0));
}

/* Closed box of six quads with outward (counter-clockwise from outside) vertex order;
 * the box is [-h, h] in its own frame (ex, ey, ez orthonormal, right-handed), centred at c. */
void box(scene *sc, vec3 c, vec3 h, vec3 ex, vec3 ey, vec3 ez)
{
    vec3 corner[8];
    for (int i = 0; i < 8; ++i) {
        double sx = (i & 1) ? h.x : -h.x, sy = (i & 2) ? h.y : -h.y, sz = (i & 4) ? h.z : -h.z;
        corner[i] = vadd(c, vadd(vmul(ex, sx), vadd(vmul(ey, sy), vmul(ez, sz))));
    }
    /* Each face listed counter-clockwise seen from outside. */
    static const int face[6][4] = {
        {1, 3, 7, 5}, /* +x */ {0, 4, 6, 2}, /* -x */ {2, 6, 7, 3}, /* +y */
        {0, 1, 5, 4}, /* -y */ {4, 5, 7, 6}, /* +z */ {0, 2, 3, 1}, /* -z */
    };
    for (int f = 0; f < 6; ++f) {
        vec3 v[4];
        vec3 mid = v3(0, 0, 0);
        for (int k = 0; k < 4; ++k) {
            v[k] = corner[face[f][k]];
            mid = vadd(mid, vmul(v[k], 0.25));
        }
        if (vdot(newell(4, v), vsub(mid, c)) <= 0) { /* never: the table is outward */
            fprintf(stderr, "gen_scenes: internal error: box face %d faces inward\n", f);
            sc->failed = 1;
        }
        polygon(sc, 4, v);
    }
}

/* ---------------------------------------------------------------- framing */

/* Camera basis exactly as the renderer builds it (docs/design.md section 3). */
static void camera_basis(const scene *sc, vec3 *w, vec3 *u, vec3 *v)
{
    *w = vnorm(vsub(sc->at, sc->from));
    *u = vnorm(vcross(*w, sc->up));
    *v = vcross(*u, *w);
}

/* Largest tangent, off the view axis along one screen axis, of a sphere seen from the eye;
 * (a, z) are its centre's coordinates along that screen axis and the view axis. */
static double extent_tan(double a, double z, double r)
{
    double rho = sqrt(a * a + z * z);
    if (r >= rho) return 1e30;
    double ang = atan2(fabs(a), z) + asin(r / rho);
    return ang >= PI / 2 ? 1e30 : tan(ang);
}

/* Sets sc->angle to the smallest multiple of 0.5 degree whose picture holds every object
 * (bounding spheres of cones, polygon vertices) with `margin` (e.g. 1.05) to spare. */
void frame_all(scene *sc, double margin)
{
    vec3 w, u, v;
    camera_basis(sc, &w, &u, &v);
    double tu = 0, tv = 0;
    for (int i = 0; i < sc->nitems; ++i) {
        const item *it = &sc->items[i];
        vec3 c[64];
        double r[64];
        int n = 0;
        switch (it->kind) {
        case IT_SPHERE:
            c[0] = it->centre;
            r[0] = it->radius;
            n = 1;
            break;
        case IT_CONE:
            c[0] = it->base;
            r[0] = it->base_radius;
            c[1] = it->apex;
            r[1] = it->apex_radius;
            n = 2;
            break;
        case IT_POLYGON:
        case IT_PATCH:
            for (n = 0; n < it->nverts && n < 64; ++n) {
                c[n] = it->verts[n];
                r[n] = 0;
            }
            break;
        case IT_MATERIAL: break;
        }
        for (int k = 0; k < n; ++k) {
            vec3 p = vsub(c[k], sc->from);
            double z = vdot(p, w);
            double a = extent_tan(vdot(p, u), z, r[k]);
            double b = extent_tan(vdot(p, v), z, r[k]);
            if (a > tu) tu = a;
            if (b > tv) tv = b;
        }
    }
    /* Pixel-centre spacing needed along each axis, then the `angle` giving that spacing. */
    int wm = sc->width > 1 ? sc->width - 1 : 1, hm = sc->height > 1 ? sc->height - 1 : 1;
    int mm = (sc->width > sc->height ? sc->width : sc->height) - 1;
    if (mm < 1) mm = 1;
    double s = fmax(2 * tu / wm, 2 * tv / hm) * margin;
    double deg = 2 * atan(s * mm / 2) * 180 / PI;
    sc->angle = ceil(deg * 2 - 1e-9) / 2;
}
