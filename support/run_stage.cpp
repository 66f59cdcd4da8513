// run_stage.cpp - the run's current stage in a fixed buffer.
#include "run_stage.h"

#include <algorithm>
#include <cstring>

namespace torusrt {

namespace {

char g_stage[128] = "";

}  // namespace

void set_run_stage(const std::string &what)
{
    size_t n = std::min(what.size(), sizeof g_stage - 1);
    std::memcpy(g_stage, what.data(), n);
    g_stage[n] = '\0';
}

const char *run_stage() { return g_stage; }

}  // namespace torusrt
