// processor_driver.cpp - the thread and method drivers of an intersection processor's state
// machine, and the order it runs in within a delta cycle.
#include "processor_driver.h"

#include "intersection_processor.h"
#include "sim_now.h"

namespace torusrt {

ProcessorDriver::ProcessorDriver(IntersectionProcessor &machine, PacketQueue &queue, sc_core::sc_event &room,
                                 sc_core::sc_event &out_room, WakeCalendar *calendar, ActivationQueue *activations,
                                 DeliveryRoundIf *order_after)
    : m_machine(machine), m_unit(order_after), m_activations(activations), m_timer_wake(calendar, *this, m_timer),
      m_queue(queue), m_room(room), m_out_room(out_room)
{
}

void ProcessorDriver::run_thread()
{
    for (;;) {
        m_wake = m_machine.act();
        if (m_wake == ProcessorWake::timer) sc_core::wait(m_delay);
        else if (m_wake == ProcessorWake::queue) sc_core::wait(m_queue.not_empty_event());
        else if (m_wake == ProcessorWake::queue_or_room) sc_core::wait(m_queue.not_empty_event() | m_room);
        else sc_core::wait(m_out_room);
    }
}

void ProcessorDriver::ask_to_act()
{
    if (!m_activations) {
        m_act.notify();  // immediate: run() runs after the processes runnable now
        return;
    }
    if (m_act_asked) return;
    m_act_asked = true;
    if (m_unit && !m_acting) {
        if (m_unit->run_after_delivery(*this)) return;
        if (!m_unit->arrival_due()) {
            activate();  // nothing of its node is still to come in this delta
            return;
        }
    }
    m_activations->request(*this);
}

void ProcessorDriver::run()
{
    // Only what the machine waits for moves it on (as for a thread): a release of a buffer it
    // once waited on may come while it steps or waits on its queue alone.
    bool go = m_woken || (m_room_woken && m_wake == ProcessorWake::queue_or_room);
    if (m_wake == ProcessorWake::timer) go = m_woken && sim_now() >= m_due;
    m_woken = m_room_woken = false;
    if (!go) return;
    m_acting = true;
    m_wake = m_machine.act();
    m_acting = false;
    if (m_wake != ProcessorWake::timer) return;
    m_due = sim_now() + m_delay;
    if (m_delay != sc_core::SC_ZERO_TIME) m_timer_wake.at(m_due, m_delay);
    else m_timer.notify(sc_core::SC_ZERO_TIME);  // the next delta, as wait(SC_ZERO_TIME)
}

}  // namespace torusrt
