/* scene_internal.h - the scene's storage, shared by the kernel's own files only. */
#ifndef RT_SCENE_INTERNAL_H
#define RT_SCENE_INTERNAL_H

#include <stddef.h>
#include <stdint.h>

#include "rt_scene.h"

typedef struct rt_sphere_data {
    rt_vec3 center;
    double radius;
} rt_sphere_data;

typedef struct rt_polygon_data {
    uint32_t first_vertex; /* into scene->vertices */
    uint32_t count;
    rt_vec3 normal; /* unit Newell normal (vertex order, counter-clockwise = front) */
    double offset;  /* plane: dot(normal, p) == offset */
    int drop_axis;  /* axis dropped for the 2D inside test (largest normal component) */
    int degenerate; /* zero area: never hit */
} rt_polygon_data;

typedef struct rt_triangle_data {
    rt_vec3 v[3];   /* vertices */
    rt_vec3 n[3];   /* unit vertex normals */
    rt_vec3 normal; /* unit geometric normal from the vertex order */
    double side;    /* +1 or -1: the side of `normal` the vertex normals, summed, lie on */
    int degenerate; /* zero area: never hit */
} rt_triangle_data;

typedef struct rt_cone_data {
    rt_vec3 base, apex; /* axis end points */
    double base_radius, apex_radius;
    rt_vec3 axis;  /* unit vector base -> apex */
    double height; /* |apex - base| */
    double slope;  /* (apex_radius - base_radius) / height */
} rt_cone_data;

typedef struct rt_object {
    rt_object_kind kind;
    uint32_t material; /* into scene->materials */
    rt_box bounds;     /* axis-aligned bounds (lo > hi: none) */
    union {
        rt_sphere_data sphere;
        rt_polygon_data polygon;
        rt_triangle_data triangle;
        rt_cone_data cone;
    } u;
} rt_object;

typedef struct rt_light_entry {
    rt_light light;
    int has_color;
} rt_light_entry;

struct rt_scene {
    rt_camera camera;
    int has_view;
    rt_vec3 background;
    rt_vec3 ambient;

    rt_light_entry *lights;
    size_t light_count, light_capacity;

    rt_material *materials;
    size_t material_count, material_capacity;
    int has_material; /* set_material was called */
    int used_default; /* an object got the default material */

    rt_object *objects;
    size_t object_count, object_capacity;

    rt_vec3 *vertices; /* polygon vertex pool */
    size_t vertex_count, vertex_capacity;

    int has_transmission;
    int finished;
};

/* Recompute an object's derived data (normals, planes, axis, bounds) from its defining
 * geometry: the sphere's centre and radius, the polygon's vertices in s->vertices, the
 * triangle's vertices and unit vertex normals, the cone's end points and radii. The builders
 * use them, and so does a motion moving the object (motion.c). */
void rt_scene_derive_sphere(rt_object *o);
void rt_scene_derive_polygon(const rt_scene *s, rt_object *o);
void rt_scene_derive_triangle(rt_object *o);
void rt_scene_derive_cone(rt_object *o);

#endif
