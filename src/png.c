/* png.c - 8-bit RGB PNG files through libpng. libpng reports errors by
 * longjmp; its messages are caught into a buffer and nothing is printed. */
#include <errno.h>
#include <png.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "rt_png.h"

/* Owned by the caller of the setjmp functions, so its contents stay
 * defined after a longjmp. */
typedef struct png_errors {
    char text[200];
    int err; /* errno when libpng gave up: a failed write's cause */
} png_errors;

static void on_error(png_structp png, png_const_charp message)
{
    png_errors *e = png_get_error_ptr(png);
    e->err = errno;
    snprintf(e->text, sizeof e->text, "%s", message);
    png_longjmp(png, 1);
}

/* Warnings (e.g. about ancillary chunks) stop nothing: kept silent. */
static void on_warning(png_structp png, png_const_charp message)
{
    (void)png;
    (void)message;
}

/* Encodes the image into fp; 0 with e->text set on failure. */
static int encode(FILE *fp, uint32_t width, uint32_t height, const uint8_t *rgb8, png_errors *e)
{
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, e, on_error, on_warning);
    png_infop info = png ? png_create_info_struct(png) : NULL;
    if (!png || !info) {
        png_destroy_write_struct(&png, NULL);
        snprintf(e->text, sizeof e->text, "cannot set up libpng");
        return 0;
    }
    /* png and info do not change after setjmp. */
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        return 0;
    }
    png_init_io(png, fp);
    png_set_IHDR(png, info, width, height, 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
                 PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    size_t stride = (size_t)width * 3u;
    for (uint32_t y = 0; y < height; y++) png_write_row(png, rgb8 + (size_t)y * stride);
    png_write_end(png, info);
    png_destroy_write_struct(&png, &info);
    return 1;
}

rt_status rt_png_write_stream(FILE *fp, const char *name, uint32_t width, uint32_t height, const uint8_t *rgb8,
                              char *msg, size_t msg_len)
{
    if (!fp || !rgb8 || width == 0 || height == 0 || width > PNG_UINT_31_MAX || height > PNG_UINT_31_MAX ||
        (size_t)width > SIZE_MAX / 3u / (size_t)height) {
        if (msg && msg_len)
            snprintf(msg, msg_len, "%s: cannot write a %ux%u image", name ? name : "(no name)", (unsigned)width,
                     (unsigned)height);
        return RT_ERR_INVALID;
    }
    png_errors e = {"", 0};
    int ok = encode(fp, width, height, rgb8, &e);
    if (ok && fflush(fp) == 0 && !ferror(fp)) return RT_OK;
    if (msg && msg_len) {
        /* A failed write (a full disk) is told by its errno, not libpng's "Write Error". */
        if (ok || ferror(fp))
            snprintf(msg, msg_len, "%s: cannot write: %s", name ? name : "",
                     strerror(ok      ? errno
                              : e.err ? e.err
                                      : EIO));
        else snprintf(msg, msg_len, "%s: PNG write failed: %s", name ? name : "", e.text);
    }
    return RT_ERR_IO;
}

/* Decodes an 8-bit RGB PNG (signature already read); e->text on failure. */
static rt_status decode(FILE *fp, png_errors *e, uint32_t *width, uint32_t *height, uint8_t **out)
{
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, e, on_error, on_warning);
    png_infop info = png ? png_create_info_struct(png) : NULL;
    if (!png || !info) {
        png_destroy_read_struct(&png, NULL, NULL);
        snprintf(e->text, sizeof e->text, "cannot set up libpng");
        return RT_ERR_IO;
    }
    /* Allocated after setjmp: volatile so the handler frees the right one. */
    uint8_t *volatile pixels = NULL;
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_read_struct(&png, &info, NULL);
        free(pixels);
        return RT_ERR_IO;
    }
    png_init_io(png, fp);
    png_set_sig_bytes(png, 8);
    png_read_info(png, info);
    png_uint_32 w = png_get_image_width(png, info), h = png_get_image_height(png, info);
    int depth = png_get_bit_depth(png, info), type = png_get_color_type(png, info);
    rt_status st = RT_OK;
    if (depth != 8 || type != PNG_COLOR_TYPE_RGB) {
        snprintf(e->text, sizeof e->text, "not an 8-bit RGB PNG (bit depth %d, colour type %d)", depth, type);
        st = RT_ERR_INVALID;
    } else if (w == 0 || h == 0 || (size_t)w > SIZE_MAX / 3u / (size_t)h) {
        snprintf(e->text, sizeof e->text, "image too large");
        st = RT_ERR_INVALID;
    } else {
        int passes = png_set_interlace_handling(png);
        png_read_update_info(png, info);
        size_t stride = (size_t)w * 3u;
        pixels = malloc(stride * h);
        if (!pixels) {
            snprintf(e->text, sizeof e->text, "out of memory");
            st = RT_ERR_NOMEM;
        } else {
            for (int pass = 0; pass < passes; pass++)
                for (png_uint_32 y = 0; y < h; y++) png_read_row(png, pixels + (size_t)y * stride, NULL);
            png_read_end(png, NULL);
        }
    }
    png_destroy_read_struct(&png, &info, NULL);
    if (st == RT_OK) {
        *width = w;
        *height = h;
        *out = pixels;
    }
    return st;
}

rt_status rt_png_read(const char *path, uint32_t *width, uint32_t *height, uint8_t **rgb8, char *msg, size_t msg_len)
{
    if (!path || !width || !height || !rgb8) {
        if (msg && msg_len) snprintf(msg, msg_len, "rt_png_read: missing argument");
        return RT_ERR_INVALID;
    }
    *rgb8 = NULL;
    FILE *fp = fopen(path, "rb");
    if (!fp) {
        if (msg && msg_len) snprintf(msg, msg_len, "%s: cannot open: %s", path, strerror(errno));
        return RT_ERR_IO;
    }
    unsigned char sig[8];
    if (fread(sig, 1, sizeof sig, fp) != sizeof sig || png_sig_cmp(sig, 0, sizeof sig) != 0) {
        fclose(fp);
        if (msg && msg_len) snprintf(msg, msg_len, "%s: not a PNG file", path);
        return RT_ERR_INVALID;
    }
    png_errors e = {"", 0};
    rt_status st = decode(fp, &e, width, height, rgb8);
    fclose(fp);
    if (st != RT_OK && msg && msg_len) snprintf(msg, msg_len, "%s: %s", path, e.text);
    return st;
}
