// wake_calendar.h - the machine's one calendar of timed wake-ups. Every communication unit (and
// every method-driven processor) that wants to run again at a later time asks the calendar
// instead of notifying an event of its own; the calendar holds the earliest time each client
// wants in a compact min-heap and keeps ONE SystemC event, notified for the earliest time of all.
// At each such time its SC_METHOD wakes every client due in a fixed order: time, then client
// (the order they were added: node by node), then sequence (the order the wakes were asked for),
// so the order of simultaneous wakes is the model's, not the SystemC kernel's; then it re-arms
// for the next time. A hop costs a push and a pop on a small heap of warm keys and the kernel's
// timed queue holds one entry instead of one per node.
//
// Lazy deletion: a client has at most one live wake, its earliest; asking for an earlier one
// pushes a new key and leaves the later one in the heap, skipped when it comes to the top. A
// client woken asks again for its next time, if any.
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
    // Keys in the heap, live and stale.
    size_t heap_size() const { return m_heap.size(); }

  private:
    static constexpr uint64_t kNone = ~uint64_t{0};
    // Client ids below 2^24; 40 bits of sequence.
    static constexpr int kSeqBits = 40;
    struct Key {
        uint64_t when;  // sc_time value
        uint64_t order; // client << kSeqBits | sequence
    };
    struct Slot {
        Client *client;
        uint64_t when;  // its live wake, or kNone
        uint64_t order; // the live wake's key order (the older keys of the client are stale)
    };
    static bool later(const Key &a, const Key &b) { return a.when != b.when ? a.when > b.when : a.order > b.order; }
    bool stale(const Key &k) const { return m_slots[k.order >> kSeqBits].order != k.order; }
    Key pop();
    void run();
    // Drops stale keys from the top and notifies the event for the earliest live wake.
    void arm(uint64_t now);

    std::vector<Key> m_heap;
    std::vector<Slot> m_slots;
    uint64_t m_seq = 0;
    uint64_t m_notified = kNone; // time the event is notified for, or kNone
    sc_core::sc_event m_due;
};

}  // namespace torusrt
