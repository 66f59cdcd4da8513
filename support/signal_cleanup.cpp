// signal_cleanup.cpp - the list of paths a stopping signal removes. The list only changes with
// the three signals blocked in this thread, and the threads the program starts block them, so
// the handler never sees it half changed.
#include "signal_cleanup.h"

#include <atomic>
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

const int kSignals[] = {SIGINT, SIGTERM, SIGHUP};

extern "C" void on_stop_signal(int sig)
{
    for (size_t i = g_used.load(); i-- > 0;) {
        const char *p = g_slots[i].path.load();
        if (p) g_slots[i].folder ? rmdir(p) : unlink(p);
    }
    _exit(128 + sig);
}

void install_handler()
{
    for (int sig : kSignals) {
        struct sigaction old {};
        if (sigaction(sig, nullptr, &old) == 0 && old.sa_handler == SIG_IGN) continue;
        struct sigaction sa {};
        sa.sa_handler = on_stop_signal;
        sigfillset(&sa.sa_mask);
        sigaction(sig, &sa, nullptr);
    }
}

}  // namespace

SignalsBlocked::SignalsBlocked()
{
    sigset_t set;
    sigemptyset(&set);
    for (int sig : kSignals) sigaddset(&set, sig);
    pthread_sigmask(SIG_BLOCK, &set, &m_old);
}

SignalsBlocked::~SignalsBlocked() { pthread_sigmask(SIG_SETMASK, &m_old, nullptr); }

size_t remove_on_signal(const std::string &path, bool folder)
{
    char *copy = new char[path.size() + 1];
    std::memcpy(copy, path.c_str(), path.size() + 1);
    SignalsBlocked blocked;
    if (g_capacity == 0) install_handler();
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
