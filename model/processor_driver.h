// processor_driver.h - what runs an intersection processor's state machine
// (IntersectionProcessor::act: take up, wait for the arrival, fetch, step, hand over) and when.
// The machine runs until it must wait and says what for (ProcessorWake); the driver waits for
// that and runs it again.
//
// Three ways to drive it, chosen at elaboration from the processor's setup:
//   - a thread (a cluster, whose bus crossings wait in b_transport): run_thread() loops;
//   - methods on a flat torus: the processor's method woken (by the timer, the queue or room
//     for the outputs) asks the machine's activation queue (activation_queue.h) to run the
//     machine later in the same evaluation phase, after every process that was runnable when it
//     began, where a thread would run (after the delta's methods); so it takes up a packet after
//     every delivery and release of that delta cycle, whichever SystemC ran first. (A processor
//     alone notifies its own act event at once, to the same effect);
//   - with unbounded buffers (ProcessorSetup::order_after) only its own node's deliveries can
//     come before it in a delta: it then runs at once, or right after its unit's delivery round,
//     and the activation queue serves only a wake while its unit still has an arrival due; its
//     queue tells it of a packet in the pushing delta (the driver is the queue's reader).
// Timed waits end through the machine's wake calendar (wake_calendar.h) where the machine has
// one, which wakes the driver in the first delta of the time, as the timer event would.
//
// Usage: the processor owns one, built with the events its machine waits on; its processes
// (registered by the processor) call woken(), room_released(), run() and run_thread().
#pragma once

#include <cstdint>
#include <systemc>

#include "activation_queue.h"
#include "delivery_round_if.h"
#include "packet_queue.h"
#include "timed_wake.h"
#include "wake_calendar.h"

namespace torusrt {

class IntersectionProcessor;

// What the state machine waits for: its timer (the owed delay), its queue, its queue or room
// for its outputs, or the processor side of its communication unit (--flow none, a packet held).
enum class ProcessorWake : uint8_t { start, timer, queue, queue_or_room, out_room };

class ProcessorDriver final : public WakeCalendar::Client, public ActivationQueue::Client, public PacketQueueReader {
  public:
    // What the machine waits on: its input queue (a packet in it), a slot released in a buffer
    // its outputs go to (`room`), the processor side taking packets again (`out_room`); none is
    // used before the simulation starts. `calendar`, `activations` and `order_after` as in
    // ProcessorSetup (null: the driver's own events).
    ProcessorDriver(IntersectionProcessor &machine, PacketQueue &queue, sc_core::sc_event &room,
                    sc_core::sc_event &out_room, WakeCalendar *calendar, ActivationQueue *activations,
                    DeliveryRoundIf *order_after);

    // For the machine: what it waited for last, and the delay it owes when it says Wake::timer.
    ProcessorWake waited_for() const { return m_wake; }
    void owe(const sc_core::sc_time &delay) { m_delay = delay; }

    // The method driver's events: the owed wait is over, and run the machine (notified at once).
    const sc_core::sc_event &timer_event() const { return m_timer; }
    const sc_core::sc_event &act_event() const { return m_act; }

    // The processor's methods: woken by the timer, the queue or the processor side; woken by a
    // released slot; the act event.
    void woken()
    {
        m_woken = true;
        ask_to_act();
    }
    void room_released()
    {
        m_room_woken = true;
        ask_to_act();
    }
    void run();
    // The thread driver's loop.
    void run_thread();

  private:
    // Runs the machine after the processes runnable now (once however often it is asked).
    void ask_to_act();
    void activate() override
    {
        m_act_asked = false;
        run();
    }
    void wake_due() override { woken(); }     // the calendar's timer
    void queue_ready() override { woken(); }  // a packet joined the empty queue (told at once)

    IntersectionProcessor &m_machine;
    ProcessorWake m_wake = ProcessorWake::start;
    bool m_woken = false, m_room_woken = false;  // method driver: what woke it this delta
    bool m_act_asked = false, m_acting = false;
    DeliveryRoundIf *m_unit;  // order_after: its node's unit
    ActivationQueue *m_activations;
    TimedWake m_timer_wake;           // ends a timed wait: the machine's calendar, or m_timer
    sc_core::sc_time m_delay, m_due;  // the owed wait and when it ends
    PacketQueue &m_queue;
    sc_core::sc_event &m_room, &m_out_room;
    // On the calendar's path (a flat machine with a positive link time) no event is touched per
    // step.
    sc_core::sc_event m_timer;  // method driver: the owed wait is over
    sc_core::sc_event m_act;    // method driver: run the machine (notified at once)
};

}  // namespace torusrt
