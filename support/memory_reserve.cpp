// memory_reserve.cpp - a reserve block freed by the new-handler when an allocation fails.
#include "memory_reserve.h"

#include <cstdlib>
#include <exception>
#include <new>

namespace torusrt {

namespace {

// The reserve in blocks, one given back per refused allocation: a failure something catches and
// drops (a std::ostream only sets its badbit) leaves the rest for the next failure's unwinding.
constexpr int kBlocks = 8;
void *g_blocks[kBlocks] = {};

void release_reserve_and_throw()
{
    bool freed = false;
    for (void *&block : g_blocks)
        if (block != nullptr) {
            std::free(block);
            block = nullptr;
            freed = true;
            break;
        }
    // While an exception travels (a destructor allocating as the stack unwinds, after a failed
    // malloc our code turned into std::bad_alloc), a throw would end the process: the
    // allocation is tried again in the block just freed.
    if (freed && std::uncaught_exceptions() > 0) return;
    throw std::bad_alloc();  // the allocation that failed is not retried: the run ends
}

}  // namespace

void keep_memory_reserve(size_t bytes)
{
    for (void *&block : g_blocks)
        if (block == nullptr) block = std::malloc(bytes / kBlocks);
    std::set_new_handler(release_reserve_and_throw);
}

}  // namespace torusrt
