/* map_fuzz.c - libFuzzer target: the map-file reader (rt_map_file_parse_replicas, what
 * rt_map_file_read_replicas runs on a file's text; versions 1 and 2) on a 2 x 3 x 2 grid of 5
 * nodes, and for an accepted table a check that every id is a node and that every cell's extra
 * owners ascend, differ from its primary owner and fit the offsets. Built by bench/fuzz.sh with libFuzzer and,
 * beside replay_main.c, for the CTest replay of tests/fuzz/map_corpus. */
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>

#include "rt_map_file.h"

#define FUZZ_MAX_INPUT (64u * 1024u)

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const int dims[3] = {2, 3, 2};
    enum { nodes = 5, cells = 2 * 3 * 2 };
    if (size > FUZZ_MAX_INPUT) return 0;
    int32_t owner[cells];
    uint32_t first[cells + 1];
    int32_t *extra = NULL;
    size_t count = 0;
    char msg[256];
    if (rt_map_file_parse_replicas("fuzz.map", (const char *)data, size, dims, nodes, owner, first, &extra, &count, msg,
                                   sizeof msg) != RT_OK)
        return 0;
    if (first[0] != 0 || first[cells] != count) abort();
    for (int i = 0; i < cells; i++) {
        if (owner[i] < 0 || owner[i] >= nodes) abort(); /* an accepted table names only nodes */
        for (uint32_t k = first[i]; k < first[i + 1]; k++)
            if (extra[k] < 0 || extra[k] >= nodes || extra[k] == owner[i] || (k > first[i] && extra[k - 1] >= extra[k]))
                abort();
    }
    free(extra);
    return 0;
}
