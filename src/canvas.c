/* canvas.c - RGB drawing for the load pictures (heat maps, owner colours, labels). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "rt_canvas.h"

rt_canvas *rt_canvas_new(uint32_t width, uint32_t height)
{
    if (width == 0 || height == 0) return NULL;
    rt_canvas *c = malloc(sizeof *c);
    if (!c) return NULL;
    c->width = width;
    c->height = height;
    c->rgb = malloc((size_t)width * height * 3);
    if (!c->rgb) {
        free(c);
        return NULL;
    }
    memset(c->rgb, 255, (size_t)width * height * 3);
    return c;
}

void rt_canvas_free(rt_canvas *c)
{
    if (!c) return;
    free(c->rgb);
    free(c);
}

void rt_heat_colour(double t, uint8_t rgb[3])
{
    static const double stops[5][3] = {{0, 0, 0}, {0, 0, 200}, {220, 0, 0}, {255, 220, 0}, {255, 255, 255}};
    if (!(t > 0)) t = 0;
    if (t > 1) t = 1;
    double s = t * 4;
    int i = s >= 4 ? 3 : (int)s;
    double f = s - i;
    for (int k = 0; k < 3; k++) rgb[k] = (uint8_t)lround(stops[i][k] + f * (stops[i + 1][k] - stops[i][k]));
}

void rt_node_colour(int i, uint8_t rgb[3])
{
    double h = fmod(i * 137.508, 360.0) / 60.0, v = (i / 7) % 2 ? 0.75 : 0.95, s = 0.65;
    double c = v * s, x = c * (1 - fabs(fmod(h, 2.0) - 1)), m = v - c;
    double r = 0, g = 0, b = 0;
    switch ((int)h % 6) {
    case 0: r = c, g = x; break;
    case 1: r = x, g = c; break;
    case 2: g = c, b = x; break;
    case 3: g = x, b = c; break;
    case 4: r = x, b = c; break;
    default: r = c, b = x; break;
    }
    rgb[0] = (uint8_t)lround(255 * (r + m));
    rgb[1] = (uint8_t)lround(255 * (g + m));
    rgb[2] = (uint8_t)lround(255 * (b + m));
}

void rt_canvas_rect(rt_canvas *c, int x, int y, int w, int h, const uint8_t rgb[3])
{
    for (int j = y < 0 ? 0 : y; j < y + h && j < (int)c->height; j++)
        for (int i = x < 0 ? 0 : x; i < x + w && i < (int)c->width; i++)
            memcpy(c->rgb + ((size_t)j * c->width + (size_t)i) * 3, rgb, 3);
}

/* 3x5 glyphs, one row of 3 bits per digit of the octal-like string (top row first). */
static const char *glyph(char ch)
{
    static const char *digits[10] = {"75557", "26227", "71747", "71717", "55711",
                                     "74717", "74757", "71111", "75757", "75717"};
    static const char *lower[26] = {"02575", "44757", "03443", "11757", "07563", "32622", "07517", "44755", "20222",
                                    "10115", "45655", "22223", "07775", "06555", "02552", "07574", "07571", "06444",
                                    "03616", "27222", "05557", "05552", "05577", "05255", "55316", "07247"};
    if (ch >= '0' && ch <= '9') return digits[ch - '0'];
    if (ch >= 'a' && ch <= 'z') return lower[ch - 'a'];
    if (ch >= 'A' && ch <= 'Z') return lower[ch - 'A'];
    switch (ch) {
    case '.': return "00002";
    case ',': return "00012";
    case '-': return "00700";
    case '+': return "02720";
    case ':': return "02020";
    case '=': return "07070";
    case '(': return "12221";
    case ')': return "42224";
    case '>': return "42124";
    case '/': return "11244";
    case '_': return "00007";
    case ' ': return "00000";
    }
    return "77777";
}

int rt_canvas_text(rt_canvas *c, int x, int y, int scale, const char *text, const uint8_t rgb[3])
{
    for (const char *p = text; *p; p++, x += 4 * scale) {
        const char *g = glyph(*p);
        for (int row = 0; row < 5; row++)
            for (int col = 0; col < 3; col++)
                if ((g[row] - '0') & (4 >> col)) rt_canvas_rect(c, x + col * scale, y + row * scale, scale, scale, rgb);
    }
    return x;
}

void rt_canvas_heat_bar(rt_canvas *c, int x, int y, int w, int h, double lo, double hi, const char *unit)
{
    uint8_t col[3];
    const uint8_t black[3] = {0, 0, 0};
    for (int j = 0; j < h; j++) {
        rt_heat_colour(h > 1 ? 1.0 - (double)j / (h - 1) : 1.0, col);
        rt_canvas_rect(c, x, y + j, w, 1, col);
    }
    char label[48];
    int is_time = strcmp(unit, "us") == 0;
    if (is_time) rt_time_label(hi, label, sizeof label);
    else snprintf(label, sizeof label, "%.4g %s", hi, unit);
    rt_canvas_text(c, x + w + 4, y, 2, label, black);
    if (is_time) rt_time_label(lo, label, sizeof label);
    else snprintf(label, sizeof label, "%.4g %s", lo, unit);
    rt_canvas_text(c, x + w + 4, y + h - 10, 2, label, black);
}

void rt_time_label(double us, char *buf, size_t len)
{
    double a = fabs(us);
    if (a >= 1e6) snprintf(buf, len, "%.4g s", us / 1e6);
    else if (a >= 1e3) snprintf(buf, len, "%.4g ms", us / 1e3);
    else snprintf(buf, len, "%.4g us", us);
}
