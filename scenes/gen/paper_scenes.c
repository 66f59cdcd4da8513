/* paper_scenes.c - the paper's two 144 x 144 images, reconstructed from its description:
 * image 1 (369 recursively defined diffuse spheres) and image 2 (a glass and a mirror sphere
 * before 121 small spheres). */
#include "builders.h"
#include "nff_writer.h"

/* Image 1's two-level flake: a sphere of radius R, 8 children of radius R/2 along the
 * cube-corner directions, 4 grandchildren of radius R/4 on each child (41 spheres); `scale`
 * multiplies the radii, the centres stay where R = 1 puts them. */
static void flake(scene *sc, vec3 centre, const double bc[3], double scale)
{
    const double R = 1.0;          /* radius of a group's big sphere */
    const double child_dist = 1.6; /* child centre from its parent's centre, x parent radius */
    diffuse(sc, bc[0], bc[1], bc[2], 0.8);
    sphere(sc, centre, R * scale);

    vec3 child_centre[8], child_dir[8];
    for (int k = 0; k < 8; ++k) {
        vec3 d = vnorm(v3((k & 1) ? 1 : -1, (k & 2) ? 1 : -1, (k & 4) ? 1 : -1));
        child_dir[k] = d;
        child_centre[k] = vadd(centre, vmul(d, child_dist * R));
    }
    diffuse(sc, 0.95, 0.8, 0.45, 0.8);
    for (int k = 0; k < 8; ++k) sphere(sc, child_centre[k], R / 2 * scale);

    diffuse(sc, 0.92, 0.92, 0.95, 0.8);
    for (int k = 0; k < 8; ++k) {
        vec3 d = child_dir[k];
        vec3 e1 = vnorm(vcross(d, v3(0, 1, 0)));
        vec3 e2 = vcross(d, e1);
        for (int j = 0; j < 4; ++j) {
            double phi = (45.0 + 90.0 * j) * PI / 180;
            vec3 side = vadd(vmul(e1, cos(phi)), vmul(e2, sin(phi)));
            vec3 gdir = vadd(vmul(d, 0.5), vmul(side, sqrt(3.0) / 2));
            sphere(sc, vadd(child_centre[k], vmul(gdir, child_dist * R / 2)), R / 4 * scale);
        }
    }
}

static void cube_of_flakes(scene *sc, double scale);
static void tree_of_spheres(scene *sc, double scale);

static const double big_colour[3][3] = {{0.85, 0.22, 0.18}, {0.18, 0.42, 0.85}, {0.22, 0.68, 0.32}};

/* Up to three point lights: the first `count` of `pos`/`rgb`, their intensities scaled per
 * channel so that they add up to what the first two add up to (the unfitted pair): the count
 * moves the work (one shadow packet per light at a hit), not the picture's brightness. */
static void lights(scene *sc, int count, const vec3 pos[3], const double rgb[3][3])
{
    for (int k = 0; k < count; ++k) {
        double c[3];
        for (int ch = 0; ch < 3; ++ch) {
            double pair = rgb[0][ch] + rgb[1][ch], chosen = 0;
            for (int j = 0; j < count; ++j) chosen += rgb[j][ch];
            c[ch] = count == 2 ? rgb[k][ch] : q9(rgb[k][ch] * pair / chosen);
        }
        add_light(sc, pos[k], c[0], c[1], c[2]);
    }
}

/* Image 1's camera, lights and background, shared by its layouts: `n_lights` of the key, the
 * fill and a light above the scene; the view angle framing every sphere with `margin`. */
static void image1_setting(scene *sc, int n_lights, double margin)
{
    static const vec3 pos[3] = {{-20, 25, 30}, {25, 5, 20}, {0, 30, 0}};
    static const double rgb[3][3] = {{0.85, 0.85, 0.85}, {0.4, 0.4, 0.45}, {0.4, 0.4, 0.45}};
    view(sc, v3(4, 5, 30), v3(0, 0, 0), v3(0, 1, 0), 0, 144, 144);
    frame_all(sc, margin);
    background(sc, 0.04, 0.04, 0.08);
    ambient(sc, 0.1, 0.1, 0.1);
    lights(sc, n_lights, pos, rgb);
}

/* Nine flakes on the 3 x 3 grid of x and y, 5 apart; column gx at z = z_step * (gx - 1). */
static void flake_grid(scene *sc, double z_step, double scale)
{
    const double spacing = 5.0; /* between group centres on the 3 x 3 grid */
    for (int gy = 0; gy < 3; ++gy)
        for (int gx = 0; gx < 3; ++gx)
            flake(sc, v3(spacing * (gx - 1), spacing * (1 - gy), z_step == 0.0 ? 0.0 : z_step * (gx - 1)),
                  big_colour[(gy * 3 + gx) % 3], scale);
}

