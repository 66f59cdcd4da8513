/* text.c - quoting bytes from files and names in messages. */
#include "rt_text.h"

#include <stdio.h>
#include <string.h>

const char *rt_escape_bytes(const char *s, size_t len, int ascii_only, char *buf, size_t buf_len)
{
    size_t o = 0;
    if (!buf_len) return buf;
    for (size_t i = 0; i < len; i++) {
        unsigned char c = (unsigned char)s[i];
        char piece[5];
        if (c == '\\') snprintf(piece, sizeof piece, "\\\\");
        else if (c < 0x20 || c == 0x7f || (ascii_only && c >= 0x80)) snprintf(piece, sizeof piece, "\\x%02x", c);
        else piece[0] = (char)c, piece[1] = '\0';
        size_t n = strlen(piece);
        if (o + n + 4 > buf_len) { /* room for "..." and the NUL */
            if (o + 4 <= buf_len) memcpy(buf + o, "...", 3), o += 3;
            break;
        }
        memcpy(buf + o, piece, n);
        o += n;
    }
    buf[o < buf_len ? o : buf_len - 1] = '\0';
    return buf;
}
