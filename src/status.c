/* status.c - names of the kernel's status codes. */
#include "rt_status.h"

const char *rt_status_name(rt_status status)
{
    switch (status) {
    case RT_OK: return "ok";
    case RT_ERR_INVALID: return "invalid argument";
    case RT_ERR_PARSE: return "parse error";
    case RT_ERR_LIMIT: return "limit exceeded";
    case RT_ERR_NOMEM: return "out of memory";
    case RT_ERR_IO: return "input/output error";
    case RT_ERR_CAPACITY: return "buffer too small";
    }
    return "unknown status";
}
