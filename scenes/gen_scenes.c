/* gen_scenes.c - writes torusrt's NFF scene files: the paper's two images and the stiff cases.
 *
 * Usage:
 *   torusrt-genscenes OUTDIR            write every scene as OUTDIR/NAME.nff
 *   torusrt-genscenes OUTDIR NAME...    write only the named scenes
 *   torusrt-genscenes --list            print every name with a one-line description
 *   torusrt-genscenes --help            print this usage
 * Returns 0 on success, 1 when a file cannot be written, 2 on a usage error (unknown name,
 * missing OUTDIR). Each file is written to NAME.nff.tmp and renamed, so a failed run never
 * leaves a partial NAME.nff behind.
 *
 * Output is byte-reproducible: no clock, no rand(); the one pseudo-random placement uses a
 * fixed-seed 64-bit LCG. Every coordinate computed with libm is rounded to 9 significant
 * digits when the scene is built, and every number is printed as the shortest decimal that
 * reads back as the same double (up to "%.17g"), so the scaled scenes hold the exact products
 * of the base numbers and their factor.
 *
 * Standalone C11: libc and libm only.
 */
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846

/* ---------------------------------------------------------------- vectors */

typedef struct {
    double x, y, z;
} vec3;

static vec3 v3(double x, double y, double z) { vec3 r = {x, y, z}; return r; }
static vec3 vadd(vec3 a, vec3 b) { return v3(a.x + b.x, a.y + b.y, a.z + b.z); }
static vec3 vsub(vec3 a, vec3 b) { return v3(a.x - b.x, a.y - b.y, a.z - b.z); }
static vec3 vmul(vec3 a, double s) { return v3(a.x * s, a.y * s, a.z * s); }
static double vdot(vec3 a, vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static vec3 vcross(vec3 a, vec3 b)
{
    return v3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
static double vlen(vec3 a) { return sqrt(vdot(a, a)); }
static vec3 vnorm(vec3 a) { return vmul(a, 1.0 / vlen(a)); }

/* Rounds to 9 significant digits, so values computed with libm do not carry its last bits. */
static double q9(double x)
{
    char buf[40];
    snprintf(buf, sizeof buf, "%.9g", x);
    return strtod(buf, NULL);
}
static vec3 q9v(vec3 a) { return v3(q9(a.x), q9(a.y), q9(a.z)); }

/* Fixed-seed LCG (Knuth's MMIX constants); returns a double in [0, 1). */
static uint64_t lcg_state = 1;
static void lcg_seed(uint64_t seed) { lcg_state = seed; }
static double lcg_next(void)
{
    lcg_state = lcg_state * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(lcg_state >> 11) * (1.0 / 9007199254740992.0);
}

/* ---------------------------------------------------------------- scene in memory */

typedef struct {
    double r, g, b, kd, ks, shine, t, ior;
} material;

typedef enum { IT_MATERIAL, IT_SPHERE, IT_POLYGON, IT_PATCH, IT_CONE } item_kind;

typedef struct {
    item_kind kind;
    material mat;                      /* IT_MATERIAL */
    vec3 centre;                       /* IT_SPHERE */
    double radius;                     /* IT_SPHERE */
    vec3 base, apex;                   /* IT_CONE: axis end points */
    double base_radius, apex_radius;   /* IT_CONE */
    int nverts;                        /* IT_POLYGON, IT_PATCH */
    vec3 *verts;                       /* IT_POLYGON, IT_PATCH: nverts points */
    vec3 *normals;                     /* IT_PATCH: nverts unit vertex normals */
} item;

#define MAX_NOTES 24
#define NOTE_LEN 200
#define MAX_LIGHTS 4

typedef struct {
    vec3 pos;
    double r, g, b;
} light;

typedef struct {
    char notes[MAX_NOTES][NOTE_LEN]; /* header comment lines, without the leading "# " */
    int nnotes;
    vec3 from, at, up;
    double angle;   /* degrees */
    double hither;
    int width, height;
    double bg[3];
    int has_ambient;
    double ambient[3];
    light lights[MAX_LIGHTS];
    int nlights;
    item *items;
    int nitems, cap;
    int nobjects;
    int failed;     /* out of memory while building */
} scene;

static void scene_free(scene *sc)
{
    for (int i = 0; i < sc->nitems; ++i) {
        free(sc->items[i].verts);
        free(sc->items[i].normals);
    }
    free(sc->items);
}

static void note(scene *sc, const char *fmt, ...)
{
    if (sc->nnotes >= MAX_NOTES)
        return;
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
    if (kind != IT_MATERIAL)
        sc->nobjects++;
    return it;
}

static void view(scene *sc, vec3 from, vec3 at, vec3 up, double angle, int w, int h)
{
    sc->from = q9v(from);
    sc->at = q9v(at);
    sc->up = up;
    sc->angle = angle;
    sc->hither = 1e-3;
    sc->width = w;
    sc->height = h;
}

static void background(scene *sc, double r, double g, double b)
{
    sc->bg[0] = r; sc->bg[1] = g; sc->bg[2] = b;
}

static void ambient(scene *sc, double r, double g, double b)
{
    sc->has_ambient = 1;
    sc->ambient[0] = r; sc->ambient[1] = g; sc->ambient[2] = b;
}

static void add_light(scene *sc, vec3 pos, double r, double g, double b)
{
    if (sc->nlights >= MAX_LIGHTS)
        return;
    light *l = &sc->lights[sc->nlights++];
    l->pos = q9v(pos);
    l->r = r; l->g = g; l->b = b;
}

/* `f r g b Kd Ks Shine T ior` for the objects that follow. */
static void mat(scene *sc, double r, double g, double b, double kd, double ks, double shine,
                double t, double ior)
{
    item *it = push_item(sc, IT_MATERIAL);
    if (!it)
        return;
    material m = {r, g, b, kd, ks, shine, t, ior};
    it->mat = m;
}
static void diffuse(scene *sc, double r, double g, double b, double kd)
{
    mat(sc, r, g, b, kd, 0, 0, 0, 1);
}

static void sphere(scene *sc, vec3 c, double radius)
{
    item *it = push_item(sc, IT_SPHERE);
    if (!it)
        return;
    it->centre = q9v(c);
    it->radius = q9(radius);
}

static void cone(scene *sc, vec3 base, double base_radius, vec3 apex, double apex_radius)
{
    item *it = push_item(sc, IT_CONE);
    if (!it)
        return;
    it->base = q9v(base);
    it->apex = q9v(apex);
    it->base_radius = q9(base_radius);
    it->apex_radius = q9(apex_radius);
}

/* Newell's normal of a vertex loop (not normalised). */
static vec3 newell(int n, const vec3 *v)
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
static void polygon_n(scene *sc, int n, const vec3 *v, const vec3 *normals)
{
    item *it = push_item(sc, normals ? IT_PATCH : IT_POLYGON);
    if (!it)
        return;
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
        if (normals)
            it->normals[i] = q9v(vnorm(normals[i]));
    }
}
static void polygon(scene *sc, int n, const vec3 *v) { polygon_n(sc, n, v, NULL); }

/* Quad a, b, c, d (in that order: counter-clockwise seen from the front). */
static void quad(scene *sc, vec3 a, vec3 b, vec3 c, vec3 d)
{
    vec3 v[4] = {a, b, c, d};
    polygon(sc, 4, v);
}

/* Quad in the plane y = y0 over [x0,x1] x [z0,z1], front facing +y. */
static void floor_quad(scene *sc, double y0, double x0, double x1, double z0, double z1)
{
    quad(sc, v3(x0, y0, z1), v3(x1, y0, z1), v3(x1, y0, z0), v3(x0, y0, z0));
}

/* Closed box of six quads with outward (counter-clockwise from outside) vertex order;
 * the box is [-h, h] in its own frame (ex, ey, ez orthonormal, right-handed), centred at c. */
static void box(scene *sc, vec3 c, vec3 h, vec3 ex, vec3 ey, vec3 ez)
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

/* Camera basis exactly as the renderer builds it (DESIGN.md section 3). */
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
    if (r >= rho)
        return 1e30;
    double ang = atan2(fabs(a), z) + asin(r / rho);
    return ang >= PI / 2 ? 1e30 : tan(ang);
}

