/* rt_packet.h - the packet that travels between intersection processors.
 *
 * Usage:
 *   rt_packet p;
 *   int enters;
 *   rt_primary_packet(scene, grid, x, y, &p, &enters);
 *   if (!enters) write rt_scene_background(scene) to pixel (x, y);
 *
 * A packet is plain data: copy it freely. Its on-the-wire size is a model
 * parameter (rt_timing.packet_bytes, the paper's 28 bytes); sizeof(rt_packet)
 * is the in-memory size.
 */
#ifndef RT_PACKET_H
#define RT_PACKET_H

#include <stdint.h>

#include "rt_dda.h"
#include "rt_grid.h"
#include "rt_scene.h"
#include "rt_vec.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum rt_packet_kind {
    RT_PACKET_RAY = 0,    /* a ray looking for its nearest hit */
    RT_PACKET_SHADOW = 1, /* a ray toward a light carrying the light's contribution */
    RT_PACKET_KINDS = 2
} rt_packet_kind;

typedef struct rt_packet {
    rt_vec3 origin;      /* ray origin, scene units */
    rt_vec3 dir;         /* unit direction */
    rt_vec3 weight;      /* ray: weight k_i per channel (1 for primaries); shadow: luminance carried */
    rt_dda dda;          /* traversal state: current cell, next boundaries, t reached (dda.t_enter) */
    double t_light;      /* shadow: t at which the light is reached; ray: +inf */
    uint32_t x, y;       /* pixel, x from the left, y from the top */
    uint16_t depth;      /* shade-tree depth, 0 for primaries */
    uint8_t kind;        /* rt_packet_kind */
    uint8_t handed_over; /* 1: handed on by another IP's step, not yet taken up */
} rt_packet;

/* Packet bookkeeping of a whole render, the renderer's or the model's (created = consumed). */
typedef struct rt_packet_totals {
    uint64_t created[RT_PACKET_KINDS];  /* packets made, by kind (primaries included) */
    uint64_t consumed[RT_PACKET_KINDS]; /* packets that were absorbed or left, by kind */
    uint64_t forwarded;                 /* hand-overs between owners (0 in the renderer) */
    uint64_t primary_missed;            /* primary rays that never met the object space */
} rt_packet_totals;

/* The primary ray of pixel (x, y) (docs/design.md section 3 camera). Sets *enters
 * to 1 and fills *out when the ray meets the object space, to 0 otherwise
 * (the pixel then gets the background). Returns RT_ERR_INVALID if (x, y)
 * lies outside the image. */
rt_status rt_primary_packet(const rt_scene *scene, const rt_grid *grid, uint32_t x, uint32_t y, rt_packet *out,
                            int *enters);

/* Direction of the primary ray of pixel (x, y), unit length. */
rt_vec3 rt_primary_direction(const rt_camera *camera, uint32_t x, uint32_t y);

#ifdef __cplusplus
}
#endif
#endif