/* Image 1: nine copies of a two-level recursive "flake" of diffuse spheres, the grid's columns at
 * z = -5, 0 and +5 (the layout the fit chose, docs/fidelity.md). */
void build_paper_image1(scene *sc)
{
    note(sc, "The paper's image 1: 369 diffuse spheres, large and small, defined recursively.");
    note(sc, "Recursion: 9 groups on a 3x3 grid of x and y (centres 5 apart), the grid's three");
    note(sc, "columns at z = -5, 0 and +5 (the planar-z layout of docs/fidelity.md); each group");
    note(sc, "is a sphere of radius 1, 8 children of radius 1/2 centred 1.6 x 1 from it along the");
    note(sc, "cube-corner directions (+-1,+-1,+-1)/sqrt(3), and on each child 4 grandchildren of");
    note(sc, "radius 1/4 centred 1.6 x 1/2 from it, tilted 60 degrees off the child's outward");
    note(sc, "direction at azimuths 45+90k degrees: 9 x (1 + 8 + 8 x 4) = 9 x 41 = 369 spheres.");
    note(sc, "All diffuse (Ks = 0, T = 0); two lights, ambient 0.1; angle fitted to frame all.");
    paper_variant v = paper_variant_default(1);
    build_image1_layout(sc, &v);
}

/* Image 1, planar-z layout under its own name: the image the round-one fit chose, kept selectable
 * whatever scenes/paper-image1.nff holds. */
void build_paper_image1_planar_z(scene *sc)
{
    note(sc, "Image 1, planar-z layout (docs/readings.md): nine flakes of 41 spheres on a 3x3 grid");
    note(sc, "of x and y (centres 5 apart), the grid's three columns at z = -5, 0 and +5; radii 1,");
    note(sc, "1/2 and 1/4; two lights, ambient 0.1, framed with margin 1.03: 369 spheres.");
    paper_variant v = paper_variant_default(1);
    v.layout = PAPER_PLANAR_Z;
    build_image1_layout(sc, &v);
}

/* Image 1, planar layout: the nine flakes in the plane z = 0. */
void build_paper_image1_planar(scene *sc)
{
    note(sc, "Image 1, planar layout (docs/fidelity.md): paper-image1's nine flakes of 41 spheres");
    note(sc, "with the whole 3x3 grid in the plane z = 0: 369 spheres.");
    paper_variant v = paper_variant_default(1);
    v.layout = PAPER_PLANAR;
    build_image1_layout(sc, &v);
}

/* Image 1, cube layout: the groups repeat the flake's 1 + 8 recursion. */
void build_paper_image1_cube(scene *sc)
{
    note(sc, "Image 1, cube layout (docs/fidelity.md): paper-image1's flake of 41 spheres at the");
    note(sc, "centre and at the eight corners (+-5,+-5,+-5) of a cube: 9 x 41 = 369 spheres.");
    paper_variant v = paper_variant_default(1);
    v.layout = PAPER_CUBE;
    build_image1_layout(sc, &v);
}

static void cube_of_flakes(scene *sc, double scale)
{
    flake(sc, v3(0, 0, 0), big_colour[0], scale);
    for (int k = 0; k < 8; ++k)
        flake(sc, v3((k & 1) ? 5 : -5, (k & 2) ? 5 : -5, (k & 4) ? 5 : -5), big_colour[1 + k % 2], scale);
}

/* Two unit vectors perpendicular to d and to each other. */
static void perpendiculars(vec3 d, vec3 *e1, vec3 *e2)
{
    vec3 helper = fabs(d.y) < 0.9 ? v3(0, 1, 0) : v3(1, 0, 0);
    *e1 = vnorm(vcross(d, helper));
    *e2 = vcross(d, *e1);
}

/* Direction tilted `tilt` degrees off d at azimuth `azimuth` degrees. */
static vec3 tilted(vec3 d, double tilt, double azimuth)
{
    vec3 e1, e2;
    perpendiculars(d, &e1, &e2);
    double t = tilt * PI / 180, a = azimuth * PI / 180;
    vec3 side = vadd(vmul(e1, cos(a)), vmul(e2, sin(a)));
    return vnorm(vadd(vmul(d, cos(t)), vmul(side, sin(t))));
}

