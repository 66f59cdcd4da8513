/* file_read.c - whole-file reads of regular text files only. */
#include "rt_file_read.h"

#include <errno.h>
#include <fcntl.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "rt_status.h"

static rt_status fail(char *msg, size_t msg_len, rt_status status, const char *fmt, ...)
{
    if (msg && msg_len) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(msg, msg_len, fmt, ap);
        va_end(ap);
    }
    return status;
}

/* Reads until end of file or one byte past max_bytes; a read error is an error. */
static rt_status read_all(int fd, const char *shown, size_t max_bytes, size_t capacity, char **text, size_t *length,
                          char *msg, size_t msg_len)
{
    size_t used = 0;
    char *buf = malloc(capacity + 1);
    if (!buf) return fail(msg, msg_len, RT_ERR_NOMEM, "%s: out of memory reading the file", shown);
    for (;;) {
        if (used == capacity) {
            if (capacity > max_bytes) break; /* one byte over the limit: stop */
            size_t grown = capacity > max_bytes / 2 ? max_bytes + 1 : capacity * 2;
            char *bigger = realloc(buf, grown + 1);
            if (!bigger) {
                free(buf);
                return fail(msg, msg_len, RT_ERR_NOMEM, "%s: out of memory reading the file", shown);
            }
            buf = bigger;
            capacity = grown;
        }
        ssize_t got = read(fd, buf + used, capacity - used);
        if (got < 0 && errno == EINTR) continue;
        if (got < 0) {
            int saved = errno;
            free(buf);
            return fail(msg, msg_len, RT_ERR_IO, "%s: cannot read: %s", shown, strerror(saved));
        }
        if (got == 0) break;
        used += (size_t)got;
    }
    if (used > max_bytes) {
        free(buf);
        return fail(msg, msg_len, RT_ERR_LIMIT, "%s:1: the file is more than the limit of %zu bytes", shown, max_bytes);
    }
    buf[used] = '\0';
    *text = buf;
    *length = used;
    return RT_OK;
}

const char *rt_file_kind(unsigned mode)
{
    mode_t m = (mode_t)mode;
    return S_ISREG(m)    ? "a regular file"
           : S_ISDIR(m)  ? "a folder"
           : S_ISFIFO(m) ? "a FIFO"
           : S_ISCHR(m)  ? "a character device"
           : S_ISBLK(m)  ? "a block device"
           : S_ISSOCK(m) ? "a socket"
                         : "a special file";
}

/* Leaves out a UTF-8 byte-order mark and refuses a NUL byte, naming its line. */
static rt_status check_text(const char *shown, char *text, size_t *length, char *msg, size_t msg_len)
{
    if (*length >= 3 && memcmp(text, "\xEF\xBB\xBF", 3) == 0) {
        memmove(text, text + 3, *length - 3 + 1); /* + 1: the NUL after the last byte */
        *length -= 3;
    }
    const char *nul = memchr(text, '\0', *length);
    if (!nul) return RT_OK;
    long line = 1;
    for (const char *p = text; p < nul; p++) line += *p == '\n';
    return fail(msg, msg_len, RT_ERR_PARSE, "%s:%ld: binary data (a NUL byte at offset %zu): only text files are read",
                shown, line, (size_t)(nul - text));
}

/* The open descriptor is a regular file of at most max_bytes, set back to blocking reads. */
static rt_status check_opened(int fd, const char *shown, size_t max_bytes, struct stat *info, char *msg, size_t msg_len)
{
    if (fstat(fd, info) != 0) return fail(msg, msg_len, RT_ERR_IO, "%s: cannot read: %s", shown, strerror(errno));
    if (!S_ISREG(info->st_mode))
        return fail(msg, msg_len, RT_ERR_IO, "%s: is %s, not a regular file", shown,
                    rt_file_kind((unsigned)info->st_mode));
    if ((uintmax_t)info->st_size > max_bytes)
        return fail(msg, msg_len, RT_ERR_LIMIT, "%s:1: the file is %jd bytes, more than the limit of %zu", shown,
                    (intmax_t)info->st_size, max_bytes);
    int flags = fcntl(fd, F_GETFL);
    if (flags < 0 || fcntl(fd, F_SETFL, flags & ~O_NONBLOCK) < 0)
        return fail(msg, msg_len, RT_ERR_IO, "%s: cannot read: %s", shown, strerror(errno));
    return RT_OK;
}

rt_status rt_read_regular_file(const char *path, size_t max_bytes, char **text, size_t *length, char *msg,
                               size_t msg_len)
{
    char shown[256];
    rt_escape_bytes(path, strlen(path), 0, shown, sizeof shown);
    *text = NULL;
    *length = 0;
    /* O_NONBLOCK: opening a FIFO with no writer returns at once instead of waiting. */
    int fd = open(path, O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
    if (fd < 0) return fail(msg, msg_len, RT_ERR_IO, "%s: cannot open: %s", shown, strerror(errno));
    struct stat info;
    rt_status st = check_opened(fd, shown, max_bytes, &info, msg, msg_len);
    if (st == RT_OK) /* + 1: the end of file is seen in the first read when the size holds. */
        st = read_all(fd, shown, max_bytes, (size_t)info.st_size + 1, text, length, msg, msg_len);
    close(fd);
    if (st == RT_OK && (st = check_text(shown, *text, length, msg, msg_len)) != RT_OK) {
        free(*text);
        *text = NULL;
        *length = 0;
    }
    return st;
}
