// activation_queue_test.cpp - the machine's activation queue: clients asked for in one
// evaluation phase run after every process that was runnable when they asked (here: three
// methods woken at 10 us, one of which asks for nothing), in the order they were asked for, in
// the same delta; a client asking from its own activation runs again in that delta, after the
// others; and the queue is empty between rounds (a second round at 20 us runs only the client
// asked for then).
#include <algorithm>
#include <string>
#include <systemc>
#include <vector>

#include "activation_queue.h"
#include "model_test.h"

using model_test::us;
using namespace torusrt;

namespace {

struct Entry {
    std::string what;
    sc_core::sc_time at;
    sc_dt::uint64 delta;
};
std::vector<Entry> g_log;

void log(const std::string &what) { g_log.push_back({what, sc_core::sc_time_stamp(), sc_core::sc_delta_count()}); }

struct Client : ActivationQueue::Client {
    std::string name;
    ActivationQueue *queue = nullptr;
    int again = 0;  // times to ask again from its own activation
    void activate() override
    {
        log(name);
        if (again-- > 0) queue->request(*this);
    }
};

// One method per waker, all woken at 10 us by timed events; each asks for the given clients.
struct Waker : sc_core::sc_module {
    std::vector<Client *> asks;
    ActivationQueue &queue;
    sc_core::sc_time when;
    sc_core::sc_event ev;
    Waker(sc_core::sc_module_name n, ActivationQueue &q, sc_core::sc_time t) : sc_module(n), queue(q), when(t)
    {
        SC_HAS_PROCESS(Waker);
        SC_METHOD(wake);
        sensitive << ev;
        dont_initialize();
        SC_THREAD(arm);
    }
    void arm() { ev.notify(when); }
    void wake()
    {
        log(std::string(basename()));
        for (Client *c : asks) queue.request(*c);
    }
};

std::vector<Entry> simulate()
{
    ActivationQueue queue("queue");
    Client c0, c1, c2;
    c0.name = "c0", c1.name = "c1", c2.name = "c2";
    for (Client *c : {&c0, &c1, &c2}) c->queue = &queue;
    c0.again = 1;  // asks once more from its first activation
    Waker a("a", queue, us(10)), b("b", queue, us(10)), quiet("quiet", queue, us(10)), later("later", queue, us(20));
    a.asks = {&c2, &c0};
    b.asks = {&c1};
    later.asks = {&c1};
    sc_core::sc_start();
    return g_log;
}

const std::vector<Entry> &run()
{
    static const std::vector<Entry> r = simulate();
    return r;
}

std::vector<std::string> names_at(double t_us)
{
    std::vector<std::string> out;
    for (const Entry &e : run())
        if (e.at == us(t_us)) out.push_back(e.what);
    return out;
}

}  // namespace

TEST(ActivationQueue, RunsAfterTheRunnableMethodsInAskOrder)
{
    // The three wakers first (in whatever order SystemC runs them), then c2, c0, c1 as asked,
    // then c0 again (it asked from its own activation).
    std::vector<std::string> at10 = names_at(10);
    ASSERT_EQ(at10.size(), 7u);
    std::vector<std::string> wakers(at10.begin(), at10.begin() + 3), clients(at10.begin() + 3, at10.end());
    std::sort(wakers.begin(), wakers.end());
    EXPECT_EQ(wakers, (std::vector<std::string>{"a", "b", "quiet"}));
    EXPECT_EQ(clients, (std::vector<std::string>{"c2", "c0", "c1", "c0"}));
}

TEST(ActivationQueue, SameDelta)
{
    sc_dt::uint64 first = ~sc_dt::uint64{0};
    for (const Entry &e : run())
        if (e.at == us(10)) {
            if (first == ~sc_dt::uint64{0}) first = e.delta;
            EXPECT_EQ(e.delta, first) << e.what;
        }
}

TEST(ActivationQueue, EmptyBetweenRounds) { EXPECT_EQ(names_at(20), (std::vector<std::string>{"later", "c1"})); }
