/* stiff_scenes.c - the small stiff and extreme scenes (docs/design.md section 9): axis-aligned and
 * lattice-aligned rays, the eye or a light inside the object space, grazing hits, total
 * internal reflection, facing mirrors, empty and one-object spaces, extreme scales, every
 * primitive, a 1 x 1 image. */
#include "builders.h"
#include "nff_writer.h"

void build_axis_rays(scene *sc)
{
    note(sc, "33x33 camera looking exactly down -z with up +y: the centre row's rays have a zero");
    note(sc, "y component, the centre column's a zero x component, the centre ray is (0,0,-1).");
    note(sc, "The object space is symmetric in x and y, so the centre ray runs along the cell edge");
    note(sc, "x = y = 0. Sphere on the axis (reflective: its centre reflection goes back along +z);");
    note(sc, "backdrop z = -4, floor y = -5 and wall x = -5 are axis-aligned quads, parallel to the");
    note(sc, "centre row/column rays. One light on the axis, one off it.");
    mat(sc, 0.9, 0.25, 0.2, 0.7, 0.3, 30, 0, 1);
    sphere(sc, v3(0, 0, 0), 1.5);
    diffuse(sc, 0.6, 0.65, 0.8, 0.8);
    quad(sc, v3(-5, -5, -4), v3(5, -5, -4), v3(5, 5, -4), v3(-5, 5, -4)); /* z = -4, faces +z */
    diffuse(sc, 0.85, 0.85, 0.8, 0.8);
    floor_quad(sc, -5, -5, 5, -4, 6); /* y = -5, faces +y */
    diffuse(sc, 0.4, 0.75, 0.4, 0.8);
    quad(sc, v3(-5, -5, -4), v3(-5, 5, -4), v3(-5, 5, 6), v3(-5, -5, 6)); /* x = -5, faces +x */
    view(sc, v3(0, 0, 10), v3(0, 0, 0), v3(0, 1, 0), 40, 33, 33);
    background(sc, 0.1, 0.1, 0.15);
    ambient(sc, 0.1, 0.1, 0.1);
    add_light(sc, v3(0, 0, 6), 0.35, 0.35, 0.35);
    add_light(sc, v3(3, 4, 8), 0.7, 0.7, 0.7);
}