/* Image 1, tree layout: one four-level sphereflake-like tree. */
void build_paper_image1_tree(scene *sc)
{
    note(sc, "Image 1, tree layout (docs/fidelity.md): one recursive tree, 1 + 8 + 72 + 288 = 369");
    note(sc, "diffuse spheres. Root radius 4; 8 children of radius 2 centred 1.6 x 4 from it along");
    note(sc, "the cube-corner directions; on each child 9 grandchildren of radius 1 centred 1.6 x 2");
    note(sc, "from it (one along the child's outward direction, four tilted 60 degrees off it at");
    note(sc, "azimuths 90k, four tilted 100 degrees at azimuths 45+90k); on each grandchild 4 of");
    note(sc, "radius 1/2 centred 1.6 x 1 from it, tilted 60 degrees at azimuths 45+90k.");
    paper_variant v = paper_variant_default(1);
    v.layout = PAPER_TREE;
    build_image1_layout(sc, &v);
}

/* The tree's spheres; `scale` multiplies the radii, the centres stay. */
static void tree_of_spheres(scene *sc, double scale)
{
    const double R = 4.0, dist = 1.6; /* root radius; child centre at 1.6 x the parent's radius */
    diffuse(sc, big_colour[0][0], big_colour[0][1], big_colour[0][2], 0.8);
    sphere(sc, v3(0, 0, 0), R * scale);
    vec3 c1[8], d1[8], c2[72], d2[72];
    for (int k = 0; k < 8; ++k) {
        d1[k] = vnorm(v3((k & 1) ? 1 : -1, (k & 2) ? 1 : -1, (k & 4) ? 1 : -1));
        c1[k] = vmul(d1[k], dist * R);
    }
    diffuse(sc, 0.95, 0.8, 0.45, 0.8);
    for (int k = 0; k < 8; ++k) sphere(sc, c1[k], R / 2 * scale);
    for (int k = 0; k < 8; ++k)
        for (int j = 0; j < 9; ++j) {
            vec3 d = j == 0  ? d1[k]
                     : j < 5 ? tilted(d1[k], 60, 90.0 * (j - 1))
                             : tilted(d1[k], 100, 45 + 90.0 * (j - 5));
            d2[9 * k + j] = d;
            c2[9 * k + j] = vadd(c1[k], vmul(d, dist * R / 2));
        }
    diffuse(sc, big_colour[1][0], big_colour[1][1], big_colour[1][2], 0.8);
    for (int i = 0; i < 72; ++i) sphere(sc, c2[i], R / 4 * scale);
    diffuse(sc, 0.92, 0.92, 0.95, 0.8);
    for (int i = 0; i < 72; ++i)
        for (int j = 0; j < 4; ++j)
            sphere(sc, vadd(c2[i], vmul(tilted(d2[i], 60, 45 + 90.0 * j), dist * R / 4)), R / 8 * scale);
}

void build_image1_layout(scene *sc, const paper_variant *v)
{
    switch (v->layout) {
    case PAPER_PLANAR: flake_grid(sc, 0.0, v->scale); break;
    case PAPER_CUBE: cube_of_flakes(sc, v->scale); break;
    case PAPER_TREE: tree_of_spheres(sc, v->scale); break;
    default: flake_grid(sc, 5.0, v->scale); break;
    }
    image1_setting(sc, v->lights, v->margin);
}

/* Image 2's spheres and setting: the glass and the mirror sphere (radius r, centres at
 * x = -+(r + 0.3), y = r + 0.5), then the 121 small ones, on the horizontal plane y = 0 (floor)
 * or on the vertical plane z = -7 (wall); the camera; `n_lights` of the two lights and one
 * above the plane; the view angle framing every sphere with `margin`. */
static void image2(scene *sc, int wall, vec3 from, vec3 at, const paper_variant *v)
{
    static const vec3 pos[3] = {{-10, 18, 14}, {12, 10, 6}, {0, 20, -6}};
    static const double rgb[3][3] = {{0.8, 0.8, 0.8}, {0.45, 0.45, 0.5}, {0.45, 0.45, 0.5}};
    double r = v->big_radius;
    mat(sc, 0.95, 0.97, 1.0, 0.05, 0.1, 60, 0.9, 1.5);
    sphere(sc, v3(q9(-(r + 0.3)), q9(r + 0.5), -2.0), r);
    mat(sc, 0.85, 0.85, 0.9, 0.1, 0.9, 60, 0, 1);
    sphere(sc, v3(q9(r + 0.3), q9(r + 0.5), -2.0), r);
    for (int j = 0; j < 11; ++j) {
        for (int i = 0; i < 11; ++i) {
            diffuse(sc, q9(0.9 - 0.06 * i), q9(0.3 + 0.05 * j), q9(0.25 + 0.065 * i), 0.85);
            vec3 c = wall ? v3(1.5 * (i - 5), 2.5 + 1.5 * (5 - j), -7.0) : v3(1.5 * (i - 5), 0, -1.5 * j);
            sphere(sc, c, 0.5);
        }
    }
    view(sc, from, at, v3(0, 1, 0), 0, 144, 144);
    frame_all(sc, v->margin);
    background(sc, 0.12, 0.16, 0.32);
    ambient(sc, 0.1, 0.1, 0.1);
    lights(sc, v->lights, pos, rgb);
}

