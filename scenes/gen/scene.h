/* scene.h - torusrt-genscenes' scene in memory and the calls every scene builder uses.
 *
 * Usage:
 *   scene *sc = calloc(1, sizeof *sc);   // zeroed; set sc->up before building
 *   note(sc, "what the scene is");       // one "# " header line
 *   diffuse(sc, 0.8, 0.8, 0.8, 0.8);     // material for the objects that follow
 *   sphere(sc, v3(0, 0, 0), 1);
 *   view(sc, from, at, v3(0, 1, 0), 0, 64, 64);
 *   frame_all(sc, 1.02);                 // fit the angle to the objects
 *   ...; scene_free(sc); free(sc);
 *
 * Positions and lengths are rounded to 9 significant digits (q9) as they are stored. The
 * calls return nothing: running out of memory sets sc->failed, which the caller checks.
 */
#ifndef GEN_SCENE_H
#define GEN_SCENE_H

#include <math.h>

#define PI 3.14159265358979323846

/* ---------------------------------------------------------------- vectors */

typedef struct {
    double x, y, z;
} vec3;

static inline vec3 v3(double x, double y, double z)
{
    vec3 r = {x, y, z};
    return r;
}
static inline vec3 vadd(vec3 a, vec3 b) { return v3(a.x + b.x, a.y + b.y, a.z + b.z); }
static inline vec3 vsub(vec3 a, vec3 b) { return v3(a.x - b.x, a.y - b.y, a.z - b.z); }
static inline vec3 vmul(vec3 a, double s) { return v3(a.x * s, a.y * s, a.z * s); }
static inline double vdot(vec3 a, vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static inline vec3 vcross(vec3 a, vec3 b)
{
    return v3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
static inline double vlen(vec3 a) { return sqrt(vdot(a, a)); }
static inline vec3 vnorm(vec3 a) { return vmul(a, 1.0 / vlen(a)); }

/* ---------------------------------------------------------------- scene in memory */

typedef struct {
    double r, g, b, kd, ks, shine, t, ior;
} material;

typedef enum { IT_MATERIAL, IT_SPHERE, IT_POLYGON, IT_PATCH, IT_CONE } item_kind;

typedef struct {
    item_kind kind;
    material mat;                    /* IT_MATERIAL */
    vec3 centre;                     /* IT_SPHERE */
    double radius;                   /* IT_SPHERE */
    vec3 base, apex;                 /* IT_CONE: axis end points */
    double base_radius, apex_radius; /* IT_CONE */
    int nverts;                      /* IT_POLYGON, IT_PATCH */
    vec3 *verts;                     /* IT_POLYGON, IT_PATCH: nverts points */
    vec3 *normals;                   /* IT_PATCH: nverts unit vertex normals */
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
    double angle; /* degrees */
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
    int failed;    /* out of memory while building */
    double factor; /* the scale the scene is written at (set before its builder runs) */
} scene;

/* ---------------------------------------------------------------- building */

/* Frees the scene's items (not the scene itself). */
void scene_free(scene *sc);

/* Adds a header comment line (printf format); lines past MAX_NOTES are dropped. */
void note(scene *sc, const char *fmt, ...);

/* Sets the `v` block; `from` and `at` are rounded, hither is 1e-3. */
void view(scene *sc, vec3 from, vec3 at, vec3 up, double angle, int w, int h);
void background(scene *sc, double r, double g, double b);
/* Sets torusrt's `am` ambient light. */
void ambient(scene *sc, double r, double g, double b);
/* Adds a point light; lights past MAX_LIGHTS are dropped. */
void add_light(scene *sc, vec3 pos, double r, double g, double b);

/* `f r g b Kd Ks Shine T ior` for the objects that follow. */
void mat(scene *sc, double r, double g, double b, double kd, double ks, double shine, double t, double ior);
/* A material with Ks = 0, Shine = 0, T = 0, ior = 1. */
void diffuse(scene *sc, double r, double g, double b, double kd);

void sphere(scene *sc, vec3 c, double radius);
/* An open cone (or cylinder) between two axis end points. */
void cone(scene *sc, vec3 base, double base_radius, vec3 apex, double apex_radius);

/* Newell's normal of a vertex loop (not normalised). */
vec3 newell(int n, const vec3 *v);
/* A `p` (normals == NULL) or `pp` polygon; vertices are copied, normals normalised. */
void polygon_n(scene *sc, int n, const vec3 *v, const vec3 *normals);
void polygon(scene *sc, int n, const vec3 *v);
/* Quad a, b, c, d (in that order: counter-clockwise seen from the front). */
void quad(scene *sc, vec3 a, vec3 b, vec3 c, vec3 d);
/* Quad in the plane y = y0 over [x0,x1] x [z0,z1], front facing +y. */
void floor_quad(scene *sc, double y0, double x0, double x1, double z0, double z1);
/* Closed box of six quads with outward (counter-clockwise from outside) vertex order;
 * the box is [-h, h] in its own frame (ex, ey, ez orthonormal, right-handed), centred at c. */
void box(scene *sc, vec3 c, vec3 h, vec3 ex, vec3 ey, vec3 ez);

/* Sets sc->angle to the smallest multiple of 0.5 degree whose picture holds every object
 * (bounding spheres of cones, polygon vertices) with `margin` (e.g. 1.05) to spare; call it
 * after view(). */
void frame_all(scene *sc, double margin);

#endif
