/* rt_framebuffer.h - order-independent frame buffer (64-bit fixed point per channel).
 *
 * Usage:
 *   rt_framebuffer *fb = rt_framebuffer_new(w, h);
 *   rt_framebuffer_add(fb, x, y, rgb);        // any order, same result
 *   rt_framebuffer_to_rgb8(fb, pixels);       // w*h*3 bytes, row 0 = top
 *
 * Each contribution is converted on its own to units of 2^-32 (rounded to
 * nearest, clamped to +-2^20 per contribution, so 2^11 of the largest still
 * sum without overflow; sums saturate) and summed as integers, so the
 * final image does not depend on the order contributions arrive in.
 * rt_framebuffer_new returns NULL for a zero size or when memory runs out.
 */
#ifndef RT_FRAMEBUFFER_H
#define RT_FRAMEBUFFER_H

#include <stdint.h>

#include "rt_vec.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct rt_framebuffer rt_framebuffer;

rt_framebuffer *rt_framebuffer_new(uint32_t width, uint32_t height);
/* Bytes a width x height image takes: the 64-bit sums plus the final 8-bit pixels (for a
 * memory budget check before rt_framebuffer_new). */
uint64_t rt_framebuffer_bytes(uint32_t width, uint32_t height);
void rt_framebuffer_free(rt_framebuffer *fb);
uint32_t rt_framebuffer_width(const rt_framebuffer *fb);
uint32_t rt_framebuffer_height(const rt_framebuffer *fb);

/* Adds rgb to pixel (x, y); contributions outside the image are ignored. */
void rt_framebuffer_add(rt_framebuffer *fb, uint32_t x, uint32_t y, rt_vec3 rgb);

/* Accumulated value of one pixel as doubles (for tests). */
rt_vec3 rt_framebuffer_get(const rt_framebuffer *fb, uint32_t x, uint32_t y);

/* Final pixels: clamp to [0, 1], floor(v * 255 + 0.5); rgb8 holds width*height*3 bytes. */
void rt_framebuffer_to_rgb8(const rt_framebuffer *fb, uint8_t *rgb8);

#ifdef __cplusplus
}
#endif
#endif