void build_image2_plane(scene *sc, const paper_variant *v)
{
    if (v->layout == PAPER_WALL) image2(sc, 1, v3(0, 4, 14), v3(0, 2.5, -4), v);
    else image2(sc, 0, v3(0, 15, 10), v3(0, 0.5, -6), v);
}

paper_variant paper_variant_default(int image)
{
    paper_variant v = {image, image == 1 ? PAPER_PLANAR_Z : PAPER_FLOOR, 1.0, 2.0, 2, image == 1 ? 1.03 : 1.02};
    return v;
}

/* Image 2: a glass and a mirror sphere in front of an 11 x 11 plane of small spheres. */
void build_paper_image2(scene *sc)
{
    note(sc, "The paper's image 2: one large transparent sphere (T 0.9, ior 1.5) and one large");
    note(sc, "mirror sphere (Ks 0.9) side by side in front, 121 small diffuse spheres (radius 0.5,");
    note(sc, "11 x 11, 1.5 apart) laid out in the horizontal plane y = 0 reaching behind them;");
    note(sc, "123 objects. Colour of the small spheres shades with column and row.");
    note(sc, "The camera looks down on the plane so it shows behind, through and in the big ones.");
    paper_variant v = paper_variant_default(2);
    build_image2_plane(sc, &v);
}

/* Image 2, floor arrangement under its own name: the image round one used, kept selectable
 * whatever scenes/paper-image2.nff holds. */
void build_paper_image2_floor(scene *sc)
{
    note(sc, "Image 2, floor arrangement (docs/readings.md): a glass and a mirror sphere (radius 2)");
    note(sc, "in front of 121 small diffuse spheres (radius 0.5, 11 x 11, 1.5 apart) in the");
    note(sc, "horizontal plane y = 0; two lights, framed with margin 1.02; 123 objects.");
    paper_variant v = paper_variant_default(2);
    v.layout = PAPER_FLOOR;
    build_image2_plane(sc, &v);
}

/* Image 2, wall arrangement: the 121 small spheres on a vertical plane behind the big ones. */
void build_paper_image2_wall(scene *sc)
{
    note(sc, "Image 2, wall arrangement (docs/fidelity.md): paper-image2's glass and mirror spheres");
    note(sc, "(radius 2) in front of its 121 small diffuse spheres (radius 0.5, 11 x 11, 1.5 apart)");
    note(sc, "standing in the vertical plane z = -7 behind them, facing the eye; 123 objects.");
    paper_variant v = paper_variant_default(2);
    v.layout = PAPER_WALL;
    build_image2_plane(sc, &v);
}

/* Orbiting mirror: image 2 whose mirror sphere circles the glass sphere (the motion is
 * written by write_orbiting_mirror_motion). The view is framed to hold the mirror sphere at
 * every quarter of its orbit. */
void build_orbiting_mirror(scene *sc)
{
    note(sc, "Image 2 with a moving mirror (docs/scenes.md): paper-image2's objects, the mirror");
    note(sc, "sphere (object 1) circling the glass sphere (object 0) about the vertical axis through");
    note(sc, "its centre, once in 64 frames (scenes/orbiting-mirror.motion); 123 objects.");
    paper_variant v = paper_variant_default(2);
    build_image2_plane(sc, &v);
    int keep_items = sc->nitems, keep_objects = sc->nobjects;
    /* The mirror's centre turned by 90, 180 and 270 degrees about the glass sphere's axis. */
    const vec3 quarter[3] = {v3(-2.3, 2.5, -6.6), v3(-6.9, 2.5, -2.0), v3(-2.3, 2.5, 2.6)};
    for (int k = 0; k < 3; ++k) sphere(sc, quarter[k], 2.0);
    frame_all(sc, 1.02);
    sc->nitems = keep_items; /* the framing spheres are not part of the scene */
    sc->nobjects = keep_objects;
}
