// comm_unit_test.cpp - a communication unit on node 0 of a 4-node ring routes each packet by the
// owner of its cell: its own cells to the local side, others to the link of the first hop
// (dimension order, the shorter way; on a tie + for a pixel with x + y even, - for odd); packets from its links are
// delivered at their annotated arrival time, simultaneous ones in source-port order and then in send order, and each
// link slot (credit) is given back at delivery; processor-side packets leave at their stamp. The unit has one link
// socket per neighbour, handed out in order, and answers only blocking transport on them.
#include <systemc>
#include <tlm>
#include <tlm_utils/simple_initiator_socket.h>
#include <vector>

#include "comm_unit.h"
#include "model_test.h"
#include "rt_scene.h"

using model_test::us;
using sc_core::sc_time;
using namespace torusrt;

// A packet in cell (cell, 0, 0), tagged by its x pixel.
static TimedPacket packet_in(int cell, uint32_t tag, sc_time stamp = sc_core::SC_ZERO_TIME)
{
    TimedPacket p{};
    p.packet.dda.cell[0] = cell;
    p.packet.x = tag;
    p.stamp = stamp;
    return p;
}

struct RecordingSink : PacketSinkIf {
    std::vector<sc_time> times;
    std::vector<uint32_t> tags;
    void accept(const TimedPacket &p) override
    {
        times.push_back(sc_core::sc_time_stamp());
        tags.push_back(p.packet.x);
    }
};

// An incoming link: sends (tag, delay) pairs at time `at` as b_transport calls with a credit.
struct LinkSender : sc_core::sc_module {
    tlm_utils::simple_initiator_socket<LinkSender> socket;
    struct Send {
        uint32_t tag;
        sc_time delay;
    };
    std::vector<Send> sends;
    sc_time at;
    BufferSpace credit{8};
    PacketPool pool;
    explicit LinkSender(sc_core::sc_module_name n) : sc_module(n), socket("socket")
    {
        SC_HAS_PROCESS(LinkSender);
        SC_THREAD(run);
    }
    void run()
    {
        sc_core::wait(at);
        for (const Send &s : sends) {
            tlm::tlm_generic_payload t;
            PacketExtension ext;
            ext.pool = &pool;  // a pool of the sender's own: the unit copies the packet in
            ext.handle = pool.add(packet_in(0, s.tag), -1);
            ext.credit = &credit;
            credit.take();
            t.set_command(tlm::TLM_WRITE_COMMAND);
            t.set_extension(&ext);
            sc_time d = s.delay;
            socket->b_transport(t, d);
            t.clear_extension(&ext);
        }
    }
};

// The processor side: hands packets to the unit's `in` at given times.
struct ProcessorSide : sc_core::sc_module {
    sc_core::sc_port<PacketSinkIf> out;
    struct Push {
        sc_time at;
        TimedPacket p;
    };
    std::vector<Push> pushes;
    explicit ProcessorSide(sc_core::sc_module_name n) : sc_module(n), out("out")
    {
        SC_HAS_PROCESS(ProcessorSide);
        SC_THREAD(run);
    }
    void run()
    {
        for (const Push &p : pushes) {
            if (p.at > sc_core::sc_time_stamp()) sc_core::wait(p.at - sc_core::sc_time_stamp());
            out->accept(p.p);
        }
    }
};

// Samples the link senders' credits in use at 4 us (before delivery) and 6 us (after).
struct CreditProbe : sc_core::sc_module {
    std::vector<LinkSender *> senders;
    size_t at4 = 99, at6 = 99;
    explicit CreditProbe(sc_core::sc_module_name n) : sc_module(n)
    {
        SC_HAS_PROCESS(CreditProbe);
        SC_THREAD(run);
    }
    void run()
    {
        sc_core::wait(us(4));
        at4 = senders[0]->credit.used() + senders[1]->credit.used();
        sc_core::wait(us(2));
        at6 = senders[0]->credit.used() + senders[1]->credit.used();
    }
};

// What the three sides of the unit received, and its counts.
struct Outcome {
    std::vector<uint32_t> local_tags, plus_tags, minus_tags;
    std::vector<sc_time> local_times, plus_times, minus_times;
    uint64_t routed_local = 0, routed_transit = 0;
    size_t credits_at4 = 0, credits_at6 = 0, held = 0;
};