/* Sets sc->angle to the smallest multiple of 0.5 degree whose picture holds every object
 * (bounding spheres of cones, polygon vertices) with `margin` (e.g. 1.05) to spare. */
static void frame_all(scene *sc, double margin)
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
        case IT_SPHERE: c[0] = it->centre; r[0] = it->radius; n = 1; break;
        case IT_CONE:
            c[0] = it->base; r[0] = it->base_radius;
            c[1] = it->apex; r[1] = it->apex_radius; n = 2;
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

/* ---------------------------------------------------------------- writer */

/* Shortest "%.*g" decimal that reads back as x, without an exponent for 1e-4 <= |x| < 1e17
 * (30, not 3e+01); -0 prints as 0. */
static const char *num(char *buf, size_t n, double x)
{
    if (x == 0)
        x = 0.0;
    int plain_ok = fabs(x) >= 1e-4 && fabs(x) < 1e17;
    for (int p = 1; p <= 17; ++p) {
        snprintf(buf, n, "%.*g", p, x);
        if (strtod(buf, NULL) == x && (!plain_ok || !strchr(buf, 'e')))
            break;
    }
    return buf;
}

typedef struct {
    FILE *f;
    double scale; /* applied to every position and length; not to colours or directions */
} writer;

static void put_nums(writer *wr, const char *tag, int n, const double *x)
{
    char buf[40];
    fputs(tag, wr->f);
    for (int i = 0; i < n; ++i) {
        if (i > 0 || tag[0] != '\0')
            fputc(' ', wr->f);
        fputs(num(buf, sizeof buf, x[i]), wr->f);
    }
    fputc('\n', wr->f);
}
static void put_pos(writer *wr, const char *tag, vec3 p, int extra, const double *more)
{
    double x[8] = {p.x * wr->scale, p.y * wr->scale, p.z * wr->scale};
    for (int i = 0; i < extra; ++i)
        x[3 + i] = more[i];
    put_nums(wr, tag, 3 + extra, x);
}

static void write_scene(writer *wr, const char *name, const char *desc, const scene *sc)
{
    FILE *f = wr->f;
    fprintf(f, "# torusrt scene %s: %s\n", name, desc);
    for (int i = 0; i < sc->nnotes; ++i)
        fprintf(f, "# %s\n", sc->notes[i]);
    fprintf(f, "# %d objects, %dx%d pixels.\n", sc->nobjects, sc->width, sc->height);
    fprintf(f, "# Generated by scenes/gen_scenes.c (build/torusrt-genscenes scenes); "
               "do not edit by hand.\n");
    fputs("v\n", f);
    put_pos(wr, "from", sc->from, 0, NULL);
    put_pos(wr, "at", sc->at, 0, NULL);
    put_nums(wr, "up", 3, (const double[]){sc->up.x, sc->up.y, sc->up.z});
    put_nums(wr, "angle", 1, &sc->angle);
    double hither = sc->hither * wr->scale;
    put_nums(wr, "hither", 1, &hither);
    fprintf(f, "resolution %d %d\n", sc->width, sc->height);
    put_nums(wr, "b", 3, sc->bg);
    if (sc->has_ambient)
        put_nums(wr, "am", 3, sc->ambient);
    for (int i = 0; i < sc->nlights; ++i) {
        const light *l = &sc->lights[i];
        put_pos(wr, "l", l->pos, 3, (const double[]){l->r, l->g, l->b});
    }
    for (int i = 0; i < sc->nitems; ++i) {
        const item *it = &sc->items[i];
        switch (it->kind) {
        case IT_MATERIAL: {
            const material *m = &it->mat;
            put_nums(wr, "f", 8, (const double[]){m->r, m->g, m->b, m->kd, m->ks, m->shine,
                                                  m->t, m->ior});
            break;
        }
        case IT_SPHERE: {
            double r = it->radius * wr->scale;
            put_pos(wr, "s", it->centre, 1, &r);
            break;
        }
        case IT_CONE: {
            double rb = it->base_radius * wr->scale, ra = it->apex_radius * wr->scale;
            fputs("c\n", f);
            put_pos(wr, "", it->base, 1, &rb);
            put_pos(wr, "", it->apex, 1, &ra);
            break;
        }
        case IT_POLYGON:
        case IT_PATCH:
            fprintf(f, "%s %d\n", it->kind == IT_PATCH ? "pp" : "p", it->nverts);
            for (int k = 0; k < it->nverts; ++k) {
                if (it->kind == IT_PATCH) {
                    vec3 n = it->normals[k];
                    put_pos(wr, "", it->verts[k], 3, (const double[]){n.x, n.y, n.z});
                } else {
                    put_pos(wr, "", it->verts[k], 0, NULL);
                }
            }
            break;
        }
    }
}

