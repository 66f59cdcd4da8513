// comm_unit.cpp - routing by the owner of the packet's current cell, delivery from the arrival
// queue, and holding packets while the next buffer is full.
#include "comm_unit.h"

#include <algorithm>
#include <string>

#include "flow_control.h"
#include "replica_choice.h"
#include "rt_step.h"
#include "sim_now.h"
#include "timed_packet.h"

namespace torusrt {

namespace {
// Links arrive from every neighbour: one per direction that has one.
size_t neighbours(const Routing &routing, int node)
{
    size_t n = 0;
    for (int dir = 0; dir < routing.ports(); dir++) n += routing.neighbour(node, dir) >= 0;
    return n;
}
}  // namespace

CommUnit::CommUnit(sc_core::sc_module_name name, int node, const Routing &routing, const rt_grid *grid,
                   const int32_t *cell_owner, const Setup &setup)
    : sc_module(name), link_in("link_in", neighbours(routing, node)), in("in"), local("local"), link_out("link_out"),
      m_pool(setup.pool ? setup.pool : &m_own_pool), m_wake(setup.calendar, *this, m_due), m_lookahead(setup.lookahead),
      m_route_at_once(setup.route_at_once), m_node(node), m_flow(setup.flow), m_routing(routing), m_grid(grid),
      m_owner(cell_owner), m_replicas(setup.replicas)
{
    m_port_of_dir.fill(-1);
    in.bind(*this);
    for (size_t i = 0; i < link_in.size(); i++) {
        m_inputs[i].m_unit = this;
        m_inputs[i].m_source = static_cast<int>(i);
        link_in[i].bind(m_inputs[i]);
    }
    SC_HAS_PROCESS(CommUnit);
    SC_METHOD(deliver);
    sensitive << m_due << m_run;
    dont_initialize();
    SC_METHOD(retry);
    sensitive << m_retry;
    dont_initialize();
}

CommUnit::LinkInSocket &CommUnit::next_link_in()
{
    if (static_cast<size_t>(m_processor_source) >= link_in.size())
        SC_REPORT_FATAL(
            name(), ("more incoming links than the node's " + std::to_string(link_in.size()) + " neighbours").c_str());
    return link_in[m_processor_source++];
}

void CommUnit::end_of_elaboration()
{
    m_held.resize(m_processor_source + 1);
    m_held_count.assign(m_processor_source + 1, 0);
}

void CommUnit::start_of_simulation()
{
    m_local_sink = local.operator->();  // bound now
    for (int dir = 0; dir < m_routing.ports(); dir++)
        if (m_port_of_dir[dir] >= 0) m_ways.set_sink(dir, link_out[m_port_of_dir[dir]]);
}

void CommUnit::connect_link(int dir, sc_core::sc_export<PacketSinkIf> &in, tlm::tlm_initiator_socket<> &socket,
                            CommUnit &receiver)
{
    bind_link_out(dir, in);
    LinkInSocket &target = receiver.next_link_in();
    // A crossing lands in the receiver's input for that socket, then in its arrival state.
    const Landing landing = receiver.last_link_landing();
    m_ways.set_lines(dir, landing.input, landing.arrivals);
    socket.bind(target);
}

int CommUnit::owner_of(const TimedPacket &p) const
{
    uint32_t cell = rt_packet_cell(m_grid, &p.packet);
    return m_replicas ? m_replicas->choose(m_node, cell, p.packet) : m_owner[cell];
}

CommUnit::Hop CommUnit::next_hop(TimedPacket &p, int owner)
{
    if (owner == m_node) return {m_local_sink, true, -1};
    // A tie on an even ring goes by the pixel's checkerboard: neighbouring pixels take opposite ways.
    int dir = m_routing.next_direction_by(m_node, owner, [&p] { return p.packet.x + p.packet.y; });
    PacketSinkIf *way = dir < 0 ? nullptr : m_ways.sink(dir);
    if (!way) SC_REPORT_FATAL(name(), "no link toward the packet's owner");
    p.vc = link_channel(m_flow, m_routing, p, m_node, dir);
    return {way, false, dir};
}

BufferSpace *CommUnit::room_for(const TimedPacket &p)
{
    TimedPacket q = p;
    q.last_dir = -1;  // it leaves the processor side
    return next_hop(q, owner_of(q)).sink->room_for(q);
}

bool CommUnit::holds(int source, uint32_t buffer) const
{
    if (!m_held_total || !m_held_count[source]) return false;
    const HeldFifo *f = held_fifo(source, buffer);
    return f && !f->packets.empty();
}

namespace {
// The first FIFO of `fifos` (sorted by buffer) whose buffer is not below `buffer`.
template <class Fifos> auto fifo_at_or_after(Fifos &fifos, uint32_t buffer)
{
    return std::lower_bound(fifos.begin(), fifos.end(), buffer, [](const auto &f, uint32_t b) { return f.buffer < b; });
}
}  // namespace

const CommUnit::HeldFifo *CommUnit::held_fifo(int source, uint32_t buffer) const
{
    const auto &fifos = m_held[source];
    auto it = fifo_at_or_after(fifos, buffer);
    return it != fifos.end() && it->buffer == buffer ? &*it : nullptr;
}

void CommUnit::hold(int source, uint32_t buffer, uint32_t packet)
{
    auto &fifos = m_held[source];
    auto it = fifo_at_or_after(fifos, buffer);
    if (it == fifos.end() || it->buffer != buffer) it = fifos.insert(it, HeldFifo{buffer, {}});
    it->packets.push_back(packet);
    m_held_count[source]++;
    m_held_total++;
}

bool CommUnit::processor_held() const { return m_held_total && m_held_count[processor_source()] > 0; }

void CommUnit::accept(const TimedPacket &p)
{
    // Called in the processor side's thread: it waits while one of its packets is held.
    while (processor_held()) sc_core::wait(m_processor_room);
    from_processor(m_pool->add(p, owner_of(p)));
}

void CommUnit::accept_pooled(PacketPool &pool, uint32_t handle)
{
    if (&pool != m_pool) {
        PacketSinkIf::accept_pooled(pool, handle);  // copied in
        return;
    }
    while (processor_held()) sc_core::wait(m_processor_room);
    m_pool->reuse(handle, owner_of(m_pool->at(handle)));
    from_processor(handle);
}

void CommUnit::from_processor(uint32_t packet)
{
    TimedPacket &p = m_pool->at(packet);
    p.last_dir = -1;  // it leaves the processor side
    const sc_core::sc_time stamp = p.stamp, now = sim_now();
    // Bound for a link: routed now, as it would be one delta on (nothing else is routed at this
    // time any more). Bound for this node's own processor, it waits for that delta, so the
    // processor takes up its next packet before this one joins its queue.
    if (m_route_at_once && stamp <= now && m_pool->owner(packet) != m_node &&
        (m_arrivals.empty() || m_arrivals.next_value() > now.value())) {
        if (forward(packet)) return;  // unbounded buffers: it always moves on (no credit held)
    }
    enqueue(packet, stamp, processor_source(), nullptr);
}

void CommUnit::on_space(const TimedPacket &, sc_core::sc_event &e) { m_processor_waiters.push_back(&e); }

void CommUnit::enqueue(uint32_t packet, const sc_core::sc_time &stamp, int source, BufferSpace *credit)
{
    sc_core::sc_time now = sim_now();
    m_pool->at(packet).stamp = stamp;
    m_pool->credit(packet) = credit;
    if (m_lookahead != sc_core::SC_ZERO_TIME && stamp <= now + m_lookahead) {
        route_in_quantum(packet, source);
        return;
    }
    sc_core::sc_time when = stamp > now + m_lookahead ? stamp - m_lookahead : now;
    m_arrivals.push(when, source, packet);
    wake_at(when);
}

void CommUnit::route_in_quantum(uint32_t packet, int source)
{
    const TimedPacket &p = m_pool->at(packet);
    uint32_t buffer = 2 * p.cls + p.vc;
    if (holds(source, buffer) || !forward(packet)) hold(source, buffer, packet);
}

void CommUnit::b_transport(int source, tlm::tlm_generic_payload &trans, sc_core::sc_time &delay)
{
    auto *ext = trans.get_extension<PacketExtension>();
    if (!ext || !ext->pool) {
        trans.set_response_status(tlm::TLM_GENERIC_ERROR_RESPONSE);
        return;
    }
    // The packet by handle (from another pool, moved into this one), arriving in the sender's
    // local time plus the link's annotated delay.
    uint32_t packet = m_pool->adopt(*ext->pool, ext->handle);
    if (m_pool->owner(packet) < 0) m_pool->reuse(packet, owner_of(m_pool->at(packet)));
    enqueue(packet, sim_now() + delay, source, ext->credit);
    trans.set_response_status(tlm::TLM_OK_RESPONSE);
}

void CommUnit::wake_at(const sc_core::sc_time &when)
{
    sc_core::sc_time now = sim_now();
    // Due now: deliver one delta on. Later: the calendar's wake or a timed notification (an
    // earlier one pending is kept; deliver() asks again for the rest).
    if (when <= now) m_run.notify(sc_core::SC_ZERO_TIME);
    else m_wake.at(when, when - now);
}

bool CommUnit::forward(uint32_t packet)
{
    TimedPacket &p = m_pool->at(packet);
    sc_core::sc_time now = sim_now();
    if (p.stamp < now) p.stamp = now;  // held packets move on no earlier than now
    Hop next = next_hop(p, m_pool->owner(packet));
    if (!next.local) m_ways.prefetch(next.dir);
    if (!next.sink->can_accept(p)) {
        next.sink->on_space(p, m_retry);
        return false;
    }
    (next.local ? m_local : m_transit)++;
    BufferSpace *credit = m_pool->credit(packet);
    // The packet goes on by handle: into a link, or into the processor side's input queue.
    next.sink->accept_pooled(*m_pool, packet);
    if (credit) credit->release();
    return true;
}

void CommUnit::deliver()
{
    m_delivering = true;
    deliver_due();
    m_delivering = false;
    if (ActivationQueue::Client *c = m_after_delivery) {
        m_after_delivery = nullptr;
        c->activate();
    }
}

void CommUnit::deliver_due()
{
    const sc_dt::uint64 now = sim_now().value();
    while (!m_arrivals.empty() && m_arrivals.next_value() <= now) {
        if (m_arrivals.next_is_new()) {  // sent in this delta: next delta (already notified)
            m_run.notify(sc_core::SC_ZERO_TIME);
            return;
        }
        ArrivalQueue::Arrival a = m_arrivals.pop();
        int source = a.source;
        uint32_t h = a.packet;
        const TimedPacket &p = m_pool->at(h);
        uint32_t buffer = 2 * p.cls + p.vc;
        // Behind packets held from the same buffer it waits its turn; else it moves on if it can.
        if (!holds(source, buffer) && forward(h)) continue;
        hold(source, buffer, h);
    }
    if (!m_arrivals.empty()) wake_at(m_arrivals.next_time());
}

void CommUnit::retry()
{
    for (size_t s = 0; s < m_held.size(); s++) {
        for (auto it = m_held[s].begin(); it != m_held[s].end();) {
            auto &held = it->packets;
            while (!held.empty() && forward(held.front())) {
                held.pop_front();
                m_held_count[s]--;
                m_held_total--;
            }
            it = held.empty() ? m_held[s].erase(it) : std::next(it);
        }
        if (static_cast<int>(s) == processor_source() && m_held[s].empty()) {
            m_processor_room.notify(sc_core::SC_ZERO_TIME);
            for (sc_core::sc_event *e : m_processor_waiters) e->notify(sc_core::SC_ZERO_TIME);
            m_processor_waiters.clear();
        }
    }
}

size_t CommUnit::held() const
{
    size_t n = 0;
    for (size_t c : m_held_count) n += c;
    return n;
}

}  // namespace torusrt
