// delta_commit.h - a call made in the update phase of the delta cycle in which it was requested:
// after every process of that delta has run, so whatever the call decides does not depend on
// the order in which SystemC ran them (the way an sc_signal's new value takes effect). An
// SC_METHOD that must act as a thread would, after the delta's other processes, requests it.
// The call may notify events with a delay (zero: the next delta), never immediately.
#pragma once

#include <functional>
#include <systemc>

namespace torusrt {

class DeltaCommit : public sc_core::sc_prim_channel {
  public:
    DeltaCommit(const char *name, std::function<void()> call) : sc_prim_channel(name), m_call(std::move(call)) {}
    // Makes the call once, in this delta's update phase (requests in one delta merge).
    void request() { request_update(); }

  private:
    void update() override { m_call(); }

    std::function<void()> m_call;
};

}  // namespace torusrt