/* ---------------------------------------------------------------- the paper's scenes */

/* Image 1: nine copies of a two-level recursive "flake" of diffuse spheres. */
static void build_paper_image1(scene *sc, double factor)
{
    (void)factor;
    const double R = 1.0;           /* radius of a group's big sphere */
    const double spacing = 5.0;     /* between group centres on the 3 x 3 grid */
    const double child_dist = 1.6;  /* child centre from its parent's centre, x parent radius */
    static const double big_colour[3][3] = {
        {0.85, 0.22, 0.18}, {0.18, 0.42, 0.85}, {0.22, 0.68, 0.32}};
    note(sc, "The paper's image 1: 369 diffuse spheres, large and small, defined recursively.");
    note(sc, "Recursion: 9 groups on a 3x3 grid in the plane z = 0 (centres 5 apart); each group");
    note(sc, "is a sphere of radius 1, 8 children of radius 1/2 centred 1.6 x 1 from it along the");
    note(sc, "cube-corner directions (+-1,+-1,+-1)/sqrt(3), and on each child 4 grandchildren of");
    note(sc, "radius 1/4 centred 1.6 x 1/2 from it, tilted 60 degrees off the child's outward");
    note(sc, "direction at azimuths 45+90k degrees: 9 x (1 + 8 + 8 x 4) = 9 x 41 = 369 spheres.");
    note(sc, "All diffuse (Ks = 0, T = 0); two lights, ambient 0.1; angle fitted to frame all.");

    for (int gy = 0; gy < 3; ++gy) {
        for (int gx = 0; gx < 3; ++gx) {
            int g = gy * 3 + gx;
            vec3 centre = v3(spacing * (gx - 1), spacing * (1 - gy), 0);
            const double *bc = big_colour[g % 3];
            diffuse(sc, bc[0], bc[1], bc[2], 0.8);
            sphere(sc, centre, R);

            vec3 child_centre[8], child_dir[8];
            for (int k = 0; k < 8; ++k) {
                vec3 d = vnorm(v3((k & 1) ? 1 : -1, (k & 2) ? 1 : -1, (k & 4) ? 1 : -1));
                child_dir[k] = d;
                child_centre[k] = vadd(centre, vmul(d, child_dist * R));
            }
            diffuse(sc, 0.95, 0.8, 0.45, 0.8);
            for (int k = 0; k < 8; ++k)
                sphere(sc, child_centre[k], R / 2);

            diffuse(sc, 0.92, 0.92, 0.95, 0.8);
            for (int k = 0; k < 8; ++k) {
                vec3 d = child_dir[k];
                vec3 e1 = vnorm(vcross(d, v3(0, 1, 0)));
                vec3 e2 = vcross(d, e1);
                for (int j = 0; j < 4; ++j) {
                    double phi = (45.0 + 90.0 * j) * PI / 180;
                    vec3 side = vadd(vmul(e1, cos(phi)), vmul(e2, sin(phi)));
                    vec3 gdir = vadd(vmul(d, 0.5), vmul(side, sqrt(3.0) / 2));
                    sphere(sc, vadd(child_centre[k], vmul(gdir, child_dist * R / 2)), R / 4);
                }
            }
        }
    }
    view(sc, v3(4, 5, 30), v3(0, 0, 0), v3(0, 1, 0), 0, 144, 144);
    frame_all(sc, 1.03);
    background(sc, 0.04, 0.04, 0.08);
    ambient(sc, 0.1, 0.1, 0.1);
    add_light(sc, v3(-20, 25, 30), 0.85, 0.85, 0.85);
    add_light(sc, v3(25, 5, 20), 0.4, 0.4, 0.45);
}

/* Image 2: a glass and a mirror sphere in front of an 11 x 11 plane of small spheres. */
static void build_paper_image2(scene *sc, double factor)
{
    (void)factor;
    note(sc, "The paper's image 2: one large transparent sphere (T 0.9, ior 1.5) and one large");
    note(sc, "mirror sphere (Ks 0.9) side by side in front, 121 small diffuse spheres (radius 0.5,");
    note(sc, "11 x 11, 1.5 apart) laid out in the horizontal plane y = 0 reaching behind them;");
    note(sc, "123 objects. Colour of the small spheres shades with column and row.");
    note(sc, "The camera looks down on the plane so it shows behind, through and in the big ones.");

    mat(sc, 0.95, 0.97, 1.0, 0.05, 0.1, 60, 0.9, 1.5);
    sphere(sc, v3(-2.3, 2.5, -2.0), 2.0);
    mat(sc, 0.85, 0.85, 0.9, 0.1, 0.9, 60, 0, 1);
    sphere(sc, v3(2.3, 2.5, -2.0), 2.0);
    for (int j = 0; j < 11; ++j) {
        for (int i = 0; i < 11; ++i) {
            diffuse(sc, q9(0.9 - 0.06 * i), q9(0.3 + 0.05 * j), q9(0.25 + 0.065 * i), 0.85);
            sphere(sc, v3(1.5 * (i - 5), 0, -1.5 * j), 0.5);
        }
    }
    view(sc, v3(0, 15, 10), v3(0, 0.5, -6), v3(0, 1, 0), 0, 144, 144);
    frame_all(sc, 1.02);
    background(sc, 0.12, 0.16, 0.32);
    ambient(sc, 0.1, 0.1, 0.1);
    add_light(sc, v3(-10, 18, 14), 0.8, 0.8, 0.8);
    add_light(sc, v3(12, 10, 6), 0.45, 0.45, 0.5);
}

/* ---------------------------------------------------------------- stiff and extreme cases */

