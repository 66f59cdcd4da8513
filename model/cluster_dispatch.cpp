// cluster_dispatch.cpp - dispatch policies and the dispatcher's process.
#include "cluster_dispatch.h"

#include <cstdint>
#include <functional>
#include <stdexcept>

#include "name_registry.h"

#include "sim_now.h"

namespace torusrt {

namespace {

class RoundRobinDispatch : public DispatchPolicyIf {
  public:
    int candidate(const std::vector<IntersectionProcessor *> &processors) const override
    {
        return (m_next + 1) % static_cast<int>(processors.size());
    }
    void chosen(int k) override { m_next = k; }

  private:
    int m_next = -1;
};

class ShortestQueueDispatch : public DispatchPolicyIf {
  public:
    int candidate(const std::vector<IntersectionProcessor *> &processors) const override
    {
        int best = 0;
        size_t best_load = SIZE_MAX;
        for (size_t k = 0; k < processors.size(); k++) {
            size_t load = processors[k]->queue().size() + (processors[k]->busy() ? 1 : 0);
            if (load < best_load) {
                best = static_cast<int>(k);
                best_load = load;
            }
        }
        return best;
    }
};

using DispatchFactory = std::function<std::unique_ptr<DispatchPolicyIf>()>;

const NameRegistry<DispatchFactory> &dispatch_registry()
{
    static const NameRegistry<DispatchFactory> table = {
        {"round-robin", [] { return std::make_unique<RoundRobinDispatch>(); }},
        {"shortest-queue", [] { return std::make_unique<ShortestQueueDispatch>(); }},
    };
    return table;
}

}  // namespace

std::vector<std::string> dispatch_policy_names() { return dispatch_registry().names(); }

std::unique_ptr<DispatchPolicyIf> make_dispatch_policy(const std::string &name)
{
    const DispatchFactory *make = dispatch_registry().find(name);
    if (!make) throw std::invalid_argument("unknown dispatch policy '" + name + "'");
    return (*make)();
}

ClusterDispatcher::ClusterDispatcher(sc_core::sc_module_name name, const MachineConfig &config,
                                     std::vector<IntersectionProcessor *> processors, const PacketQueueSetup &inbox)
    : sc_module(name), in("in"), bus_socket("bus_socket"), m_processors(std::move(processors)),
      m_policy(make_dispatch_policy(config.dispatch)),
      m_inbox(std::string(basename()) + ".queue", config.queue_capacity, inbox),
      m_time(config.style == TimingStyle::lt), m_flow(config.flow), m_dispatched(m_processors.size(), 0)
{
    in.bind(*this);
    SC_HAS_PROCESS(ClusterDispatcher);
    SC_THREAD(run);
}

bool ClusterDispatcher::place(const TimedPacket &tp)
{
    m_target = -1;  // unbounded or --flow none: chosen once the packet has arrived
    if (m_flow == FlowControl::none || m_inbox.capacity() == 0) return true;
    int k = m_policy->candidate(m_processors);
    BufferSpace &room = m_processors[k]->queue().space_for(tp);
    if (!room.available()) {
        room.on_release(m_room);
        return false;
    }
    room.take();
    m_policy->chosen(k);
    m_target = k;
    return true;
}

void ClusterDispatcher::run()
{
    for (;;) {
        if (m_inbox.empty()) m_time.sync();
        sc_core::sc_time before = m_time.now();
        TimedPacket tp = m_inbox.take_first([this](const TimedPacket &c) { return place(c); }, m_room);
        if (m_target >= 0) tp.reserved = true;  // place() took its slot
        m_time.settle(before);                  // it may have waited for room
        m_time.advance_to(tp.stamp);            // cannot move a packet before it arrived
        int k = m_target >= 0 ? m_target : m_policy->choose(m_processors);
        m_busy_flag = true;
        // Packet write over the bus; the delay argument carries this process's local offset.
        sc_core::sc_time delay = m_time.now() - sim_now();
        m_trans.set_command(tlm::TLM_WRITE_COMMAND);
        m_trans.set_address(static_cast<uint64_t>(k));
        m_trans.set_data_ptr(reinterpret_cast<unsigned char *>(&tp.packet));
        m_trans.set_data_length(sizeof(rt_packet));
        m_trans.set_streaming_width(sizeof(rt_packet));
        m_trans.set_response_status(tlm::TLM_INCOMPLETE_RESPONSE);
        bus_socket->b_transport(m_trans, delay);
        if (m_trans.is_response_error()) SC_REPORT_FATAL(name(), "packet transfer over the cluster bus failed");
        m_time.advance_to(sim_now() + delay);
        m_busy_flag = false;
        tp.stamp = m_time.now();
        m_dispatched[k]++;
        m_processors[k]->accept(tp);
        m_time.settle(tp.stamp);  // the processor's queue may have been full
    }
}

}  // namespace torusrt
