// queue_link_test.cpp - a toroidal link serialises packets at its packet time and delivers them as
// TLM-2.0 transactions in order, annotated with their arrival time; a bounded link blocks its
// writer until the receiver returns a slot; a bounded queue blocks its writer while full.
#include <systemc>
#include <tlm>
#include <tlm_utils/simple_target_socket.h>
#include <vector>

#include "harness.h"
#include "packet_queue.h"
#include "rt_timing.h"
#include "sim_config.h"
#include "toroidal_link.h"

using harness::check;
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
        xs.push_back(ext ? ext->item.packet.x : 9999);
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

int sc_main(int, char **)
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
    check(rx.arrivals.size() == 5, "all five packets delivered");
    bool spaced = rx.arrivals.size() == 5;
    for (size_t i = 0; spaced && i < 5; i++)
        spaced = rx.arrivals[i] == sc_core::sc_time(50.0 * (i + 1), sc_core::SC_US) && rx.xs[i] == i;
    check(spaced, "packet i arrives at 50 us x (i+1), in order");
    check(link.packets() == 5, "link counts five packets");
    check(link.busy_time() == sc_core::sc_time(250, sc_core::SC_US), "link busy 250 us");
    // With capacity 2 the sender must have been held back: its last push happens after t = 0.
    check(tx.pushed.size() == 5 && tx.pushed.back() > sc_core::SC_ZERO_TIME, "bounded queue blocks the writer");
    check(link.queue().high_water() == 2, "the link holds up to its capacity, never more");
    check(rx.released == 5 && link.queue().used() == 0, "every slot returned at arrival");
    check(filler.host_pushed == 1, "the host packet entered");
    check(filler.network_pushed == 1, "class 0 stops at the capacity, the host packet counted");
    check(filler.class1_pushed == 2, "class 1 has a capacity of its own");
    check(filler.queue.size() == 4 && filler.queue.class_high_water() == 2, "4 waiting, at most 2 of a class");
    check(filler.queue.blocked_writers() == 2 && filler.queue.full(), "both writers are left waiting");
    return harness::finish();
}