static void build_axis_rays(scene *sc, double factor)
{
    (void)factor;
    note(sc, "33x33 camera looking exactly down -z with up +y: the centre row's rays have a zero");
    note(sc, "y component, the centre column's a zero x component, the centre ray is (0,0,-1).");
    note(sc, "The object space is symmetric in x and y, so the centre ray runs along the cell edge");
    note(sc, "x = y = 0. Sphere on the axis (reflective: its centre reflection goes back along +z);");
    note(sc, "backdrop z = -4, floor y = -5 and wall x = -5 are axis-aligned quads, parallel to the");
    note(sc, "centre row/column rays. One light on the axis, one off it.");
    mat(sc, 0.9, 0.25, 0.2, 0.7, 0.3, 30, 0, 1);
    sphere(sc, v3(0, 0, 0), 1.5);
    diffuse(sc, 0.6, 0.65, 0.8, 0.8);
    quad(sc, v3(-5, -5, -4), v3(5, -5, -4), v3(5, 5, -4), v3(-5, 5, -4));   /* z = -4, faces +z */
    diffuse(sc, 0.85, 0.85, 0.8, 0.8);
    floor_quad(sc, -5, -5, 5, -4, 6);                                       /* y = -5, faces +y */
    diffuse(sc, 0.4, 0.75, 0.4, 0.8);
    quad(sc, v3(-5, -5, -4), v3(-5, 5, -4), v3(-5, 5, 6), v3(-5, -5, 6));   /* x = -5, faces +x */
    view(sc, v3(0, 0, 10), v3(0, 0, 0), v3(0, 1, 0), 40, 33, 33);
    background(sc, 0.1, 0.1, 0.15);
    ambient(sc, 0.1, 0.1, 0.1);
    add_light(sc, v3(0, 0, 6), 0.35, 0.35, 0.35);
    add_light(sc, v3(3, 4, 8), 0.7, 0.7, 0.7);
}

static void build_grid_corners(scene *sc, double factor)
{
    (void)factor;
    note(sc, "Objects on the integer lattice of the object space [-12,12]^3, whose 24^3 cells are");
    note(sc, "unit cubes: three back walls on the space's faces x,y,z = -12, a reflective sphere");
    note(sc, "at the origin (a cell corner) with radius 3, six radius-2 spheres on the axes at 8,");
    note(sc, "nine radius-1 spheres along the wall edges, tangent to cell faces. Camera on the body");
    note(sc, "diagonal (odd resolution): the centre ray runs through cell corners (k,k,k) and the");
    note(sc, "centre column lies in the plane x = z, through cell edges. One light on a lattice");
    note(sc, "point inside the space.");
    diffuse(sc, 0.8, 0.45, 0.4, 0.8);
    quad(sc, v3(-12, -12, -12), v3(-12, 12, -12), v3(-12, 12, 12), v3(-12, -12, 12)); /* x */
    diffuse(sc, 0.75, 0.75, 0.72, 0.8);
    floor_quad(sc, -12, -12, 12, -12, 12);                                             /* y */
    diffuse(sc, 0.4, 0.5, 0.8, 0.8);
    quad(sc, v3(-12, -12, -12), v3(12, -12, -12), v3(12, 12, -12), v3(-12, 12, -12)); /* z */
    mat(sc, 0.8, 0.8, 0.85, 0.4, 0.5, 40, 0, 1);
    sphere(sc, v3(0, 0, 0), 3);
    diffuse(sc, 0.95, 0.8, 0.3, 0.8);
    for (int a = 0; a < 3; ++a) {
        for (int s = -1; s <= 1; s += 2) {
            double c[3] = {0, 0, 0};
            c[a] = 8.0 * s;
            sphere(sc, v3(c[0], c[1], c[2]), 2);
        }
    }
    diffuse(sc, 0.9, 0.9, 0.9, 0.8);
    for (int k = -6; k <= 6; k += 6) {
        sphere(sc, v3(-11, -11, k), 1);
        sphere(sc, v3(-11, k, -11), 1);
        sphere(sc, v3(k, -11, -11), 1);
    }
    view(sc, v3(30, 30, 30), v3(0, 0, 0), v3(0, 1, 0), 0, 49, 49);
    frame_all(sc, 1.02);
    background(sc, 0.05, 0.05, 0.1);
    ambient(sc, 0.1, 0.1, 0.1);
    add_light(sc, v3(18, 24, 12), 0.7, 0.7, 0.7);
    add_light(sc, v3(4, 10, 6), 0.3, 0.3, 0.3);
}

static const double PALETTE6[6][3] = {
    {0.9, 0.25, 0.2}, {0.95, 0.65, 0.15}, {0.85, 0.85, 0.2},
    {0.25, 0.75, 0.3}, {0.2, 0.45, 0.9}, {0.65, 0.3, 0.85}};

static void build_eye_inside(scene *sc, double factor)
{
    (void)factor;
    note(sc, "The eye at the centre of the object space: a ring of 12 spheres around it (some");
    note(sc, "behind the camera), one sphere above, a floor under it; wide 90 degree view.");
    diffuse(sc, 0.7, 0.7, 0.7, 0.8);
    floor_quad(sc, -2, -9, 9, -9, 9);
    for (int k = 0; k < 12; ++k) {
        const double *c = PALETTE6[k % 6];
        diffuse(sc, c[0], c[1], c[2], 0.8);
        double a = 2 * PI * k / 12;
        sphere(sc, v3(6 * cos(a), 0, 6 * sin(a)), 1);
    }
    diffuse(sc, 0.9, 0.9, 0.95, 0.8);
    sphere(sc, v3(0, 5, 0), 1.2);
    view(sc, v3(0, 0.5, 0), v3(1, 0.2, 0.6), v3(0, 1, 0), 90, 48, 48);
    background(sc, 0.1, 0.1, 0.2);
    ambient(sc, 0.1, 0.1, 0.1);
    add_light(sc, v3(4, 10, 3), 0.9, 0.9, 0.9);
}

static void build_light_inside(scene *sc, double factor)
{
    (void)factor;
    note(sc, "A point light at the centre of a ring of 8 spheres on a floor: the light lies inside");
    note(sc, "the object space; shadows point outward. Camera above, outside the space.");
    diffuse(sc, 0.8, 0.8, 0.75, 0.8);
    floor_quad(sc, 0, -8, 8, -8, 8);
    for (int k = 0; k < 8; ++k) {
        const double *c = PALETTE6[k % 6];
        diffuse(sc, c[0], c[1], c[2], 0.8);
        double a = 2 * PI * k / 8;
        sphere(sc, v3(4 * cos(a), 1, 4 * sin(a)), 1);
    }
    view(sc, v3(0, 11, 11), v3(0, 0, 0), v3(0, 1, 0), 0, 48, 48);
    frame_all(sc, 1.02);
    background(sc, 0.05, 0.05, 0.1);
    ambient(sc, 0.08, 0.08, 0.08);
    add_light(sc, v3(0, 1.5, 0), 1, 1, 1);
}

