/* rt_status.h - the kernel's error convention.
 *
 * Usage:
 *   char msg[RT_MSG_LEN];
 *   if (rt_something(..., msg, sizeof msg) != RT_OK) fprintf(stderr, "%s\n", msg);
 *
 * Every kernel function that can fail returns an rt_status; functions that
 * can explain a failure take a caller-owned message buffer. The kernel never
 * prints and never exits.
 */
#ifndef RT_STATUS_H
#define RT_STATUS_H

#ifdef __cplusplus
extern "C" {
#endif

/* Length of a message buffer that always holds a full kernel message. */
#define RT_MSG_LEN 512

typedef enum rt_status {
    RT_OK = 0,      /* success */
    RT_ERR_INVALID, /* an argument or input value is out of its documented range */
    RT_ERR_PARSE,   /* a scene or timing file is malformed */
    RT_ERR_LIMIT,   /* input exceeds a documented limit (size, count) */
    RT_ERR_NOMEM,   /* an allocation failed */
    RT_ERR_IO,      /* a file could not be opened, read or written */
    RT_ERR_CAPACITY /* a caller-provided buffer is too small */
} rt_status;

/* Returns a static, human-readable name for a status (never NULL). */
const char *rt_status_name(rt_status status);

#ifdef __cplusplus
}
#endif
#endif
