// signal_cleanup.h - files and folders to remove when the run is stopped by a signal.
//
// Usage:
//   size_t slot = remove_on_signal(tmp_path);   // SIGINT, SIGTERM or SIGHUP now removes it
//   ...
//   forget_on_signal(slot);                      // renamed or removed by the program itself
// The handler is async-signal-safe: it walks a list of paths made beforehand (newest first, so
// a FIFO goes before its folder), calls only unlink, rmdir and _exit, and exits 128 + the
// signal's number. A signal the process was started ignoring (nohup) stays ignored.
#pragma once

#include <csignal>
#include <cstddef>
#include <string>

namespace torusrt {

// Registers PATH (a file, or a folder when `folder`) and installs the handler on first use.
size_t remove_on_signal(const std::string &path, bool folder = false);
// Drops the registration of `slot` (the path is no longer the program's to remove).
void forget_on_signal(size_t slot);

// Blocks SIGINT, SIGTERM and SIGHUP in this thread while alive; a thread started meanwhile
// keeps them blocked, so the handler runs in the main thread only.
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
