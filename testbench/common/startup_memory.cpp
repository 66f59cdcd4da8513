// startup_memory.cpp - the terminate handler for the time before main (startup_memory.h).
#include "startup_memory.h"

#include <cstdlib>
#include <cstring>
#include <exception>
#include <new>
#include <unistd.h>

namespace torusrt {

namespace {

const char *g_program = "torusrt";
std::terminate_handler g_before = nullptr;

void say(const char *text)
{
    if (write(STDERR_FILENO, text, std::strlen(text)) < 0) return;  // nothing more can be done
}

// std::bad_alloc escaping a static constructor: the message, exit 1. Anything else: as before.
[[noreturn]] void refused_at_start()
{
    if (std::exception_ptr e = std::current_exception()) {
        try {
            std::rethrow_exception(e);
        } catch (const std::bad_alloc &) {
            say(g_program);
            say(": out of memory while starting: the system refused the memory its libraries set up before "
                "the run (ulimit -v is too small for the program itself)\n");
            _exit(1);
        } catch (...) {
        }
    }
    if (g_before) g_before();
    std::abort();
}

void install(int argc, char **argv, char **)
{
    if (argc > 0 && argv && argv[0]) {
        const char *slash = std::strrchr(argv[0], '/');
        g_program = slash ? slash + 1 : argv[0];
    }
    g_before = std::set_terminate(&refused_at_start);
}

}  // namespace

// Runs before the shared libraries' constructors (and before this program's own).
__attribute__((section(".preinit_array"), used)) void (*const torusrt_startup_memory)(int, char **, char **) = &install;

void startup_done()
{
    if (std::get_terminate() == &refused_at_start) std::set_terminate(g_before);
}

}  // namespace torusrt