static Outcome simulate()
{
    char msg[256];
    rt_scene *scene = rt_scene_new();
    rt_scene_set_view(scene, rt_vec(0, 0, 5), rt_vec(0, 0, 0), rt_vec(0, 1, 0), 45.0, 4, 4);
    rt_scene_add_sphere(scene, rt_vec(0, 0, 0), 1.0);
    rt_scene_finish(scene, msg, sizeof msg);
    rt_grid *grid = rt_grid_new(scene, 4, 1, 1, msg, sizeof msg);
    const int32_t owner[4] = {0, 1, 2, 3};  // cell i belongs to node i

    Routing routing({4, 1, 1}, "torus", RouteTies::split);
    CommUnit cu("cu", 0, routing, grid, owner);
    RecordingSink local, plus, minus;
    cu.local.bind(local);
    cu.bind_link_out(direction(0, true), plus);    // port 0
    cu.bind_link_out(direction(0, false), minus);  // port 1

    // Port 1 sends first (1 us), port 0 later (2 us), all arriving at 5 us: delivery must still
    // put port 0's packet first.
    LinkSender port0("port0"), port1("port1");
    port0.socket.bind(cu.next_link_in());  // source 0
    port1.socket.bind(cu.next_link_in());  // source 1
    port1.at = us(1);
    port0.at = us(2);
    port1.sends = {{11, us(4)}, {12, us(4)}, {13, us(2)}};  // 13 arrives first, at 3 us
    port0.sends = {{10, us(3)}};
    CreditProbe probe("probe");
    probe.senders = {&port0, &port1};

    ProcessorSide proc("proc");
    proc.out.bind(cu.in);
    proc.pushes = {
        {us(20), packet_in(0, 20, us(20))},  // own cell: local
        {us(20), packet_in(1, 21, us(20))},  // node 1: + link
        {us(20), packet_in(3, 23, us(20))},  // node 3: - link
        {us(20), packet_in(2, 22, us(20))},  // node 2, two hops either way: x + y = 22 even, +
        {us(20), packet_in(2, 25, us(20))},  // node 2 again: x + y = 25 odd, - on the tie
        {us(40), packet_in(1, 40, us(47))},  // stamped ahead: leaves at its stamp
    };
    sc_core::sc_start();

    Outcome run;
    run.local_tags = local.tags, run.plus_tags = plus.tags, run.minus_tags = minus.tags;
    run.local_times = local.times, run.plus_times = plus.times, run.minus_times = minus.times;
    run.routed_local = cu.stats().routed_local, run.routed_transit = cu.stats().routed_transit;
    run.credits_at4 = probe.at4, run.credits_at6 = probe.at6, run.held = cu.held();
    rt_grid_free(grid);
    rt_scene_free(scene);
    return run;
}

static const Outcome &run()
{
    static const Outcome r = simulate();
    return r;
}

TEST(CommUnit, DeliversLinkPacketsAtArrivalInPortThenSendOrder)
{
    // 13 arrives first (1 + 2 = 3 us); at 5 us 10 (port 0, 2 + 3) before 11, 12 (port 1, 1 + 4, send
    // order); then the processor's own-cell packet 20 at 20 us.
    EXPECT_EQ(run().local_tags, (std::vector<uint32_t>{13, 10, 11, 12, 20}));
    EXPECT_EQ(run().local_times, (std::vector<sc_time>{us(3), us(5), us(5), us(5), us(20)}))
        << "link arrivals at their annotated time";
}

TEST(CommUnit, RoutesOtherCellsToTheFirstHopLink)
{
    EXPECT_EQ(run().plus_tags, (std::vector<uint32_t>{21, 22, 40})) << "+x link gets the packets for nodes 1 and 2";
    EXPECT_EQ(run().plus_times, (std::vector<sc_time>{us(20), us(20), us(47)}))
        << "+x link times: 20, 20 and the stamp 47 us";
    EXPECT_EQ(run().minus_tags, (std::vector<uint32_t>{23, 25}))
        << "-x link gets the packet for node 3 and the odd pixel's packet for node 2";
    EXPECT_EQ(run().minus_times, (std::vector<sc_time>{us(20), us(20)})) << "both at 20 us";
}

TEST(CommUnit, CountsLocalAndTransitPackets)
{
    EXPECT_EQ(run().routed_local, 5u) << "13, 10, 11, 12, 20";
    EXPECT_EQ(run().routed_transit, 5u) << "21, 22, 23, 25, 40";
    EXPECT_EQ(run().held, 0u) << "nothing held";
}

TEST(CommUnit, HoldsLinkSlotsUntilDelivery)
{
    EXPECT_EQ(run().credits_at4, 3u) << "11, 12 (port 1) and 10 (port 0) not yet delivered at 4 us";
    EXPECT_EQ(run().credits_at6, 0u) << "all back at 6 us";
}

TEST(CommUnit, HasOneLinkSocketPerNeighbourAndRefusesAnotherLink)
{
    sc_core::sc_report_handler::set_actions(sc_core::SC_FATAL, sc_core::SC_THROW);
    Routing ring({4, 1, 1}, "torus"), line({4, 1, 1}, "mesh");
    CommUnit inner("inner", 0, ring, nullptr, nullptr), end("end", 0, line, nullptr, nullptr);
    EXPECT_EQ(inner.link_in.size(), 2u) << "two neighbours on a ring";
    EXPECT_EQ(end.link_in.size(), 1u) << "one at the end of a line";
    EXPECT_EQ(&inner.next_link_in(), &inner.link_in[0]) << "handed out in order";
    EXPECT_EQ(&inner.next_link_in(), &inner.link_in[1]);
    EXPECT_THROW(inner.next_link_in(), sc_core::sc_report) << "a third link has no neighbour to come from";
}

TEST(CommUnit, LinkSocketAnswersOnlyBlockingTransport)
{
    Routing ring({4, 1, 1}, "torus");
    CommUnit cu("cu", 0, ring, nullptr, nullptr);
    tlm::tlm_fw_transport_if<> *target = cu.link_in[0].get_base_export().operator->();
    tlm::tlm_generic_payload t;
    tlm::tlm_phase phase = tlm::BEGIN_REQ;
    sc_time delay = sc_core::SC_ZERO_TIME;
    EXPECT_EQ(target->nb_transport_fw(t, phase, delay), tlm::TLM_COMPLETED);
    EXPECT_EQ(t.get_response_status(), tlm::TLM_COMMAND_ERROR_RESPONSE);
    tlm::tlm_dmi dmi;
    EXPECT_FALSE(target->get_direct_mem_ptr(t, dmi));
    EXPECT_EQ(target->transport_dbg(t), 0u);
    t.set_response_status(tlm::TLM_INCOMPLETE_RESPONSE);
    target->b_transport(t, delay);  // no packet extension: refused
    EXPECT_EQ(t.get_response_status(), tlm::TLM_GENERIC_ERROR_RESPONSE);
}
