// signal_cleanup.h - files and folders to remove when the run is stopped by a signal.
//
// Usage:
//   stop_on_signals("torusrt-sim");              // first thing in main: the stopping signals end the run
//   size_t slot = remove_on_signal(tmp_path);   // a stopping signal now removes it
//   ...
//   forget_on_signal(slot);                      // renamed or removed by the program itself
// The stopping signals are SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGUSR1, SIGUSR2, SIGALRM and
// SIGPIPE. The handler is async-signal-safe: it walks a list of paths made beforehand (newest
// first, so a FIFO goes before its folder), calls only unlink, rmdir, write and _exit, prints
// "PROGRAM: stopped by SIGNAME" and exits 128 + the signal's number. A signal the process was
// started ignoring (nohup) stays ignored. In a child made by fork the handler only exits: the
// parent removes the files and reports.
#pragma once

#include <csignal>
#include <cstddef>
#include <string>

namespace torusrt {

// Installs the handler for the stopping signals and unblocks them (one that arrived while they
// were blocked is handled now); `program` starts its message. Called first thing in main, and
// again by run_cli, where it only changes the name.
void stop_on_signals(const char *program);
// Registers PATH (a file, or a folder when `folder`); installs the handler if not yet done.
size_t remove_on_signal(const std::string &path, bool folder = false);
// Drops the registration of `slot` (the path is no longer the program's to remove).
void forget_on_signal(size_t slot);

// Blocks the stopping signals in this thread while alive; a thread started meanwhile keeps them
// blocked, so the handler runs in the main thread only (a write to a closed pipe from such a
// thread fails with EPIPE instead).
class SignalsBlocked {
  public:
    SignalsBlocked();
    ~SignalsBlocked();
    SignalsBlocked(const SignalsBlocked &) = delete;
    SignalsBlocked &operator=(const SignalsBlocked &) = delete;

  private:
    sigset_t m_old;
};

}  // namespace torusrt
