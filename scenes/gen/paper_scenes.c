/* paper_scenes.c - the paper's two 144 x 144 images, reconstructed from its description:
 * image 1 (369 recursively defined diffuse spheres) and image 2 (a glass and a mirror sphere
 * before 121 small spheres). */
#include "builders.h"
#include "nff_writer.h"

/* Image 1: nine copies of a two-level recursive "flake" of diffuse spheres. */
void build_paper_image1(scene *sc, double factor)
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
void build_paper_image2(scene *sc, double factor)
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