static void build_grazing(scene *sc, double factor)
{
    (void)factor;
    const int res = 63;
    const double angle = 30;
    const vec3 eye = v3(0, 0.25, 10);
    note(sc, "Grazing hits. Level camera at height 0.25 looking down -z (63x63: the centre row is");
    note(sc, "horizontal, the centre column lies in the plane x = 0). A floor y = 0 reaching 70");
    note(sc, "units ahead (seen at a fraction of a degree near the horizon); a quad in the plane");
    note(sc, "x = 0 and a quad in the plane y = 0.25 (both seen exactly edge-on); a sphere whose");
    note(sc, "top touches the centre ray's line y = 0.25 exactly; a sphere whose silhouette is");
    note(sc, "tangent to the ray of column 22 of the centre row; a sphere touching the floor;");
    note(sc, "a second light just above the floor far away (shadow rays skim the floor).");
    diffuse(sc, 0.8, 0.8, 0.8, 0.8);
    floor_quad(sc, 0, -6, 6, -60, 9.5);
    diffuse(sc, 0.9, 0.3, 0.25, 0.8);
    quad(sc, v3(0, 0, -10), v3(0, 0, -20), v3(0, 2, -20), v3(0, 2, -10));    /* plane x = 0 */
    diffuse(sc, 0.3, 0.5, 0.9, 0.8);
    quad(sc, v3(1, 0.25, -4), v3(3, 0.25, -4), v3(3, 0.25, -8), v3(1, 0.25, -8)); /* y = 0.25 */
    diffuse(sc, 0.95, 0.75, 0.2, 0.8);
    sphere(sc, v3(0, 0.125, -3), 0.125);
    /* Radius = distance from the centre to the ray of pixel (22, 31), as the renderer makes it. */
    double s = 2 * tan(angle / 2 * PI / 180) / (res - 1);
    double a = (22 - (res - 1) / 2.0) * s;
    vec3 d = vnorm(v3(a, 0, -1));
    vec3 centre = v3(-2, 0.25, -6);
    double r = vlen(vcross(vsub(centre, eye), d));
    diffuse(sc, 0.3, 0.8, 0.35, 0.8);
    sphere(sc, centre, r);
    diffuse(sc, 0.7, 0.4, 0.85, 0.8);
    sphere(sc, v3(1.5, 0.5, -12), 0.5);
    view(sc, eye, v3(0, 0.25, -10), v3(0, 1, 0), angle, res, res);
    background(sc, 0.2, 0.3, 0.5);
    ambient(sc, 0.1, 0.1, 0.1);
    add_light(sc, v3(-4, 6, 4), 0.8, 0.8, 0.8);
    add_light(sc, v3(10, 0.05, -30), 0.4, 0.4, 0.4);
}

static void build_tir(scene *sc, double factor)
{
    (void)factor;
    const double a = 30 * PI / 180;
    note(sc, "Total internal reflection: a glass slab (closed box of 6 quads, outward vertex order;");
    note(sc, "T 0.9, ior 1.5, 3.2 x 1.2 x 2.4, turned 30 degrees about y) above a checkered floor");
    note(sc, "of 36 quads, two spheres behind. Every ray that enters through the top and meets a");
    note(sc, "side face inside the box is totally reflected there (critical angle 41.8 degrees).");
    for (int j = 0; j < 6; ++j) {
        for (int i = 0; i < 6; ++i) {
            if ((i + j) % 2)
                diffuse(sc, 0.85, 0.85, 0.8, 0.8);
            else
                diffuse(sc, 0.7, 0.15, 0.15, 0.8);
            double x0 = -4.5 + 1.5 * i, z0 = -4.5 + 1.5 * j;
            floor_quad(sc, 0, x0, x0 + 1.5, z0, z0 + 1.5);
        }
    }
    diffuse(sc, 0.25, 0.75, 0.3, 0.8);
    sphere(sc, v3(-1.8, 0.7, -3.2), 0.7);
    diffuse(sc, 0.95, 0.8, 0.2, 0.8);
    sphere(sc, v3(2.0, 0.9, -2.8), 0.9);
    mat(sc, 0.95, 0.97, 1.0, 0.05, 0.1, 60, 0.9, 1.5);
    vec3 ex = v3(cos(a), 0, -sin(a)), ey = v3(0, 1, 0), ez = vcross(ex, ey);
    box(sc, v3(0, 1.6, 0), v3(1.6, 0.6, 1.2), ex, ey, ez);
    view(sc, v3(2.5, 4.5, 7), v3(0, 1.2, 0), v3(0, 1, 0), 0, 64, 64);
    frame_all(sc, 1.0);
    sc->angle = fmin(sc->angle, 50);
    background(sc, 0.08, 0.1, 0.2);
    ambient(sc, 0.12, 0.12, 0.12);
    add_light(sc, v3(-3, 8, 5), 0.9, 0.9, 0.9);
}

static void build_facing_mirrors(scene *sc, double factor)
{
    (void)factor;
    note(sc, "Two parallel mirror quads (Ks 1, Kd 0), 68 long, in the planes x = -1.5 and x = 1.5");
    note(sc, "facing each other, a diffuse sphere between them 20 ahead of the camera, which looks");
    note(sc, "down the corridor: the sphere repeats in the mirrors and rays bounce until the depth");
    note(sc, "limit. Mirror colour 0.2 times ambient 0.05 adds a little light per bounce.");
    mat(sc, 0.2, 0.2, 0.25, 0, 1, 0, 0, 1);
    quad(sc, v3(-1.5, -4, 8), v3(-1.5, -4, -60), v3(-1.5, 4, -60), v3(-1.5, 4, 8)); /* faces +x */
    quad(sc, v3(1.5, -4, -60), v3(1.5, -4, 8), v3(1.5, 4, 8), v3(1.5, 4, -60));     /* faces -x */
    diffuse(sc, 0.95, 0.55, 0.15, 0.85);
    sphere(sc, v3(0, 0, -12), 1);
    view(sc, v3(0.4, 0.8, 8), v3(0, 0, -12), v3(0, 1, 0), 50, 64, 64);
    background(sc, 0.1, 0.1, 0.15);
    ambient(sc, 0.05, 0.05, 0.05);
    add_light(sc, v3(0, 3, -4), 1, 1, 1);
}

