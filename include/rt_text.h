/* rt_text.h - quoting bytes from input files and file names in messages.
 *
 * Usage:
 *   char shown[256];
 *   fprintf(stderr, "%s: ...\n", rt_escape_bytes(path, strlen(path), 0, shown, sizeof shown));
 *
 * Every byte outside printable ASCII (control bytes, DEL, and, when `ascii_only`, bytes
 * >= 0x80) is written as \xNN and a backslash as \\, so no file or name can send raw control
 * bytes to a terminal; UTF-8 names stay readable with ascii_only = 0.
 */
#ifndef RT_TEXT_H
#define RT_TEXT_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Copies up to `len` bytes of s into buf, escaped; stops (with "...") before buf
 * overflows; returns buf (always NUL-terminated when buf_len > 0). */
const char *rt_escape_bytes(const char *s, size_t len, int ascii_only, char *buf, size_t buf_len);

#ifdef __cplusplus
}
#endif
#endif
