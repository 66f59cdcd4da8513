/* framebuffer.c - fixed-point accumulation: integer sums do not depend on order. */
#include <math.h>
#include <stdlib.h>

#include "rt_framebuffer.h"

#define FB_ONE 4294967296.0 /* 2^32 units = 1.0 */
#define FB_CLAMP 1048576.0  /* |contribution| <= 2^20 keeps 2^11 of them summable */

struct rt_framebuffer {
    uint32_t width, height;
    int64_t *sum; /* 3 per pixel */
};

rt_framebuffer *rt_framebuffer_new(uint32_t width, uint32_t height)
{
    if (width == 0 || height == 0) return NULL;
    rt_framebuffer *fb = malloc(sizeof *fb);
    if (!fb) return NULL;
    fb->width = width;
    fb->height = height;
    fb->sum = calloc((size_t)width * height * 3u, sizeof *fb->sum);
    if (!fb->sum) {
        free(fb);
        return NULL;
    }
    return fb;
}

uint64_t rt_framebuffer_bytes(uint32_t width, uint32_t height)
{
    return (uint64_t)width * height * 3u * (sizeof(int64_t) + 1u);
}

void rt_framebuffer_free(rt_framebuffer *fb)
{
    if (!fb) return;
    free(fb->sum);
    free(fb);
}

uint32_t rt_framebuffer_width(const rt_framebuffer *fb) { return fb->width; }
uint32_t rt_framebuffer_height(const rt_framebuffer *fb) { return fb->height; }

static int64_t to_fixed(double v)
{
    if (!(v == v)) return 0; /* NaN adds nothing */
    if (v > FB_CLAMP) v = FB_CLAMP;
    if (v < -FB_CLAMP) v = -FB_CLAMP;
    return (int64_t)llround(v * FB_ONE);
}

/* Saturating add: only reachable with absurd scenes, never wraps. */
static int64_t add_sat(int64_t a, int64_t b)
{
    int64_t r;
    if (__builtin_add_overflow(a, b, &r)) return b > 0 ? INT64_MAX : INT64_MIN;
    return r;
}

void rt_framebuffer_add(rt_framebuffer *fb, uint32_t x, uint32_t y, rt_vec3 rgb)
{
    if (x >= fb->width || y >= fb->height) return;
    int64_t *p = fb->sum + ((size_t)y * fb->width + x) * 3u;
    p[0] = add_sat(p[0], to_fixed(rgb.x));
    p[1] = add_sat(p[1], to_fixed(rgb.y));
    p[2] = add_sat(p[2], to_fixed(rgb.z));
}

rt_vec3 rt_framebuffer_get(const rt_framebuffer *fb, uint32_t x, uint32_t y)
{
    if (x >= fb->width || y >= fb->height) return rt_vec(0, 0, 0);
    const int64_t *p = fb->sum + ((size_t)y * fb->width + x) * 3u;
    return rt_vec((double)p[0] / FB_ONE, (double)p[1] / FB_ONE, (double)p[2] / FB_ONE);
}

void rt_framebuffer_to_rgb8(const rt_framebuffer *fb, uint8_t *rgb8)
{
    const int64_t one = (int64_t)1 << 32;
    size_t n = (size_t)fb->width * fb->height * 3u;
    for (size_t i = 0; i < n; i++) {
        int64_t v = fb->sum[i];
        if (v < 0) v = 0;
        if (v > one) v = one;
        /* floor(v * 255 + 0.5) in integers: exact, no double rounding. */
        rgb8[i] = (uint8_t)((v * 255 + one / 2) >> 32);
    }
}