static void build_empty(scene *sc, double factor)
{
    (void)factor;
    note(sc, "A view, a light and a background, and no objects: every pixel is the background.");
    view(sc, v3(0, 0, 5), v3(0, 0, 0), v3(0, 1, 0), 45, 32, 32);
    background(sc, 0.2, 0.3, 0.5);
    ambient(sc, 0.1, 0.1, 0.1);
    add_light(sc, v3(5, 5, 5), 1, 1, 1);
}

static void build_one_big_sphere(scene *sc, double factor)
{
    (void)factor;
    note(sc, "A single sphere of radius 10 is the whole object space: it lies in nearly every one");
    note(sc, "of the cells (all but those near the corners). Partly transparent (T 0.3, ior 1.3)");
    note(sc, "and reflective, so rays also run through its inside.");
    mat(sc, 0.9, 0.6, 0.3, 0.6, 0.15, 30, 0.3, 1.3);
    sphere(sc, v3(0, 0, 0), 10);
    view(sc, v3(0, 6, 35), v3(0, 0, 0), v3(0, 1, 0), 0, 48, 48);
    frame_all(sc, 1.1);
    background(sc, 0.1, 0.15, 0.3);
    ambient(sc, 0.1, 0.1, 0.1);
    add_light(sc, v3(-20, 30, 30), 1, 1, 1);
}

static void build_one_cell(scene *sc, double factor)
{
    (void)factor;
    note(sc, "50 spheres of radius 0.12 packed (fixed-seed LCG, no overlaps) within 0.9 of the");
    note(sc, "origin, plus one more at (100,100,100): the object space is about 101 wide, so its");
    note(sc, "24^3 cells are about 4.2 wide and all 50 clustered spheres lie in cell (0,0,0).");
    note(sc, "The far sphere is behind the camera.");
    vec3 c[50];
    int n = 0;
    lcg_seed(20240601);
    while (n < 50) {
        /* One call per statement: argument evaluation order is unspecified in C. */
        double px = 1.8 * lcg_next() - 0.9;
        double py = 1.8 * lcg_next() - 0.9;
        double pz = 1.8 * lcg_next() - 0.9;
        vec3 p = v3(px, py, pz);
        if (vlen(p) > 0.9)
            continue;
        int ok = 1;
        for (int k = 0; k < n && ok; ++k)
            if (vlen(vsub(p, c[k])) < 0.26)
                ok = 0;
        if (ok)
            c[n++] = q9v(p);
    }
    for (int k = 0; k < n; ++k) {
        const double *col = PALETTE6[k % 6];
        diffuse(sc, col[0], col[1], col[2], 0.8);
        sphere(sc, c[k], 0.12);
    }
    diffuse(sc, 0.9, 0.9, 0.9, 0.8);
    sphere(sc, v3(100, 100, 100), 0.12);
    view(sc, v3(-2.6, 1.8, -3.2), v3(0, 0, 0), v3(0, 1, 0), 30, 48, 48);
    background(sc, 0.05, 0.05, 0.1);
    ambient(sc, 0.1, 0.1, 0.1);
    add_light(sc, v3(-6, 8, -5), 1, 1, 1);
}

/* The same small scene at several scales; `factor` multiplies every position and length. */
static void build_scaled(scene *sc, double factor)
{
    char buf[40];
    note(sc, "A small scene (floor quad, three diffuse spheres, a glass sphere T 0.9 ior 1.5, a");
    note(sc, "mirror sphere Ks 0.9, one light) with every coordinate, radius, light position,");
    note(sc, "camera position and hither multiplied by %s; colours, directions and angle as in", 
         num(buf, sizeof buf, factor));
    note(sc, "scale-1. Numbers are the exact double products, printed to round-trip.");
    note(sc, "All scale-* images should equal scale-1's.");
    diffuse(sc, 0.8, 0.8, 0.75, 0.8);
    floor_quad(sc, 0, -4, 4, -4, 4);
    diffuse(sc, 0.9, 0.25, 0.2, 0.8);
    sphere(sc, v3(-2.0, 0.6, 0.6), 0.6);
    diffuse(sc, 0.25, 0.75, 0.3, 0.8);
    sphere(sc, v3(0.9, 0.4, 1.7), 0.4);
    diffuse(sc, 0.2, 0.4, 0.9, 0.8);
    sphere(sc, v3(-0.6, 0.5, -2.4), 0.5);
    mat(sc, 0.95, 0.97, 1.0, 0.05, 0.1, 60, 0.9, 1.5);
    sphere(sc, v3(-0.5, 0.9, 0.1), 0.9);
    mat(sc, 0.85, 0.85, 0.9, 0.1, 0.9, 60, 0, 1);
    sphere(sc, v3(1.8, 0.8, -1.0), 0.8);
    view(sc, v3(0.5, 2.6, 7.5), v3(0, 0.6, 0), v3(0, 1, 0), 45, 48, 48);
    background(sc, 0.1, 0.15, 0.3);
    ambient(sc, 0.1, 0.1, 0.1);
    add_light(sc, v3(3, 6, 4), 1, 1, 1);
}

