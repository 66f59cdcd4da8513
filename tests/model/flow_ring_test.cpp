// flow_ring_test.cpp - the flow-control argument on rings of 2 and 3 nodes with buffers of
// capacity 1. Each node has the model's communication unit, its outgoing links and a relay
// processor that takes up a packet, spends 10 us on it and hands it to the next node on the
// ring (+ direction) until its hop count is spent; the relay follows the processor's rule of
// each scheme (flow_control.h): under --flow none it takes the oldest packet and waits for room
// with the packet in hand; under the class scheme the packet it hands on has class + 1 and it
// takes a packet up only once that packet's next buffer has a slot reserved.
//
// Six packets per node, each making 8 hops: more than a node can hold with one class (one in its
// queue, one in its processor's hand, one held at its comm unit, one on its outgoing link). So
// node n's processor waits with a packet in hand for the link to n + 1, which holds one waiting
// for n + 1's full queue, whose processor waits for the next link..., a cyclic wait, and the run
// stalls with packets undelivered. With classes each wait points to a buffer of a higher class, and every
// packet arrives. One packet per node making H hops arrives, by hand, at H (10 + 50) + 10 us
// (a step, a 50 us link crossing, the next step, ...), the last step absorbing it.
#include <algorithm>
#include <memory>
#include <string>
#include <systemc>
#include <vector>

#include "comm_unit.h"
#include "flow_control.h"
#include "model_test.h"
#include "packet_injector.h"
#include "packet_queue.h"
#include "rt_scene.h"
#include "toroidal_link.h"

using model_test::us;
using sc_core::sc_time;
using namespace torusrt;

struct Relay : sc_core::sc_module, PacketSinkIf {
    sc_core::sc_port<PacketSinkIf> out;  // to the node's communication unit
    PacketQueue queue;
    int node, nodes;
    FlowControl flow;
    std::vector<sc_time> absorbed;
    sc_core::sc_event room;
    Relay(sc_core::sc_module_name n, int node_, int nodes_, FlowControl f)
        : sc_module(n), out("out"), queue(std::string(n) + ".queue", 1), node(node_), nodes(nodes_), flow(f)
    {
        SC_HAS_PROCESS(Relay);
        SC_THREAD(run);
    }
    void accept(const TimedPacket &p) override { queue.push_blocking(p); }
    bool can_accept(const TimedPacket &p) const override { return queue.has_room(p); }
    void on_space(const TimedPacket &p, sc_core::sc_event &e) override { queue.space_for(p).on_release(e); }
    BufferSpace *room_for(const TimedPacket &p) override { return &queue.space_for(p); }

    // The packet a step of `p` hands on: one cell (one node) further, one hop fewer.
    TimedPacket next_of(const TimedPacket &p) const
    {
        TimedPacket n = p;
        n.packet.x--;
        n.packet.dda.cell[0] = (node + 1) % nodes;
        n.cls = output_class(flow, p.cls);
        n.from_host = false;
        return n;
    }
    void run()
    {
        TimedPacket next;
        for (;;) {
            TimedPacket tp = queue.take_first(
                [&](const TimedPacket &c) {
                    if (c.packet.x == 0 || flow == FlowControl::none) return true;
                    next = next_of(c);
                    BufferSpace *b = out->room_for(next);
                    if (!b->available()) {
                        b->on_release(room);
                        return false;
                    }
                    b->take();
                    next.reserved = true;
                    return true;
                },
                room);
            if (sc_core::sc_time_stamp() < tp.stamp) sc_core::wait(tp.stamp - sc_core::sc_time_stamp());
            sc_core::wait(us(10));
            if (tp.packet.x == 0) {
                absorbed.push_back(sc_core::sc_time_stamp());
                continue;
            }
            if (flow == FlowControl::none) next = next_of(tp);
            next.stamp = sc_core::sc_time_stamp();
            out->accept(next);  // waits with the packet in hand while the link is full (none)
        }
    }
};

// One ring: N nodes, each with a relay fed by an injector, a comm unit and its links.
struct Ring {
    rt_grid *grid;
    std::vector<int32_t> owner;
    Routing routing;
    SimConfig config;
    std::vector<std::unique_ptr<CommUnit>> cus;
    std::vector<std::unique_ptr<Relay>> relays;
    std::vector<std::unique_ptr<model_test::Injector>> injectors;
    std::vector<std::unique_ptr<ToroidalLink>> links;

