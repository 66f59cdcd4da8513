// memory_reserve.cpp - a reserve block freed by the new-handler when an allocation fails.
#include "memory_reserve.h"

#include <cstdlib>
#include <new>

namespace torusrt {

namespace {

void *g_reserve = nullptr;

void release_reserve_and_throw()
{
    std::free(g_reserve);
    g_reserve = nullptr;
    throw std::bad_alloc();  // the allocation that failed is not retried: the run ends
}

}  // namespace

void keep_memory_reserve(size_t bytes)
{
    if (g_reserve == nullptr) g_reserve = std::malloc(bytes);
    std::set_new_handler(release_reserve_and_throw);
}

}  // namespace torusrt
