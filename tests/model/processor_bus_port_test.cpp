// processor_bus_port_test.cpp - a cluster processor's bus port: an outgoing packet crosses the bus
// (arbitration + ceil(packet_bytes / width) x cycle, starting no earlier than its stamp) and
// reaches the communication unit stamped with the transfer's end; an object fetch from the
// processor's own memory costs nothing, from another processor's memory arbitration +
// ceil(object bytes / width) x cycle + the memory access.
#include <cmath>
#include <memory>
#include <systemc>
#include <vector>

#include "bus_arbiter.h"
#include "cluster_bus.h"
#include "model_test.h"
#include "processor_bus_port.h"
#include "sim_config.h"
#include "time_keeper.h"
#include "two_port_memory.h"

using model_test::us;
using sc_core::sc_time;
using namespace torusrt;

struct RecordingSink : PacketSinkIf {
    std::vector<sc_time> times, stamps;
    void accept(const TimedPacket &p) override
    {
        times.push_back(sc_core::sc_time_stamp());
        stamps.push_back(p.stamp);
    }
};

// The processor side: two packets out, then fetches; records the time after each fetch.
struct Processor : sc_core::sc_module {
    sc_core::sc_port<PacketSinkIf> out;
    sc_core::sc_port<ObjectFetchIf> fetch;
    std::vector<uint32_t> objects;
    std::vector<sc_time> after_fetch;
    sc_time fetch_start;
    explicit Processor(sc_core::sc_module_name n) : sc_module(n), out("out"), fetch("fetch")
    {
        SC_HAS_PROCESS(Processor);
        SC_THREAD(run);
    }
    void run()
    {
        sc_core::wait(us(5));
        TimedPacket p{};
        p.stamp = us(5);
        out->accept(p);  // bus 5..22
        p.stamp = sc_core::sc_time_stamp() + us(10);
        out->accept(p);  // stamped 10 us ahead: bus 32..49
        TimeKeeper time(false);
        fetch_start = sc_core::sc_time_stamp();
        for (uint32_t obj : objects) {
            fetch->fetch(0, obj, time);
            after_fetch.push_back(sc_core::sc_time_stamp());
        }
    }
};

// The bus figures: arbitration 1 us, 4-byte width, 2 us cycle, 30-byte packets, 3 us memory access.
static const double packet_us = 1 + 8 * 2;  // ceil(30 / 4) = 8 cycles

// What reached the communication unit, the fetch times and the counts; read1 and read3 are the
// remote reads of objects 1 and 3 worked out from their sizes.
struct Outcome {
    std::vector<sc_time> comm_times, comm_stamps, after_fetch;
    sc_time fetch_start, read1, read3;
    uint64_t local_reads = 0, remote_reads = 0, mem0_reads = 0, mem1_reads = 0, packet_transfers = 0, object_reads = 0;
};

static Outcome simulate()
{
    char msg[256];
    rt_scene *scene = rt_scene_new();
    rt_scene_set_view(scene, rt_vec(0, 0, 5), rt_vec(0, 0, 0), rt_vec(0, 1, 0), 45.0, 4, 4);
    for (int i = 0; i < 4; i++) rt_scene_add_sphere(scene, rt_vec(i, 0, 0), 0.5);
    rt_scene_finish(scene, msg, sizeof msg);

    SimConfig config;
    rt_timing_defaults(&config.timing);
    rt_timing &t = config.timing;
    t.bus_arbitration_us = 1, t.bus_width_bytes = 4, t.bus_cycle_us = 2, t.packet_bytes = 30, t.memory_access_us = 3;

    // Objects 0..3 in the node; with m = 2 processor 0 holds 0 and 2, processor 1 holds 1 and 3.
    const std::vector<uint32_t> node_objects{0, 1, 2, 3};
    ProcessorBusPort port("port", scene, 0, node_objects, 2);
    auto arbiter = make_arbiter("round-robin", "arbiter", 1, -1);
    ClusterBus bus("bus", config.timing, false, 1);
    bus.arbiter.bind(*arbiter);
    TwoPortMemory mem0("mem0", config.timing, node_objects, 0, 2), mem1("mem1", config.timing, node_objects, 1, 2);
    bus.memory.bind(mem0.bus_side);
    bus.memory.bind(mem1.bus_side);
    port.bus_socket.bind(bus.target);
    RecordingSink comm;
    port.to_comm_unit.bind(comm);
    Processor proc("proc");
    proc.out.bind(port.in);
    proc.fetch.bind(port.objects);
    proc.objects = {0, 1, 2, 3};
    sc_core::sc_start();

    Outcome run;
    run.comm_times = comm.times, run.comm_stamps = comm.stamps;
    run.fetch_start = proc.fetch_start, run.after_fetch = proc.after_fetch;
    // Arbitration + ceil(bytes / 4) x 2 + the 3 us memory access.
    run.read1 = us(1 + std::ceil(rt_scene_object_bytes(scene, 1) / 4.0) * 2 + 3);
    run.read3 = us(1 + std::ceil(rt_scene_object_bytes(scene, 3) / 4.0) * 2 + 3);
    run.local_reads = port.local_reads(), run.remote_reads = port.remote_reads();
    run.mem0_reads = mem0.reads_served(), run.mem1_reads = mem1.reads_served();
    run.packet_transfers = bus.packet_transfers(), run.object_reads = bus.object_reads();
    rt_scene_free(scene);
    return run;
}

static const Outcome &run()
{
    static const Outcome r = simulate();
    return r;
}

TEST(ProcessorBusPort, PacketsCrossTheBusNoEarlierThanTheirStamp)
{
    EXPECT_EQ(run().comm_times, (std::vector<sc_time>{us(5 + packet_us), us(32 + packet_us)}))
        << "packets reach the communication unit at 5 + 17 = 22 us and (22 + 10) + 17 = 49 us";
    EXPECT_EQ(run().comm_stamps, run().comm_times) << "each packet is stamped with the end of its transfer";
}

TEST(ProcessorBusPort, OwnMemoryFetchIsFreeRemoteCostsABusRead)
{
    const Outcome &r = run();
    EXPECT_EQ(r.fetch_start, us(49)) << "fetches start after the second packet's transfer";
    ASSERT_EQ(r.after_fetch.size(), 4u);
    EXPECT_EQ(r.after_fetch[0], r.fetch_start) << "object 0 (own memory): no time";
    EXPECT_EQ(r.after_fetch[1], r.fetch_start + r.read1)
        << "object 1 (processor 1): arbitration + ceil(bytes / 4) x 2 + 3 us";
    EXPECT_EQ(r.after_fetch[2], r.fetch_start + r.read1) << "object 2 (own memory): no time";
    EXPECT_EQ(r.after_fetch[3], r.fetch_start + r.read1 + r.read3) << "object 3 (processor 1): a second remote read";
}

TEST(ProcessorBusPort, CountsReadsAndTransfers)
{
    EXPECT_EQ(run().local_reads, 2u);
    EXPECT_EQ(run().remote_reads, 2u);
    EXPECT_EQ(run().mem1_reads, 2u) << "remote reads served by processor 1's memory";
    EXPECT_EQ(run().mem0_reads, 0u);
    EXPECT_EQ(run().packet_transfers, 2u);
    EXPECT_EQ(run().object_reads, 2u);
}