static void build_tiny(scene *sc, int with_huge)
{
    const double u = 1e-6;
    note(sc, "A sphere of radius 1e-6 at (0, 1.5e-6, 0) over a 6e-6 square floor quad, lit so it");
    note(sc, "casts a shadow on it, seen close up (camera 1e-5 away, 24 degree view).");
    if (with_huge) {
        note(sc, "Plus one sphere of radius 0.5 behind the camera (nearest point at z = 1e-3):");
        note(sc, "the object space is about 1 wide, a million times the tiny sphere's radius.");
        note(sc, "All surfaces are diffuse and the light is on this side, so no ray or shadow ray");
        note(sc, "can reach it: the image must equal tiny-sphere-alone's.");
    } else {
        note(sc, "Identical to tiny-sphere without its huge far sphere: the images must be equal.");
    }
    diffuse(sc, 0.8, 0.8, 0.75, 0.8);
    floor_quad(sc, 0, -3 * u, 3 * u, -3 * u, 3 * u);
    diffuse(sc, 0.9, 0.3, 0.2, 0.8); /* no secondary rays: nothing could reach the far sphere */
    sphere(sc, v3(0, 1.5 * u, 0), 1 * u);
    if (with_huge) {
        diffuse(sc, 0.3, 0.3, 0.9, 0.8);
        sphere(sc, v3(0, 0, 0.501), 0.5);
    }
    view(sc, v3(0, 4 * u, 10 * u), v3(0, 1.2 * u, 0), v3(0, 1, 0), 24, 48, 48);
    sc->hither = 1e-9;
    background(sc, 0.1, 0.15, 0.3);
    ambient(sc, 0.1, 0.1, 0.1);
    add_light(sc, v3(2 * u, 8 * u, 3 * u), 1, 1, 1);
}
static void build_tiny_sphere(scene *sc, double factor) { (void)factor; build_tiny(sc, 1); }
static void build_tiny_alone(scene *sc, double factor) { (void)factor; build_tiny(sc, 0); }

/* A hemisphere of radius r on the plane y = c.y as `pp` patches with radial normals:
 * two bands of 4-vertex patches and a cap of triangles, 8 segments round. */
static void hemisphere_patches(scene *sc, vec3 c, double r)
{
    const int seg = 8;
    const double lat[4] = {0, 30, 60, 90};
    for (int b = 0; b < 3; ++b) {
        for (int k = 0; k < seg; ++k) {
            vec3 v[4], n[4];
            int m = 0;
            double lo = lat[b] * PI / 180, hi = lat[b + 1] * PI / 180;
            double a0 = 2 * PI * k / seg, a1 = 2 * PI * (k + 1) / seg;
            double pts[4][2] = {{lo, a0}, {lo, a1}, {hi, a1}, {hi, a0}};
            for (int q = 0; q < 4; ++q) {
                if (b == 2 && q == 3)
                    break; /* the pole: one vertex, a triangle */
                double la = pts[q][0], az = pts[q][1];
                n[m] = b == 2 && q == 2 ? v3(0, 1, 0)
                                        : v3(cos(la) * cos(az), sin(la), cos(la) * sin(az));
                v[m] = vadd(c, vmul(n[m], r));
                ++m;
            }
            /* Counter-clockwise seen from outside. */
            vec3 mid = v3(0, 0, 0);
            for (int q = 0; q < m; ++q)
                mid = vadd(mid, vmul(v[q], 1.0 / m));
            if (vdot(newell(m, v), vsub(mid, c)) < 0) {
                for (int q = 0; q < m / 2; ++q) {
                    vec3 t = v[q]; v[q] = v[m - 1 - q]; v[m - 1 - q] = t;
                    t = n[q]; n[q] = n[m - 1 - q]; n[m - 1 - q] = t;
                }
            }
            polygon_n(sc, m, v, n);
        }
    }
}

static void build_cones_and_patches(scene *sc, double factor)
{
    (void)factor;
    note(sc, "Every primitive: a floor quad (p 4); an open cone (c, base radius 1, apex radius");
    note(sc, "0.12); an open cylinder (c, both radii 0.75; its inside shows from above); a");
    note(sc, "hemisphere of 24 smooth patches (16 pp 4 + 8 pp 3, radial vertex normals); a concave");
    note(sc, "10-pointed star polygon (p 20) facing the camera.");
    diffuse(sc, 0.75, 0.75, 0.7, 0.8);
    floor_quad(sc, 0, -4.2, 4.2, -3, 2.2);
    mat(sc, 0.95, 0.55, 0.15, 0.8, 0.1, 20, 0, 1);
    cone(sc, v3(-2.6, 0, 0.3), 1.0, v3(-2.6, 2.2, 0.3), 0.12);
    mat(sc, 0.2, 0.7, 0.7, 0.8, 0.1, 20, 0, 1);
    cone(sc, v3(0, 0, 0.8), 0.75, v3(0, 1.4, 0.8), 0.75);
    mat(sc, 0.85, 0.3, 0.6, 0.7, 0.3, 40, 0, 1);
    hemisphere_patches(sc, v3(2.5, 0, 0.3), 1.1);
    diffuse(sc, 0.95, 0.85, 0.2, 0.8);
    vec3 star[20];
    for (int k = 0; k < 20; ++k) {
        double a = PI / 2 + 2 * PI * k / 20;
        double rad = (k % 2) ? 0.65 : 1.5;
        star[k] = v3(rad * cos(a), 2.3 + rad * sin(a), -2.2);
    }
    polygon(sc, 20, star);
    view(sc, v3(0.4, 3.6, 6.5), v3(0, 1.0, -0.5), v3(0, 1, 0), 54, 64, 64);
    background(sc, 0.1, 0.12, 0.25);
    ambient(sc, 0.1, 0.1, 0.1);
    add_light(sc, v3(-4, 7, 6), 0.8, 0.8, 0.8);
    add_light(sc, v3(5, 4, 3), 0.4, 0.4, 0.4);
}

static void build_one_pixel(scene *sc, double factor)
{
    (void)factor;
    note(sc, "Resolution 1 x 1: the single ray goes along the view direction and hits the centre");
    note(sc, "of a reflective sphere; a second sphere off the axis casts no shadow there.");
    mat(sc, 0.9, 0.3, 0.2, 0.8, 0.3, 30, 0, 1);
    sphere(sc, v3(0, 0, 0), 1);
    diffuse(sc, 0.2, 0.5, 0.9, 0.8);
    sphere(sc, v3(2, 0, -2), 0.7);
    view(sc, v3(0, 0, 5), v3(0, 0, 0), v3(0, 1, 0), 30, 1, 1);
    background(sc, 0.1, 0.15, 0.3);
    ambient(sc, 0.1, 0.1, 0.1);
    add_light(sc, v3(3, 4, 5), 1, 1, 1);
}

/* ---------------------------------------------------------------- table and main */

typedef struct {
    const char *name;
    const char *desc;
    void (*build)(scene *sc, double factor);
    double factor; /* scale applied when writing */
} scene_def;

