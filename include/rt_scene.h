/* rt_scene.h - the scene model: camera, lights, materials and objects.
 *
 * Usage:
 *   rt_scene *s = rt_scene_new();
 *   rt_scene_set_view(s, from, at, up, 45.0, 144, 144);
 *   rt_material m = rt_material_default();
 *   rt_scene_set_material(s, &m);
 *   rt_scene_add_sphere(s, rt_vec(0, 0, 0), 1.0);
 *   rt_scene_add_light(s, rt_vec(5, 5, 5), NULL);
 *   ... rt_scene_free(s);
 *
 * Every builder returns RT_OK or RT_ERR_INVALID (non-finite numbers or
 * magnitudes above 1e30, radius <= 0, fewer than 3 vertices), RT_ERR_LIMIT (see the RT_SCENE_MAX_*
 * limits) or RT_ERR_NOMEM. Objects are numbered 0, 1, ... in the order they
 * are added; a `pp` patch with n vertices adds n - 2 triangle objects (a
 * fan from vertex 0), so ties in t go to the object added first.
 */
#ifndef RT_SCENE_H
#define RT_SCENE_H

#include <stddef.h>
#include <stdint.h>

#include "rt_status.h"
#include "rt_vec.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Documented limits: bigger input is rejected with RT_ERR_LIMIT. */
#define RT_SCENE_MAX_OBJECTS 4000000u  /* objects (after splitting patches) */
#define RT_SCENE_MAX_LIGHTS 1024u      /* point lights */
#define RT_SCENE_MAX_VERTICES 100000u  /* vertices of one polygon or patch */
#define RT_SCENE_MAX_RESOLUTION 16384u /* image width or height, pixels */

typedef struct rt_scene rt_scene;

typedef struct rt_material {
    rt_vec3 color; /* diffuse colour C, each channel in [0, 1] usually */
    double kd;     /* diffuse coefficient */
    double ks;     /* specular (mirror) coefficient; > 0 spawns reflection */
    double shine;  /* Phong exponent of the highlight, >= 0 (any size); 0 = no highlight */
    double t;      /* transmission coefficient; > 0 spawns refraction */
    double ior;    /* index of refraction of the inside; must be > 0 only when t > 0 */
} rt_material;

typedef struct rt_camera {
    rt_vec3 from;           /* eye position, scene units */
    rt_vec3 at;             /* point looked at, scene units */
    rt_vec3 up;             /* up hint (need not be unit or orthogonal) */
    double angle;           /* degrees, centre of first pixel column to centre of last */
    uint32_t width, height; /* pixels */
} rt_camera;

typedef struct rt_light {
    rt_vec3 position; /* scene units */
    rt_vec3 color;    /* intensity per channel (already defaulted, see rt_scene_finish) */
} rt_light;

typedef enum rt_object_kind {
    RT_OBJ_SPHERE = 0,
    RT_OBJ_POLYGON = 1,  /* flat polygon, any vertex count, even-odd inside test */
    RT_OBJ_TRIANGLE = 2, /* one triangle of a `pp` fan, with vertex normals */
    RT_OBJ_CONE = 3      /* open cone or cylinder, no caps */
} rt_object_kind;

/* The material every object gets before any `f`: f 1 1 1 1 0 0 0 1. */
rt_material rt_material_default(void);

/* Returns NULL if memory runs out. */
rt_scene *rt_scene_new(void);
void rt_scene_free(rt_scene *scene);
/* A deep copy (camera, lights, materials, objects); NULL if memory runs out. */
rt_scene *rt_scene_clone(const rt_scene *scene);

rt_status rt_scene_set_view(rt_scene *scene, rt_vec3 from, rt_vec3 at, rt_vec3 up, double angle_deg, uint32_t width,
                            uint32_t height);
/* Overrides the resolution only (the --size option). */
rt_status rt_scene_set_resolution(rt_scene *scene, uint32_t width, uint32_t height);
rt_status rt_scene_set_background(rt_scene *scene, rt_vec3 rgb);
rt_status rt_scene_set_ambient(rt_scene *scene, rt_vec3 rgb);
/* rgb NULL = no colour given: (1,1,1)/sqrt(lights) once the scene is finished. */
rt_status rt_scene_add_light(rt_scene *scene, rt_vec3 position, const rt_vec3 *rgb);
/* Sets the material of the objects added from now on. */
rt_status rt_scene_set_material(rt_scene *scene, const rt_material *material);
rt_status rt_scene_add_sphere(rt_scene *scene, rt_vec3 center, double radius);
rt_status rt_scene_add_polygon(rt_scene *scene, const rt_vec3 *vertices, size_t count);
/* normals: one per vertex (normalised here). */
rt_status rt_scene_add_patch(rt_scene *scene, const rt_vec3 *vertices, const rt_vec3 *normals, size_t count);
rt_status rt_scene_add_cone(rt_scene *scene, rt_vec3 base, double base_radius, rt_vec3 apex, double apex_radius);

/* Ends building: gives uncoloured lights their default colour. Returns
 * RT_ERR_INVALID with a message if the view was never set or the camera is
 * degenerate (from == at, up parallel to the view direction). */
rt_status rt_scene_finish(rt_scene *scene, char *msg, size_t msg_len);

/* 1 if some object was added before any material was set. */
int rt_scene_used_default_material(const rt_scene *scene);

const rt_camera *rt_scene_camera(const rt_scene *scene);
rt_vec3 rt_scene_background(const rt_scene *scene);
rt_vec3 rt_scene_ambient(const rt_scene *scene);
size_t rt_scene_light_count(const rt_scene *scene);
const rt_light *rt_scene_light(const rt_scene *scene, size_t index);
size_t rt_scene_object_count(const rt_scene *scene);
rt_object_kind rt_scene_object_kind(const rt_scene *scene, size_t index);
const rt_material *rt_scene_object_material(const rt_scene *scene, size_t index);
/* Axis-aligned bounds of one object (empty box lo > hi for a zero-area polygon). */
rt_box rt_scene_object_bounds(const rt_scene *scene, size_t index);
/* 1 if any material has t > 0 (refraction work exists). */
int rt_scene_has_transmission(const rt_scene *scene);

/* Data memory model (bytes) of one object as an IP would store it:
 * 4-byte floats and a 4-byte material index; see docs/memory.md. */
uint32_t rt_scene_object_bytes(const rt_scene *scene, size_t index);
/* Bytes of one material record. */
uint32_t rt_scene_material_bytes(void);

#ifdef __cplusplus
}
#endif
#endif
