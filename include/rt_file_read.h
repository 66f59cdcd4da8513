/* rt_file_read.h - the one way every input file is read: the scene, the timing file, the
 * machine file, the map file and the camera path.
 *
 * Usage:
 *   char *text; size_t len;
 *   if (rt_read_regular_file(path, limit, &text, &len, msg, sizeof msg)) return ...;
 *   ... free(text);
 *
 * Only regular files are read: a FIFO, device, socket or folder is refused before any
 * read, with a message saying what it is ("PATH: is a FIFO, not a regular file"). The file is
 * opened without blocking, so a FIFO with no writer cannot hang the open, and its size is
 * checked before reading, so /dev/zero-like input cannot feed an unbounded read. Every input
 * is text: a UTF-8 byte-order mark at the start is skipped, and a NUL byte is refused naming
 * its line. A read or allocation failure is an error, never an end of file.
 */
#ifndef RT_FILE_READ_H
#define RT_FILE_READ_H

#include <stddef.h>

#include "rt_status.h"
#include "rt_text.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Reads the whole regular file (at most max_bytes) into a malloc'd buffer with a NUL after
 * the last byte, its byte-order mark left out. Returns RT_ERR_IO (cannot open or read, not a
 * regular file), RT_ERR_LIMIT (larger than max_bytes: "PATH:1: ..."), RT_ERR_PARSE (a NUL
 * byte: "PATH:LINE: binary data ...") or RT_ERR_NOMEM, with the message in msg. */
rt_status rt_read_regular_file(const char *path, size_t max_bytes, char **text, size_t *length, char *msg,
                               size_t msg_len);

/* What a file of this st_mode is, for messages: "a FIFO", "a folder", "a character
 * device", ...; "a regular file" for one. */
const char *rt_file_kind(unsigned mode);

#ifdef __cplusplus
}
#endif
#endif
