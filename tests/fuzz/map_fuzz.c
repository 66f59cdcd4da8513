/* map_fuzz.c - libFuzzer target: the map-file reader (rt_map_file_parse, what
 * rt_map_file_read runs on a file's text) on a 2 x 3 x 2 grid of 5 nodes, and for an
 * accepted table a check that every id is a node. Built by bench/fuzz.sh with libFuzzer and,
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
    char msg[256];
    if (rt_map_file_parse("fuzz.map", (const char *)data, size, dims, nodes, owner, msg, sizeof msg) != RT_OK)
        return 0;
    for (int i = 0; i < cells; i++)
        if (owner[i] < 0 || owner[i] >= nodes) abort(); /* an accepted table names only nodes */
    return 0;
}
