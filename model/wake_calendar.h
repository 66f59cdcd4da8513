// wake_calendar.h - the machine's one calendar of timed wake-ups. Every communication unit (and
// every method-driven processor) that wants to run again at a later time asks the calendar
// instead of notifying an event of its own; the calendar holds the earliest time each client
// wants and keeps ONE SystemC event, notified for the earliest time of all. At each such time
// its SC_METHOD wakes every client due in a fixed order: time, then client (the order they were
// added: node by node), so the order of simultaneous wakes is the model's, not the SystemC
// kernel's; then it re-arms for the next time. The kernel's timed queue holds one entry instead
// of one per node.
//
// A client has at most one wake, its earliest: asking for an earlier time replaces it, asking for
// a later one while it is pending changes nothing, and a client woken asks again for its next
// time, if any. So the calendar is a tournament tree over the clients (one leaf each, a node
// holding the earlier of its two children's wakes): asking climbs from the client's leaf only
// while it beats what is there, waking the earliest replays its one path to the root. That is
// fewer steps than a heap's push and pop of the same wake, and it keeps no stale entries.
#pragma once

#include <cstdint>
#include <systemc>
#include <vector>

namespace torusrt {

class WakeCalendar : public sc_core::sc_module {
  public:
    // What the calendar wakes: run at the time it asked for, from the calendar's method.
    class Client {
      public:
        virtual void wake_due() = 0;

      protected:
        ~Client() = default;
    };

    explicit WakeCalendar(sc_core::sc_module_name name);

    // Adds `client` (elaboration); returns its id, its rank among simultaneous wakes.
    int add(Client &client);
    // Wakes client `id` at `when` (later than simulation time) unless it is already due no later.
    void wake_at(int id, const sc_core::sc_time &when);
    // The time client `id` will be woken, if it is to be (else false).
    bool due_time(int id, sc_core::sc_time &when) const;
    // Clients with a wake pending.
    size_t pending() const;

  private:
    static constexpr uint64_t kNone = ~uint64_t{0};
    // Whether client a's wake comes before client b's: time, then client.
    bool before(int32_t a, int32_t b) const { return m_when[a] != m_when[b] ? m_when[a] < m_when[b] : a < b; }
    int32_t earliest() const { return m_win[1]; }
    // Clears the wake of `id`, the earliest of all, and replays its path.
    void clear_earliest(int32_t id);
    void run();
    // Notifies the event for the earliest wake, if it is earlier than the one notified.
    void arm(uint64_t now);

    std::vector<Client *> m_clients;
    size_t m_leaves = 1;           // leaves of the tree: a power of two, at least the clients
    std::vector<uint64_t> m_when;  // per leaf, the client's wake (sc_time value) or kNone
    std::vector<int32_t> m_win;    // per tree node (1 is the root, leaf j at m_leaves + j), the earliest leaf below
    bool m_asked = false;          // a wake was asked for (no client may be added then)
    uint64_t m_notified = kNone;   // time the event is notified for, or kNone (0 while run() wakes)
    sc_core::sc_event m_due;
};

}  // namespace torusrt
