// signal_cleanup.cpp - the list of paths a stopping signal removes. The list only changes with
// the stopping signals blocked in this thread, and the threads the program starts block them,
// so the handler never sees it half changed.
#include "signal_cleanup.h"

#include "signal_cleanup_c.h"

#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <csignal>
#include <cstring>
#include <pthread.h>
#include <unistd.h>

namespace torusrt {

namespace {

struct Slot {
    std::atomic<const char *> path{nullptr};  // owned (new[]); null: free
    bool folder = false;
};

Slot *g_slots = nullptr;        // read by the handler
std::atomic<size_t> g_used{0};  // slots in use or freed, from the start
size_t g_capacity = 0;
bool g_installed = false;
pid_t g_pid = 0;          // the process that installed the handler (a forked child is not it)
char g_program[64] = "";  // the message's first word

struct StopSignal {
    int sig;
    const char *name;
};
const StopSignal kSignals[] = {{SIGINT, "SIGINT"},   {SIGTERM, "SIGTERM"}, {SIGHUP, "SIGHUP"},   {SIGQUIT, "SIGQUIT"},
                               {SIGUSR1, "SIGUSR1"}, {SIGUSR2, "SIGUSR2"}, {SIGALRM, "SIGALRM"}, {SIGPIPE, "SIGPIPE"}};

// Appends the C string `s` to buf[*n..cap) (async-signal-safe: no library call).
void append(char *buf, size_t cap, size_t *n, const char *s)
{
    while (*s && *n < cap) buf[(*n)++] = *s++;
}

extern "C" void on_stop_signal(int sig)
{
    if (getpid() != g_pid) _exit(128 + sig);  // a forked child: its parent cleans up and reports
    for (size_t i = g_used.load(); i-- > 0;) {
        const char *p = g_slots[i].path.load();
        if (p) g_slots[i].folder ? rmdir(p) : unlink(p);
    }
    char msg[160];
    const size_t cap = sizeof msg - 1;  // room for the newline
    size_t n = 0;
    append(msg, cap, &n, g_program);
    append(msg, cap, &n, g_program[0] ? ": stopped by " : "stopped by ");
    for (const StopSignal &s : kSignals)
        if (s.sig == sig) append(msg, cap, &n, s.name);
    if (sig == SIGPIPE) append(msg, cap, &n, " (the reader of an output closed the pipe)");
    msg[n++] = '\n';
    ssize_t ignored = write(STDERR_FILENO, msg, n);
    (void)ignored;
    _exit(128 + sig);
}

void install_handler()
{
    g_pid = getpid();
    g_installed = true;
    for (const StopSignal &s : kSignals) {
        struct sigaction old {};
        if (sigaction(s.sig, nullptr, &old) == 0 && old.sa_handler == SIG_IGN) continue;
        struct sigaction sa {};
        sa.sa_handler = on_stop_signal;
        sigfillset(&sa.sa_mask);
        sigaction(s.sig, &sa, nullptr);
    }
}

}  // namespace

SignalsBlocked::SignalsBlocked()
{
    sigset_t set;
    sigemptyset(&set);
    for (const StopSignal &s : kSignals) sigaddset(&set, s.sig);
    pthread_sigmask(SIG_BLOCK, &set, &m_old);
}

SignalsBlocked::~SignalsBlocked() { pthread_sigmask(SIG_SETMASK, &m_old, nullptr); }

void stop_on_signals(const char *program)
{
    {
        SignalsBlocked blocked;
        std::strncpy(g_program, program, sizeof g_program - 1);
        if (!g_installed) install_handler();
    }
    // A stopping signal held blocked across the program's own re-exec (huge_pages.h) is
    // delivered here, to the handler, instead of being lost to the default action.
    sigset_t set;
    sigemptyset(&set);
    for (const StopSignal &s : kSignals) sigaddset(&set, s.sig);
    pthread_sigmask(SIG_UNBLOCK, &set, nullptr);
}

size_t remove_on_signal(const std::string &path, bool folder)
{
    char *copy = new char[path.size() + 1];
    std::memcpy(copy, path.c_str(), path.size() + 1);
    SignalsBlocked blocked;
    if (!g_installed) install_handler();
    if (g_used.load() == g_capacity) {
        size_t grown = g_capacity ? 2 * g_capacity : 64;
        Slot *bigger = new Slot[grown];
        for (size_t i = 0; i < g_capacity; i++) {
            bigger[i].path.store(g_slots[i].path.load());
            bigger[i].folder = g_slots[i].folder;
        }
        delete[] g_slots;  // the handler cannot run while this thread blocks the signals
        g_slots = bigger;
        g_capacity = grown;
    }
    size_t slot = g_used.load();
    g_slots[slot].folder = folder;
    g_slots[slot].path.store(copy);
    g_used.store(slot + 1);
    return slot;
}

void forget_on_signal(size_t slot)
{
    SignalsBlocked blocked;
    if (slot >= g_used.load()) return;
    delete[] g_slots[slot].path.exchange(nullptr);
}

}  // namespace torusrt

// The C interface (signal_cleanup_c.h).
extern "C" void torusrt_stop_on_signals(const char *program) { torusrt::stop_on_signals(program); }

extern "C" int torusrt_mkstemp_removed_on_signal(char *tmpl, size_t *slot)
{
    torusrt::SignalsBlocked blocked;  // a signal between mkstemp and the registration: handled after it
    int fd = mkstemp(tmpl);
    if (fd >= 0) {
        int saved = errno;
        *slot = torusrt::remove_on_signal(tmpl);
        errno = saved;
    }
    return fd;
}

extern "C" void torusrt_forget_on_signal(size_t slot) { torusrt::forget_on_signal(slot); }
