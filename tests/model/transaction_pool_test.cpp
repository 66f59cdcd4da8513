// transaction_pool_test.cpp - the links' memory manager: a transaction goes back to the pool on
// its last release, a second is made only while the first is out, and links sharing a pool send
// every crossing in the one transaction, each with its own address, data and extension.
#include <systemc>
#include <tlm>
#include <tlm_utils/simple_target_socket.h>
#include <vector>

#include "model_test.h"
#include "rt_timing.h"
#include "sim_config.h"
#include "toroidal_link.h"
#include "transaction_pool.h"

using model_test::us;
using namespace torusrt;

// Records what each crossing's transaction held when it arrived.
struct Recorder : sc_core::sc_module {
    tlm_utils::simple_target_socket<Recorder> socket;
    std::vector<const tlm::tlm_generic_payload *> transactions;
    std::vector<uint64_t> addresses;
    std::vector<uint32_t> xs;
    std::vector<unsigned> ref_counts;
    std::vector<bool> writes;
    explicit Recorder(sc_core::sc_module_name n) : sc_module(n), socket("socket")
    {
        socket.register_b_transport(this, &Recorder::b_transport);
    }
    void b_transport(tlm::tlm_generic_payload &t, sc_core::sc_time &)
    {
        auto *ext = t.get_extension<PacketExtension>();
        transactions.push_back(&t);
        addresses.push_back(t.get_address());
        xs.push_back(ext ? ext->pool->at(ext->handle).packet.x : 9999);
        ref_counts.push_back(t.get_ref_count());
        writes.push_back(t.is_write() && t.get_data_length() == sizeof(rt_packet) &&
                         t.get_data_ptr() == reinterpret_cast<unsigned char *>(&ext->pool->at(ext->handle).packet));
        t.set_response_status(tlm::TLM_OK_RESPONSE);
    }
};

// Sends packets 0..3 alternately into two links (to nodes 1 and 2).
struct TwoLinkSender : sc_core::sc_module {
    sc_core::sc_port<PacketSinkIf> a, b;
    explicit TwoLinkSender(sc_core::sc_module_name n) : sc_module(n), a("a"), b("b")
    {
        SC_HAS_PROCESS(TwoLinkSender);
        SC_THREAD(run);
    }
    void run()
    {
        for (uint32_t i = 0; i < 4; i++) {
            TimedPacket p{};
            p.packet.x = i;
            p.stamp = sc_core::sc_time_stamp();
            (i % 2 ? b : a)->accept(p);
            sc_core::wait(us(1));
        }
    }
};

struct Outcome {
    std::vector<const tlm::tlm_generic_payload *> transactions;
    std::vector<uint64_t> addresses;
    std::vector<uint32_t> xs;
    std::vector<unsigned> ref_counts;
    std::vector<bool> writes;
    // After the run: the next take is the one transaction the crossings used, the one after a new one.
    bool one_made = false, one_free = false;
    // The pool on its own (no simulation).
    bool nested_distinct = false, first_reused = false, second_reused = false, third_new = false;
};

static Outcome simulate()
{
    Outcome run;
    {
        TransactionPool pool;
        TransactionPool::Crossing first = pool.take();
        first.trans->acquire();
        TransactionPool::Crossing second = pool.take();  // the first is still out
        second.trans->acquire();
        run.nested_distinct = first.trans != second.trans && first.ext != second.ext;
        second.trans->release();
        first.trans->release();
        TransactionPool::Crossing again = pool.take();
        run.first_reused = again.trans == first.trans && again.ext == first.ext;
        TransactionPool::Crossing next = pool.take();
        run.second_reused = next.trans == second.trans && next.ext == second.ext;
        TransactionPool::Crossing third = pool.take();  // both were free: a third is made now
        run.third_new = third.trans != first.trans && third.trans != second.trans;
    }

    SimConfig config;
    rt_timing_defaults(&config.timing);
    TransactionPool shared;
    ToroidalLink to1("to1", config, 0, 1, 0, &shared), to2("to2", config, 0, 2, 2, &shared);
    Recorder rx1("rx1"), rx2("rx2");
    TwoLinkSender tx("tx");
    tx.a.bind(to1.in);
    tx.b.bind(to2.in);
    to1.socket.bind(rx1.socket);
    to2.socket.bind(rx2.socket);
    sc_core::sc_start();
    for (Recorder *rx : {&rx1, &rx2}) {
        run.transactions.insert(run.transactions.end(), rx->transactions.begin(), rx->transactions.end());
        run.addresses.insert(run.addresses.end(), rx->addresses.begin(), rx->addresses.end());
        run.xs.insert(run.xs.end(), rx->xs.begin(), rx->xs.end());
        run.ref_counts.insert(run.ref_counts.end(), rx->ref_counts.begin(), rx->ref_counts.end());
        run.writes.insert(run.writes.end(), rx->writes.begin(), rx->writes.end());
    }
    TransactionPool::Crossing after = shared.take();
    run.one_made = !run.transactions.empty() && after.trans == run.transactions[0];
    run.one_free = shared.take().trans != after.trans;
    return run;
}

static const Outcome &run()
{
    static const Outcome r = simulate();
    return r;
}

TEST(TransactionPool, MakesASecondOnlyWhileTheFirstIsOut)
{
    EXPECT_TRUE(run().nested_distinct);
    EXPECT_TRUE(run().first_reused && run().second_reused);  // both back after their last release
    EXPECT_TRUE(run().third_new);                            // and no third was made before
}

TEST(TransactionPool, GivesBackTheLastReleasedFirst)
{
    // The first was released last, so it is on top; nothing new is made.
    EXPECT_TRUE(run().first_reused);
    EXPECT_TRUE(run().second_reused);
}

TEST(TransactionPool, LinksSharingItSendEveryCrossingInOneTransaction)
{
    // rx1 saw packets 0 and 2 (to node 1), rx2 packets 1 and 3 (to node 2).
    const Outcome &r = run();
    ASSERT_EQ(r.transactions.size(), 4u);
    EXPECT_EQ(r.xs, (std::vector<uint32_t>{0, 2, 1, 3}));
    EXPECT_EQ(r.addresses, (std::vector<uint64_t>{1, 1, 2, 2}));
    for (const tlm::tlm_generic_payload *t : r.transactions) EXPECT_EQ(t, r.transactions[0]);
    EXPECT_TRUE(r.one_made);  // released after every crossing, and back in the pool
    EXPECT_TRUE(r.one_free);  // the only one: the next take makes another
}

TEST(TransactionPool, ACrossingHoldsItsTransactionAcquired)
{
    for (unsigned c : run().ref_counts) EXPECT_EQ(c, 1u);
    for (bool w : run().writes) EXPECT_TRUE(w);  // a write of the packet in the extension
}
