// bus_arbiter.h - the cluster bus's dedicated arbitration hardware: given the requesters whose
// request lines are up, picks the one to grant. The bus reaches its arbiter through an
// sc_port<BusArbiterIf>, so a new policy is one new class registered by name in make_arbiter().
//
// Requester indices on a cluster bus: 0..m-1 are the processors, m is the communication unit.
#pragma once

#include <memory>
#include <string>
#include <systemc>
#include <vector>

namespace torusrt {

class BusArbiterIf : public virtual sc_core::sc_interface {
  public:
    // The requester to grant among those with requesting[i] true; -1 if none requests.
    virtual int pick(const std::vector<bool> &requesting) = 0;
    // Policy name as given on the command line.
    virtual const char *policy() const = 0;
};

// Base of the arbiter modules: an sc_module exporting BusArbiterIf (bind the bus's port to it).
class BusArbiter : public sc_core::sc_module, public BusArbiterIf {
  protected:
    using sc_core::sc_module::sc_module;
};

// Round-robin: the search starts one past the last grantee, so every requester is served
// within one round of the others (at most requesters - 1 transfers ahead of it).
class RoundRobinArbiter : public BusArbiter {
  public:
    RoundRobinArbiter(sc_core::sc_module_name name, int requesters);
    int pick(const std::vector<bool> &requesting) override;
    const char *policy() const override { return "round-robin"; }

  private:
    int m_requesters;
    int m_last;  // last grantee (starts at requesters - 1, so requester 0 is searched first)
};

// Fixed priority: `top` (if >= 0) first, then the others in ascending index order (lower index
// = higher priority). In a cluster `top` is the communication unit (index m), so packets from the
// network are never held behind the processors' object reads; the processors rank 0 > 1 > ... .
// A saturated bus starves the lowest-priority processor.
class FixedPriorityArbiter : public BusArbiter {
  public:
    FixedPriorityArbiter(sc_core::sc_module_name name, int requesters, int top);
    int pick(const std::vector<bool> &requesting) override;
    const char *policy() const override { return "fixed-priority"; }

  private:
    int m_requesters, m_top;
};

// The policy names make_arbiter knows, in the help's order.
std::vector<std::string> arbiter_policy_names();
// Builds an arbiter by policy name ("round-robin", "fixed-priority"); `top` is the requester the
// fixed-priority policy ranks first (-1: none). Throws std::invalid_argument for an unknown name.
std::unique_ptr<BusArbiter> make_arbiter(const std::string &policy, sc_core::sc_module_name name, int requesters,
                                         int top);

}  // namespace torusrt
