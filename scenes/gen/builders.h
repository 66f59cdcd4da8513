/* builders.h - one builder per scene, listed in gen_scenes.c's table.
 *
 * Each fills a zeroed scene (with sc->up set) through scene.h; `factor` is the scale the
 * scene is written at (only build_scaled mentions it, in a note). The paper's images are in
 * paper_scenes.c, the stiff and extreme cases in stiff_scenes.c.
 */
#ifndef GEN_BUILDERS_H
#define GEN_BUILDERS_H

#include "scene.h"

/* paper_scenes.c */
void build_paper_image1(scene *sc, double factor);
void build_paper_image2(scene *sc, double factor);
void build_paper_image1_planar_z(scene *sc, double factor);
void build_paper_image1_cube(scene *sc, double factor);
void build_paper_image1_tree(scene *sc, double factor);
void build_paper_image2_wall(scene *sc, double factor);

/* stiff_scenes.c */
void build_axis_rays(scene *sc, double factor);
void build_grid_corners(scene *sc, double factor);
void build_eye_inside(scene *sc, double factor);
void build_light_inside(scene *sc, double factor);
void build_grazing(scene *sc, double factor);
void build_tir(scene *sc, double factor);
void build_facing_mirrors(scene *sc, double factor);
void build_empty(scene *sc, double factor);
void build_one_big_sphere(scene *sc, double factor);
void build_one_cell(scene *sc, double factor);
void build_scaled(scene *sc, double factor);
void build_tiny_sphere(scene *sc, double factor);
void build_tiny_alone(scene *sc, double factor);
void build_cones_and_patches(scene *sc, double factor);
void build_one_pixel(scene *sc, double factor);
void build_opposing_normals(scene *sc, double factor);

#endif
