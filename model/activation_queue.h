// activation_queue.h - the machine's one queue of processor activations. A flat processor woken
// in an evaluation phase (by its timer, its queue or room for its outputs) asks to run its
// state machine after every process runnable now, where a thread would run; instead of each
// processor notifying an event of its own at once, it joins this queue, and the queue's one
// method, notified at once when the first one joins, runs them in the order they joined: the
// order in which their own methods would have run. A processor joins at most once a round.
// At 512 nodes this saves touching a cold event and a cold process for every step. (With
// unbounded buffers a processor asks only while its node still has an arrival due now; else it
// runs at once or after its unit's delivery round: intersection_processor.h.)
#pragma once

#include <systemc>
#include <vector>

namespace torusrt {

class ActivationQueue : public sc_core::sc_module {
  public:
    // What the queue runs.
    class Client {
      public:
        virtual void activate() = 0;

      protected:
        ~Client() = default;
    };

    explicit ActivationQueue(sc_core::sc_module_name name);

    // Runs `client` after the processes runnable now (the caller asks once a round).
    void request(Client &client)
    {
        if (m_waiting.empty()) m_run.notify();  // immediate: the method runs later in this evaluation phase
        m_waiting.push_back(&client);
    }

  private:
    void run();

    std::vector<Client *> m_waiting, m_running;
    sc_core::sc_event m_run;
};

}  // namespace torusrt
