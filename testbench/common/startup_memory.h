// startup_memory.h - an allocation the system refuses before main (a shared library's static
// constructors, SystemC's among them, under a small `ulimit -v`) ends the program with a message
// and exit 1 rather than an abort. The handler is installed from the executable's
// .preinit_array, which runs before any shared library's initialisers; run_cli puts the
// previous one back once main runs, where its own handlers take over.
#pragma once

namespace torusrt {

// main has started: the C++ runtime's own terminate handler again.
void startup_done();

}  // namespace torusrt
