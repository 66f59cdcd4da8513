// activation_queue.cpp - the method that runs the processors that asked, in order.
#include "activation_queue.h"

#include <utility>

namespace torusrt {

ActivationQueue::ActivationQueue(sc_core::sc_module_name name) : sc_module(name)
{
    SC_HAS_PROCESS(ActivationQueue);
    SC_METHOD(run);
    sensitive << m_run;
    dont_initialize();
}

void ActivationQueue::run()
{
    // A client that asks while these run (none does on a flat torus) runs in a round of its own
    // right after them: a method cannot wake itself by an immediate notification.
    while (!m_waiting.empty()) {
        std::swap(m_waiting, m_running);
        for (Client *c : m_running) c->activate();
        m_running.clear();
    }
}

}  // namespace torusrt