static const scene_def SCENES[] = {
    {"paper-image1", "the paper's image 1: 369 recursively defined diffuse spheres, 144x144",
     build_paper_image1, 1},
    {"paper-image2", "the paper's image 2: glass and mirror sphere before 121 small spheres, "
                     "144x144", build_paper_image2, 1},
    {"axis-rays", "rays with zero direction components, along cell edges, parallel to faces",
     build_axis_rays, 1},
    {"grid-corners", "objects on the cell lattice; rays through cell edges and corners",
     build_grid_corners, 1},
    {"eye-inside", "the eye inside the object space, objects all around it", build_eye_inside, 1},
    {"light-inside", "a point light inside the object space, in a ring of spheres",
     build_light_inside, 1},
    {"grazing", "edge-on polygons, tangent rays on spheres, a floor at a very low angle",
     build_grazing, 1},
    {"tir", "total internal reflection inside a glass slab", build_tir, 1},
    {"facing-mirrors", "two parallel mirrors: rays bounce to the depth limit",
     build_facing_mirrors, 1},
    {"empty", "no objects: background only", build_empty, 1},
    {"one-big-sphere", "one sphere spanning the whole object space (nearly every cell)",
     build_one_big_sphere, 1},
    {"one-cell", "50 of 51 objects in one cell of the 24^3 grid", build_one_cell, 1},
    {"scale-1", "the scale test scene at scale 1", build_scaled, 1},
    {"scale-tiny", "the scale test scene times 1e-6", build_scaled, 1e-6},
    {"scale-huge", "the scale test scene times 1e6", build_scaled, 1e6},
    {"scale-pow2-tiny", "the scale test scene times 2^-20 (exact products)", build_scaled,
     1.0 / 1048576.0},
    {"scale-pow2-huge", "the scale test scene times 2^20 (exact products)", build_scaled,
     1048576.0},
    {"tiny-sphere", "a 1e-6 sphere close up, with a huge sphere making the space 1e6 larger",
     build_tiny_sphere, 1},
    {"tiny-sphere-alone", "tiny-sphere without the huge sphere (the images must be equal)",
     build_tiny_alone, 1},
    {"cones-and-patches", "every primitive: cone, cylinder, pp patches, concave polygon",
     build_cones_and_patches, 1},
    {"one-pixel", "a small scene rendered at 1x1", build_one_pixel, 1},
};
#define NSCENES ((int)(sizeof SCENES / sizeof SCENES[0]))

static int find_scene(const char *name)
{
    for (int i = 0; i < NSCENES; ++i)
        if (strcmp(SCENES[i].name, name) == 0)
            return i;
    return -1;
}

/* Writes OUTDIR/NAME.nff through NAME.nff.tmp; returns 0, or 1 after printing why not. */
static int write_one(const char *outdir, const scene_def *def)
{
    scene *sc = calloc(1, sizeof *sc);
    if (!sc) {
        fprintf(stderr, "torusrt-genscenes: out of memory\n");
        return 1;
    }
    sc->up = v3(0, 1, 0);
    def->build(sc, def->factor);
    if (sc->failed) {
        fprintf(stderr, "torusrt-genscenes: %s: could not build the scene (out of memory)\n",
                def->name);
        scene_free(sc);
        free(sc);
        return 1;
    }
    size_t len = strlen(outdir) + strlen(def->name) + 16;
    char *path = malloc(len), *tmp = malloc(len);
    int rc = 1;
    if (!path || !tmp) {
        fprintf(stderr, "torusrt-genscenes: out of memory\n");
        goto done;
    }
    snprintf(path, len, "%s/%s.nff", outdir, def->name);
    snprintf(tmp, len, "%s/%s.nff.tmp", outdir, def->name);
    FILE *f = fopen(tmp, "wb");
    if (!f) {
        fprintf(stderr, "torusrt-genscenes: cannot write %s: ", tmp);
        perror(NULL);
        goto done;
    }
    writer wr = {f, def->factor};
    write_scene(&wr, def->name, def->desc, sc);
    int bad = ferror(f);
    if (fclose(f) != 0 || bad) {
        fprintf(stderr, "torusrt-genscenes: error writing %s\n", tmp);
        remove(tmp);
        goto done;
    }
    if (rename(tmp, path) != 0) {
        fprintf(stderr, "torusrt-genscenes: cannot rename %s to %s: ", tmp, path);
        perror(NULL);
        remove(tmp);
        goto done;
    }
    rc = 0;
done:
    free(path);
    free(tmp);
    scene_free(sc);
    free(sc);
    return rc;
}

static void usage(FILE *f)
{
    fputs("usage: torusrt-genscenes OUTDIR [NAME...]\n"
          "       torusrt-genscenes --list | --help\n"
          "Writes torusrt's scenes as OUTDIR/NAME.nff (all of them, or only the NAMEs given).\n"
          "OUTDIR must exist. Output is deterministic and byte-reproducible.\n"
          "  --list   print every scene name with a one-line description\n"
          "  --help   print this message\n",
          f);
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        usage(stderr);
        return 2;
    }
    if (strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0) {
        usage(stdout);
        return 0;
    }
    if (strcmp(argv[1], "--list") == 0) {
        for (int i = 0; i < NSCENES; ++i)
            printf("%-18s %s\n", SCENES[i].name, SCENES[i].desc);
        return 0;
    }
    if (argv[1][0] == '-') {
        fprintf(stderr, "torusrt-genscenes: unknown option '%s'\n", argv[1]);
        usage(stderr);
        return 2;
    }
    const char *outdir = argv[1];
    for (int a = 2; a < argc; ++a) {
        if (find_scene(argv[a]) < 0) {
            fprintf(stderr, "torusrt-genscenes: unknown scene '%s' (see --list)\n", argv[a]);
            return 2;
        }
    }
    int failed = 0, written = 0;
    if (argc == 2) {
        for (int i = 0; i < NSCENES; ++i) {
            if (write_one(outdir, &SCENES[i]) != 0)
                ++failed;
            else
                ++written;
        }
    } else {
        for (int a = 2; a < argc; ++a) {
            if (write_one(outdir, &SCENES[find_scene(argv[a])]) != 0)
                ++failed;
            else
                ++written;
        }
    }
    printf("torusrt-genscenes: wrote %d scene%s to %s\n", written, written == 1 ? "" : "s",
           outdir);
    return failed ? 1 : 0;
}
