/* rt_nff.h - reader for NFF (Neutral File Format) scenes, with the `am` extension.
 *
 * Usage:
 *   char msg[RT_MSG_LEN];
 *   rt_scene *s = NULL;
 *   if (rt_nff_load("scene.nff", &s, msg, sizeof msg) != RT_OK) {
 *       fprintf(stderr, "%s\n", msg);   // "scene.nff:12: sphere radius must be > 0"
 *   }
 *
 * The file is read as a stream of tokens. On failure *out is NULL and msg
 * holds "FILE:LINE: what is wrong". Warnings (objects before any `f`) go to
 * the optional warn callback as "FILE:LINE: warning: ...". A successful load
 * has called rt_scene_finish.
 */
#ifndef RT_NFF_H
#define RT_NFF_H

#include <stddef.h>

#include "rt_scene.h"
#include "rt_status.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef void (*rt_nff_warn_fn)(void *ctx, const char *message);

/* Largest scene file accepted, bytes. */
#define RT_NFF_MAX_FILE_BYTES (1024u * 1024u * 1024u)

/* Returns RT_ERR_IO (cannot open/read), RT_ERR_PARSE or RT_ERR_LIMIT on failure. */
rt_status rt_nff_load(const char *path, rt_scene **out, char *msg, size_t msg_len, rt_nff_warn_fn warn, void *warn_ctx);

/* The same from memory; `name` is used in messages in place of a file name. */
rt_status rt_nff_parse(const char *name, const char *text, size_t length, rt_scene **out, char *msg, size_t msg_len,
                       rt_nff_warn_fn warn, void *warn_ctx);

#ifdef __cplusplus
}
#endif
#endif
