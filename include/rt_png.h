/* rt_png.h - writing and reading 8-bit RGB PNG files (libpng).
 *
 * Usage:
 *   if (rt_png_write_stream(fp, "out.png", w, h, rgb8, msg, sizeof msg) != RT_OK) ...
 *
 * The kernel writes to a stream its caller owns: the caller chooses the file (a temporary
 * it renames when the run is done, or a device written in place), so the kernel never
 * replaces a file. Returns RT_ERR_IO with a message on failure.
 */
#ifndef RT_PNG_H
#define RT_PNG_H

#include <stddef.h>
#include <stdint.h>

#include <stdio.h>

#include "rt_status.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Encodes an 8-bit RGB PNG into an open stream (flushed, not closed); `name` is used in
 * messages. RT_ERR_IO when encoding or a write fails ("NAME: cannot write: ERRNO TEXT"). */
rt_status rt_png_write_stream(FILE *fp, const char *name, uint32_t width, uint32_t height, const uint8_t *rgb8,
                              char *msg, size_t msg_len);

/* Reads an 8-bit RGB PNG; *rgb8 is malloc'ed (caller frees). RT_ERR_IO or
 * RT_ERR_INVALID (not 8-bit RGB) on failure. */
rt_status rt_png_read(const char *path, uint32_t *width, uint32_t *height, uint8_t **rgb8, char *msg, size_t msg_len);

#ifdef __cplusplus
}
#endif
#endif
