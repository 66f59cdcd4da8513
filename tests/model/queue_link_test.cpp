// queue_link_test.cpp - a toroidal link serialises packets at its packet time and delivers them as
// TLM-2.0 transactions in order, annotated with their arrival time; a bounded link blocks its
// writer until the receiver returns a slot; a bounded queue blocks its writer while its class is
// full, every packet counting.
#include <systemc>
#include <tlm>
#include <tlm_utils/simple_target_socket.h>
#include <vector>

#include "model_test.h"
#include "packet_queue.h"
#include "rt_timing.h"
#include "sim_config.h"
#include "toroidal_link.h"

using model_test::us;
using namespace torusrt;

// Records each packet's annotated arrival and returns its link slot at that time.
struct Receiver : sc_core::sc_module {
    tlm_utils::simple_target_socket<Receiver> socket;
    std::vector<sc_core::sc_time> arrivals;
    std::vector<uint32_t> xs;
    std::vector<BufferSpace *> credits;
    size_t released = 0;
    sc_core::sc_event due;
    explicit Receiver(sc_core::sc_module_name n) : sc_module(n), socket("socket")
    {
        socket.register_b_transport(this, &Receiver::b_transport);
        SC_HAS_PROCESS(Receiver);
        SC_METHOD(release);
        sensitive << due;
        dont_initialize();
    }
    void b_transport(tlm::tlm_generic_payload &t, sc_core::sc_time &delay)
    {
        auto *ext = t.get_extension<PacketExtension>();
        arrivals.push_back(sc_core::sc_time_stamp() + delay);
        xs.push_back(ext ? ext->pool->at(ext->handle).packet.x : 9999);
        credits.push_back(ext ? ext->credit : nullptr);
        due.notify(arrivals[released] - sc_core::sc_time_stamp());
        t.set_response_status(tlm::TLM_OK_RESPONSE);
    }
    void release()
    {
        while (released < arrivals.size() && arrivals[released] <= sc_core::sc_time_stamp())
            if (BufferSpace *c = credits[released++]) c->release();
        if (released < arrivals.size()) due.notify(arrivals[released] - sc_core::sc_time_stamp());
    }
};

struct Sender : sc_core::sc_module {
    sc_core::sc_port<PacketSinkIf> out;
    std::vector<sc_core::sc_time> pushed;
    explicit Sender(sc_core::sc_module_name n) : sc_module(n), out("out")
    {
        SC_HAS_PROCESS(Sender);
        SC_THREAD(run);
    }
    void run()
    {
        for (uint32_t i = 0; i < 5; i++) {
            TimedPacket p{};
            p.packet.x = i;
            p.stamp = sc_core::sc_time_stamp();
            out->accept(p);
            pushed.push_back(sc_core::sc_time_stamp());
        }
    }
};

// Pushes a host packet, then network packets, then packets of class 1, into a queue of
// capacity 2 (per class) nobody drains: every packet counts, whatever its origin.
struct Filler : sc_core::sc_module {
    PacketQueue queue{"filler.queue", 2};
    int host_pushed = 0, network_pushed = 0, class1_pushed = 0;
    sc_core::sc_event stop;
    explicit Filler(sc_core::sc_module_name n) : sc_module(n)
    {
        SC_HAS_PROCESS(Filler);
        SC_THREAD(run);
        SC_THREAD(run_class1);
    }
    void run_class1()
    {
        for (int i = 0; i < 5; i++) {
            TimedPacket p{};
            p.cls = 1;
            queue.push_blocking(p);
            class1_pushed++;
        }
    }
    void run()
    {
        TimedPacket h{};
        h.from_host = true;
        queue.push_blocking(h);
        host_pushed++;
        for (int i = 0; i < 5; i++) {
            queue.push_blocking(TimedPacket{});
            network_pushed++;
        }
    }
};

// What the receiver saw, the link's and the queue's figures.
struct Outcome {
    std::vector<sc_core::sc_time> arrivals, pushed;
    std::vector<uint32_t> xs;
    size_t released = 0, link_high_water = 0, link_used = 0;
    uint64_t link_packets = 0;
    sc_core::sc_time link_busy;
    int host_pushed = 0, network_pushed = 0, class1_pushed = 0;
    size_t filler_size = 0, filler_class_high_water = 0;
    unsigned filler_blocked = 0;
    bool filler_full = false;
};

static Outcome simulate()
{
    Filler filler("filler");
    SimConfig config;
    rt_timing_defaults(&config.timing);
    config.queue_capacity = 2;
    ToroidalLink link("link", config, 0, 1, 0);
    Receiver rx("rx");
    Sender tx("tx");
    tx.out.bind(link.in);
    link.socket.bind(rx.socket);
    sc_core::sc_start();

    Outcome run;
    run.arrivals = rx.arrivals, run.xs = rx.xs, run.released = rx.released, run.pushed = tx.pushed;
    run.link_packets = link.packets(), run.link_busy = link.busy_time();
    run.link_high_water = link.queue().high_water(), run.link_used = link.queue().used();
    run.host_pushed = filler.host_pushed, run.network_pushed = filler.network_pushed;
    run.class1_pushed = filler.class1_pushed, run.filler_size = filler.queue.size();
    run.filler_class_high_water = filler.queue.class_high_water();
    run.filler_blocked = filler.queue.blocked_writers(), run.filler_full = filler.queue.full();
    return run;
}

static const Outcome &run()
{
    static const Outcome r = simulate();
    return r;
}

TEST(ToroidalLink, SerialisesPacketsAtThePacketTime)
{
    ASSERT_EQ(run().arrivals.size(), 5u) << "all five packets delivered";
    // The default link packet time is 50 us: packet i (sent from 0, back to back) arrives at 50 x (i + 1).
    for (uint32_t i = 0; i < 5; i++) {
        EXPECT_EQ(run().arrivals[i], us(50.0 * (i + 1))) << "packet " << i;
        EXPECT_EQ(run().xs[i], i) << "in order";
    }
    EXPECT_EQ(run().link_packets, 5u) << "link counts five packets";
    EXPECT_EQ(run().link_busy, us(250)) << "link busy 5 x 50 = 250 us";
}

TEST(ToroidalLink, BoundedLinkBlocksTheWriter)
{
    // With capacity 2 the sender must have been held back: its last push happens after t = 0.
    ASSERT_EQ(run().pushed.size(), 5u);
    EXPECT_GT(run().pushed.back(), sc_core::SC_ZERO_TIME) << "bounded queue blocks the writer";
    EXPECT_EQ(run().link_high_water, 2u) << "the link holds up to its capacity, never more";
    EXPECT_EQ(run().released, 5u) << "every slot returned at arrival";
    EXPECT_EQ(run().link_used, 0u);
}

TEST(PacketQueue, EveryPacketCountsAndEachClassHasItsCapacity)
{
    // Capacity 2 per class: the host packet takes a class-0 slot like any other, so one network
    // packet of class 0 fits; class 1 has two slots of its own.
    EXPECT_EQ(run().host_pushed, 1) << "the host packet entered";
    EXPECT_EQ(run().network_pushed, 1) << "class 0 stops at the capacity, the host packet counted";
    EXPECT_EQ(run().class1_pushed, 2) << "class 1 has a capacity of its own";
    EXPECT_EQ(run().filler_size, 4u) << "4 waiting";
    EXPECT_EQ(run().filler_class_high_water, 2u) << "at most 2 of a class";
    EXPECT_EQ(run().filler_blocked, 2u) << "both writers are left waiting";
    EXPECT_TRUE(run().filler_full);
}
