/* file_read.h - reading a whole input file safely (kernel internal; the NFF reader and
 * the timing table use it).
 *
 * Usage:
 *   char *text; size_t len;
 *   if (rt_read_regular_file(path, limit, &text, &len, msg, sizeof msg)) return ...;
 *   ... free(text);
 *
 * Only regular files are read: a FIFO, device or directory is refused before
 * any read (the file is opened without blocking, so a FIFO with no writer
 * cannot hang the open), and /dev/zero cannot feed an unbounded read. A read
 * or allocation failure is an error, never an end of file.
 */
#ifndef RT_FILE_READ_H
#define RT_FILE_READ_H

#include <stddef.h>

#include "rt_status.h"
#include "rt_text.h"

/* Reads the whole regular file (at most max_bytes) into a malloc'd buffer with a
 * NUL after the last byte. Returns RT_ERR_IO (cannot open or read, not a regular
 * file), RT_ERR_LIMIT (larger than max_bytes: "PATH:1: ...") or RT_ERR_NOMEM, with
 * "PATH: ..." in msg. */
rt_status rt_read_regular_file(const char *path, size_t max_bytes, char **text, size_t *length,
                               char *msg, size_t msg_len);

#endif