    Ring(const std::string &name, const rt_scene *scene, int n, FlowControl flow, int per_node, int hops, char *msg)
        : grid(rt_grid_new(scene, n, 1, 1, msg, 256)), routing({n, 1, 1}, "torus")
    {
        rt_timing_defaults(&config.timing);
        config.queue_capacity = 1;
        config.flow = flow;
        for (int i = 0; i < n; i++) owner.push_back(i);
        for (int i = 0; i < n; i++) {
            std::string s = name + "_" + std::to_string(i);
            CommUnit::Setup setup;
            setup.flow = flow;
            cus.push_back(std::make_unique<CommUnit>(("cu_" + s).c_str(), i, routing, grid, owner.data(), setup));
            relays.push_back(std::make_unique<Relay>(("relay_" + s).c_str(), i, n, flow));
            relays[i]->out.bind(cus[i]->in);
            cus[i]->local.bind(*relays[i]);
            injectors.push_back(std::make_unique<model_test::Injector>(("inj_" + s).c_str()));
            injectors[i]->out.bind(*relays[i]);
            for (int k = 0; k < per_node; k++) {
                TimedPacket p{};
                p.packet.dda.cell[0] = i;
                p.packet.x = static_cast<uint32_t>(hops);
                p.packet.y = static_cast<uint32_t>(100 * i + k);
                injectors[i]->packets.push_back(p);
            }
        }
        for (int i = 0; i < n; i++) {
            for (int dir = 0; dir < routing.ports(); dir++) {
                int to = routing.neighbour(i, dir);
                if (to < 0) continue;
                std::string ln = "link_" + name + "_" + std::to_string(i) + "_" + routing.port_name(dir);
                links.push_back(std::make_unique<ToroidalLink>(ln.c_str(), config, i, to, dir));
                cus[i]->connect_link(dir, links.back()->in, links.back()->socket, *cus[to]);
            }
        }
    }
    ~Ring() { rt_grid_free(grid); }
    std::vector<sc_time> absorbed() const
    {
        std::vector<sc_time> all;
        for (const auto &r : relays) all.insert(all.end(), r->absorbed.begin(), r->absorbed.end());
        return all;
    }
    size_t most_in_one_buffer() const
    {
        size_t h = 0;
        for (const auto &r : relays) h = std::max(h, r->queue.class_high_water());
        for (const auto &l : links) h = std::max(h, l->queue().high_water());
        return h;
    }
    // Whether the wrap-around link (last node, + direction) carried channel 1.
    bool wrap_used_channel_1() const
    {
        for (const auto &l : links)
            if (l->from() == static_cast<int>(relays.size()) - 1 && l->dir() == 0)
                for (uint32_t i = 1; i < l->queue().count(); i += 2)
                    if (l->queue().find(i) && l->queue().find(i)->high_water() > 0) return true;
        return false;
    }
};

// What the six rings did.
struct Outcome {
    size_t none2 = 0, none3 = 0, classes2 = 0, classes3 = 0;  // packets absorbed
    size_t none2_held = 0;                                    // held at the receivers at the end
    size_t classes_most = 0, none_most = 0;                   // most packets in one buffer
    std::vector<sc_time> timed2, timed3;                      // absorption times, one packet per node
    bool wrap_channel_1 = false;
};

static Outcome simulate()
{
    char msg[256];
    rt_scene *scene = rt_scene_new();
    rt_scene_set_view(scene, rt_vec(0, 0, 5), rt_vec(0, 0, 0), rt_vec(0, 1, 0), 45.0, 4, 4);
    rt_scene_add_sphere(scene, rt_vec(0, 0, 0), 1.0);
    rt_scene_finish(scene, msg, sizeof msg);
    Outcome o;
    {
        Ring none2("none2", scene, 2, FlowControl::none, 6, 8, msg);
        Ring none3("none3", scene, 3, FlowControl::none, 6, 8, msg);
        Ring classes2("classes2", scene, 2, FlowControl::classes, 6, 8, msg);
        Ring classes3("classes3", scene, 3, FlowControl::classes, 6, 8, msg);
        Ring timed2("timed2", scene, 2, FlowControl::classes, 1, 2, msg);
        Ring timed3("timed3", scene, 3, FlowControl::classes, 1, 5, msg);
        sc_core::sc_start();
        o.none2 = none2.absorbed().size();
        o.none3 = none3.absorbed().size();
        for (const auto &cu : none2.cus) o.none2_held += cu->held();
        o.classes2 = classes2.absorbed().size();
        o.classes3 = classes3.absorbed().size();
        o.classes_most = std::max(classes2.most_in_one_buffer(), classes3.most_in_one_buffer());
        o.none_most = std::max(none2.most_in_one_buffer(), none3.most_in_one_buffer());
        o.timed2 = timed2.absorbed();
        o.timed3 = timed3.absorbed();
        o.wrap_channel_1 = classes3.wrap_used_channel_1() && timed3.wrap_used_channel_1();
    }
    rt_scene_free(scene);
    return o;
}

static const Outcome &run()
{
    static const Outcome r = simulate();
    return r;
}

TEST(FlowRing, OneClassStallsInACyclicWait)
{
    EXPECT_LT(run().none2, 12u) << "ring of 2, one class: packets left undelivered";
    EXPECT_LT(run().none3, 18u) << "ring of 3, one class: packets left undelivered";
    EXPECT_GT(run().none2_held, 0u) << "ring of 2, one class: packets held at the receivers for a full queue";
    EXPECT_LE(run().none_most, 1u) << "one class: capacity 1 held too";
}

TEST(FlowRing, ClassesDrainEveryPacket)
{
    EXPECT_EQ(run().classes2, 12u) << "ring of 2, classes: all 2 x 6 packets arrive";
    EXPECT_EQ(run().classes3, 18u) << "ring of 3, classes: all 3 x 6 packets arrive";
    EXPECT_LE(run().classes_most, 1u) << "no buffer ever holds more than its capacity of 1";
    EXPECT_TRUE(run().wrap_channel_1) << "the wrap-around link carries channel 1";
}

TEST(FlowRing, DeliveryTimesByHand)
{
    // H hops: H x (10 us step + 50 us link) + the 10 us step that absorbs it.
    EXPECT_EQ(run().timed2, std::vector<sc_time>(2, us(2 * 60 + 10))) << "ring of 2, 2 hops: both at 130 us";
    EXPECT_EQ(run().timed3, std::vector<sc_time>(3, us(5 * 60 + 10))) << "ring of 3, 5 hops: all at 310 us";
}
