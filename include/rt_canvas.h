/* rt_canvas.h - small RGB drawing for the load pictures: heat colours, rectangles,
 * a 3x5 bitmap font, colour bars.
 *
 * Usage:
 *   rt_canvas *c = rt_canvas_new(w, h);          // white
 *   rt_canvas_rect(c, x, y, w, h, rgb);
 *   rt_canvas_text(c, x, y, 2, "12.5 us", black);  // scale 2: 6x10 pixel glyphs
 *   rt_canvas_heat_bar(c, x, y, w, h, 0.0, max, "us");
 *   rt_png_write(path, c->width, c->height, c->rgb, msg, sizeof msg);
 *   rt_canvas_free(c);
 *
 * The font has digits, letters (drawn lower-case), space and . , - + : = ( ) > /; anything else
 * draws a box.
 * Drawing outside the canvas is clipped. rt_canvas_new returns NULL on a zero size or
 * when memory runs out.
 */
#ifndef RT_CANVAS_H
#define RT_CANVAS_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct rt_canvas {
    uint32_t width, height;
    uint8_t *rgb; /* width * height * 3, rows from the top */
} rt_canvas;

rt_canvas *rt_canvas_new(uint32_t width, uint32_t height);
void rt_canvas_free(rt_canvas *canvas);

/* Heat colour of t in [0, 1] (clamped): black, blue, red, yellow, white. */
void rt_heat_colour(double t, uint8_t rgb[3]);
/* A distinct colour for node i (golden-angle hues). */
void rt_node_colour(int i, uint8_t rgb[3]);

void rt_canvas_rect(rt_canvas *c, int x, int y, int w, int h, const uint8_t rgb[3]);
/* Text from (x, y) at the top left; returns the x after the last glyph. */
int rt_canvas_text(rt_canvas *c, int x, int y, int scale, const char *text, const uint8_t rgb[3]);
/* A vertical colour bar (bottom = lo, top = hi) with both values written beside it; with unit
 * "us" the values are written as times in us, ms or s (rt_time_label). */
void rt_canvas_heat_bar(rt_canvas *c, int x, int y, int w, int h, double lo, double hi, const char *unit);
/* A time of `us` microseconds in the unit that reads best, 4 significant digits: "850 us",
 * "3.251 ms", "1.82 s". */
void rt_time_label(double us, char *buf, size_t len);

#ifdef __cplusplus
}
#endif
#endif
