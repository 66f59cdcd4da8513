/* builders.h - one builder per scene, listed in gen_scenes.c's table.
 *
 * Each fills a zeroed scene (with sc->up and sc->factor set) through scene.h; `sc->factor` is
 * the scale the scene is written at (only build_scaled mentions it, in a note). The paper's images are in
 * paper_scenes.c, the stiff and extreme cases in stiff_scenes.c, the moving scenes' motion files
 * (and bouncing-balls) in motion_scenes.c.
 */
#ifndef GEN_BUILDERS_H
#define GEN_BUILDERS_H

#include <stdio.h>

#include "scene.h"

/* paper_scenes.c: the paper's images, and their variants for the refit's scene-work unknowns
 * (docs/fidelity-protocol.md): image 1's layout, sphere scale, lights and framing; image 2's
 * plane, big spheres' radius, lights and framing. */
enum { PAPER_PLANAR_Z, PAPER_PLANAR, PAPER_CUBE, PAPER_TREE, PAPER_FLOOR, PAPER_WALL };
typedef struct paper_variant {
    int image;         /* 1 or 2 */
    int layout;        /* image 1: PAPER_PLANAR_Z (paper-image1), _PLANAR, _CUBE, _TREE; image 2: _FLOOR, _WALL */
    double scale;      /* image 1: factor on every sphere's radius, centres kept (1) */
    double big_radius; /* image 2: radius of the glass and the mirror sphere (2) */
    int lights;        /* 1 to 3 lights, their total intensity kept (2) */
    double margin;     /* the view angle frames every sphere with this margin (1.03 / 1.02) */
} paper_variant;
/* The values of paper-image1 (image 1) or paper-image2 (image 2). */
paper_variant paper_variant_default(int image);
void build_image1_layout(scene *sc, const paper_variant *v);
void build_image2_plane(scene *sc, const paper_variant *v);

void build_paper_image1(scene *sc);
void build_paper_image2(scene *sc);
void build_paper_image1_planar(scene *sc);
void build_paper_image1_cube(scene *sc);
void build_paper_image1_tree(scene *sc);
void build_paper_image2_wall(scene *sc);
void build_paper_image1_planar_z(scene *sc);
void build_paper_image2_floor(scene *sc);
void build_orbiting_mirror(scene *sc);

/* stiff_scenes.c */
void build_axis_rays(scene *sc);
void build_grid_corners(scene *sc);
void build_eye_inside(scene *sc);
void build_light_inside(scene *sc);
void build_grazing(scene *sc);
void build_tir(scene *sc);
void build_facing_mirrors(scene *sc);
void build_empty(scene *sc);
void build_one_big_sphere(scene *sc);
void build_one_cell(scene *sc);
void build_scaled(scene *sc);
void build_tiny_sphere(scene *sc);
void build_tiny_alone(scene *sc);
void build_cones_and_patches(scene *sc);
void build_one_pixel(scene *sc);
void build_opposing_normals(scene *sc);

/* motion_scenes.c: the moving scenes' own builders and their motion files */
void build_bouncing_balls(scene *sc);
void write_bouncing_balls_motion(FILE *f);
void write_orbiting_mirror_motion(FILE *f);

#endif