void build_grid_corners(scene *sc)
{
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
    floor_quad(sc, -12, -12, 12, -12, 12); /* y */
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

static const double PALETTE6[6][3] = {{0.9, 0.25, 0.2},  {0.95, 0.65, 0.15}, {0.85, 0.85, 0.2},
                                      {0.25, 0.75, 0.3}, {0.2, 0.45, 0.9},   {0.65, 0.3, 0.85}};

void build_eye_inside(scene *sc)
{
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

void build_light_inside(scene *sc)
{
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

void build_grazing(scene *sc)
{
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
    quad(sc, v3(0, 0, -10), v3(0, 0, -20), v3(0, 2, -20), v3(0, 2, -10)); /* plane x = 0 */
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

void build_tir(scene *sc)
{
    const double a = 30 * PI / 180;
    note(sc, "Total internal reflection: a glass slab (closed box of 6 quads, outward vertex order;");
    note(sc, "T 0.9, ior 1.5, 3.2 x 1.2 x 2.4, turned 30 degrees about y) above a checkered floor");
    note(sc, "of 36 quads, two spheres behind. Every ray that enters through the top and meets a");
    note(sc, "side face inside the box is totally reflected there (critical angle 41.8 degrees).");
    for (int j = 0; j < 6; ++j) {
        for (int i = 0; i < 6; ++i) {
            if ((i + j) % 2) diffuse(sc, 0.85, 0.85, 0.8, 0.8);
            else diffuse(sc, 0.7, 0.15, 0.15, 0.8);
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

void build_facing_mirrors(scene *sc)
{
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

void build_empty(scene *sc)
{
    note(sc, "A view, a light and a background, and no objects: every pixel is the background.");
    view(sc, v3(0, 0, 5), v3(0, 0, 0), v3(0, 1, 0), 45, 32, 32);
    background(sc, 0.2, 0.3, 0.5);
    ambient(sc, 0.1, 0.1, 0.1);
    add_light(sc, v3(5, 5, 5), 1, 1, 1);
}

void build_one_big_sphere(scene *sc)
{
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

void build_one_cell(scene *sc)
{
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
        if (vlen(p) > 0.9) continue;
        int ok = 1;
        for (int k = 0; k < n && ok; ++k)
            if (vlen(vsub(p, c[k])) < 0.26) ok = 0;
        if (ok) c[n++] = q9v(p);
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

/* The same small scene at several scales; sc->factor multiplies every position and length. */
void build_scaled(scene *sc)
{
    char buf[40];
    note(sc, "A small scene (floor quad, three diffuse spheres, a glass sphere T 0.9 ior 1.5, a");
    note(sc, "mirror sphere Ks 0.9, one light) with every coordinate, radius, light position,");
    note(sc, "camera position and hither multiplied by %s; colours, directions and angle as in",
         num(buf, sizeof buf, sc->factor));
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
void build_tiny_sphere(scene *sc) { build_tiny(sc, 1); }
void build_tiny_alone(scene *sc) { build_tiny(sc, 0); }

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
                if (b == 2 && q == 3) break; /* the pole: one vertex, a triangle */
                double la = pts[q][0], az = pts[q][1];
                n[m] = b == 2 && q == 2 ? v3(0, 1, 0) : v3(cos(la) * cos(az), sin(la), cos(la) * sin(az));
                v[m] = vadd(c, vmul(n[m], r));
                ++m;
            }
            /* Counter-clockwise seen from outside. */
            vec3 mid = v3(0, 0, 0);
            for (int q = 0; q < m; ++q) mid = vadd(mid, vmul(v[q], 1.0 / m));
            if (vdot(newell(m, v), vsub(mid, c)) < 0) {
                for (int q = 0; q < m / 2; ++q) {
                    vec3 t = v[q];
                    v[q] = v[m - 1 - q];
                    v[m - 1 - q] = t;
                    t = n[q];
                    n[q] = n[m - 1 - q];
                    n[m - 1 - q] = t;
                }
            }
            polygon_n(sc, m, v, n);
        }
    }
}

void build_cones_and_patches(scene *sc)
{
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

void build_one_pixel(scene *sc)
{
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

void build_opposing_normals(scene *sc)
{
    note(sc, "A lid of 12 pp triangles around a raised pole whose vertex normals nearly cancel, as");
    note(sc, "at the poles of Haines' teapot: on each triangle the pole's normal is the exact");
    note(sc, "opposite of one rim normal (e.g. (-0.90, -0.43, 0) beside (0.90, 0.43, 0)), so the");
    note(sc, "interpolated sum passes through zero and turns to the back of the face. Lit from");
    note(sc, "above, the lid must shade smoothly: no speckles.");
    diffuse(sc, 0.6, 0.6, 0.65, 0.8);
    floor_quad(sc, -0.05, -2, 2, -2, 2);
    mat(sc, 0.9, 0.6, 0.3, 0.8, 0, 100000, 0, 0);
    const int seg = 12;
    for (int k = 0; k < seg; ++k) {
        double a0 = 2 * PI * k / seg, a1 = 2 * PI * (k + 1) / seg;
        vec3 r0 = v3(0.90 * cos(a0), 0.43, 0.90 * sin(a0));
        vec3 r1 = v3(0.90 * cos(a1), 0.43, 0.90 * sin(a1));
        /* Counter-clockwise seen from above: pole, rim at a1, rim at a0. */
        vec3 v[3] = {v3(0, 0.3, 0), v3(cos(a1), 0, sin(a1)), v3(cos(a0), 0, sin(a0))};
        vec3 n[3] = {vmul(r0, -1), r1, r0};
        polygon_n(sc, 3, v, n);
    }
    view(sc, v3(0.3, 3.2, 2.4), v3(0, 0.1, 0), v3(0, 1, 0), 40, 48, 48);
    background(sc, 0.1, 0.12, 0.25);
    ambient(sc, 0.1, 0.1, 0.1);
    add_light(sc, v3(-2, 6, 3), 0.8, 0.8, 0.8);
    add_light(sc, v3(3, 5, -1), 0.4, 0.4, 0.4);
}
