// bus_arbiter.cpp - round-robin and fixed-priority arbitration, and the registry by name.
#include "bus_arbiter.h"

#include <algorithm>
#include <functional>
#include <stdexcept>

#include "name_registry.h"

namespace torusrt {

RoundRobinArbiter::RoundRobinArbiter(sc_core::sc_module_name name, int requesters)
    : BusArbiter(name), m_requesters(requesters), m_last(requesters - 1)
{
}

int RoundRobinArbiter::pick(const std::vector<bool> &requesting)
{
    for (int step = 1; step <= m_requesters; step++) {
        int i = (m_last + step) % m_requesters;
        if (i < static_cast<int>(requesting.size()) && requesting[i]) {
            m_last = i;
            return i;
        }
    }
    return -1;
}

FixedPriorityArbiter::FixedPriorityArbiter(sc_core::sc_module_name name, int requesters, int top)
    : BusArbiter(name), m_requesters(requesters), m_top(top)
{
}

int FixedPriorityArbiter::pick(const std::vector<bool> &requesting)
{
    int n = std::min(m_requesters, static_cast<int>(requesting.size()));
    if (m_top >= 0 && m_top < n && requesting[m_top]) return m_top;
    for (int i = 0; i < n; i++)
        if (requesting[i]) return i;
    return -1;
}

namespace {

using Factory = std::function<std::unique_ptr<BusArbiter>(sc_core::sc_module_name, int, int)>;

const NameRegistry<Factory> &registry()
{
    static const NameRegistry<Factory> table = {
        {"round-robin",
         [](sc_core::sc_module_name n, int r, int) { return std::make_unique<RoundRobinArbiter>(n, r); }},
        {"fixed-priority",
         [](sc_core::sc_module_name n, int r, int top) { return std::make_unique<FixedPriorityArbiter>(n, r, top); }},
    };
    return table;
}

}  // namespace

std::vector<std::string> arbiter_policy_names() { return registry().names(); }

std::unique_ptr<BusArbiter> make_arbiter(const std::string &policy, sc_core::sc_module_name name, int requesters,
                                         int top)
{
    const Factory *make = registry().find(policy);
    if (!make) throw std::invalid_argument("unknown bus arbiter policy '" + policy + "'");
    return (*make)(name, requesters, top);
}

}  // namespace torusrt
