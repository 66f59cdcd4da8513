/* rt_map_file.h - explicit cell-to-node mappings as text files.
 *
 * Usage:
 *   rt_map_file_read("my.map", dims, nodes, owner, msg, sizeof msg);
 *   rt_map_file_write(fp, "used.map", dims, nodes, owner, msg, sizeof msg);
 *
 * Format: a header `torusrt-map 1 NX NY NZ NODES` (format version 1, the grid's
 * cells per axis, the number of nodes), then one node id (0..NODES-1) per cell
 * in x-fastest order (cell x + NX * (y + NY * z)), separated by any white
 * space and line breaks. `#` starts a comment to the end of the line.
 * Version 2 (`torusrt-map 2 ...`) allows several owners per cell: an entry is a node id or
 * ids joined by commas without spaces (`3,7,12`), the primary owner first, then the extra
 * owners (rt_replicas.h), all different; an entry is at most RT_MAP_FILE_MAX_WORD bytes.
 * Version 2 is read only by the _replicas forms; the writer writes version 1 when no cell
 * has an extra owner, so a one-owner table is the same file as before.
 * Reading checks the header against the run's grid and node count, every id's
 * range, and the cell count; failures return RT_ERR_IO (cannot open) or
 * RT_ERR_PARSE with "FILE:LINE: message", and leave owner[] unspecified. The file is read
 * as every input is (rt_file_read.h): a regular text file of at most
 * rt_map_file_max_bytes(dims): room for every cell's id with spaces and comments.
 */
#ifndef RT_MAP_FILE_H
#define RT_MAP_FILE_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "rt_replicas.h"
#include "rt_status.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The largest map file read for this grid: 16 bytes per cell and 1 MiB more. */
size_t rt_map_file_max_bytes(const int dims[3]);

/* owner must hold dims[0] * dims[1] * dims[2] entries. */
rt_status rt_map_file_parse(const char *name, const char *text, size_t length, const int dims[3], int nodes,
                            int32_t *owner, char *msg, size_t msg_len);
/* The same, read from the file PATH. */
rt_status rt_map_file_read(const char *path, const int dims[3], int nodes, int32_t *owner, char *msg, size_t msg_len);

/* Writes the table to a stream the caller owns (flushed, not closed); RT_ERR_IO naming `name`
 * if it cannot be written. */
rt_status rt_map_file_write(FILE *fp, const char *name, const int dims[3], int nodes, const int32_t *owner, char *msg,
                            size_t msg_len);

/* The longest entry (one cell's owners) a map file may hold, bytes. */
#define RT_MAP_FILE_MAX_WORD 4095
#define RT_MAP_FILE_MAX_WORD_TEXT "4095"

/* Version 1 or 2. first (cells + 1 entries) receives rt_replicas.h's offsets and *extra a
 * malloc'd array of *extra_count extra owners (free() it; NULL on failure). */
rt_status rt_map_file_parse_replicas(const char *name, const char *text, size_t length, const int dims[3], int nodes,
                                     int32_t *owner, uint32_t *first, int32_t **extra, size_t *extra_count, char *msg,
                                     size_t msg_len);
rt_status rt_map_file_read_replicas(const char *path, const int dims[3], int nodes, int32_t *owner, uint32_t *first,
                                    int32_t **extra, size_t *extra_count, char *msg, size_t msg_len);
/* Writes version 2 when replicas (may be NULL) lists an extra owner, else version 1. */
rt_status rt_map_file_write_replicas(FILE *fp, const char *name, const int dims[3], int nodes, const int32_t *owner,
                                     const rt_replicas *replicas, char *msg, size_t msg_len);

#ifdef __cplusplus
}
#endif
#endif
