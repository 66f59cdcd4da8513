// wake_calendar_test.cpp - the machine's wake calendar: clients due at the same time are woken
// in client order (the order they were added), whatever order they asked in; asking for an
// earlier time replaces a client's later wake (no simulated time is spent on the later one, and
// nothing is left pending at the end), asking for a later one while an earlier is pending changes
// nothing; a client woken may ask again (the calendar re-arms for it), also for a time earlier
// than the one the calendar is already notified for. Many clients asking again and again, with
// earlier asks replacing later ones, are woken in (time, client) order, each at its earliest ask;
// so is a calendar's only client.
#include <systemc>
#include <utility>
#include <vector>

#include "model_test.h"
#include "wake_calendar.h"

using model_test::us;
using sc_core::sc_time;
using namespace torusrt;

struct Wake {
    sc_time at;
    int client;
    sc_dt::uint64 delta;
};

// A client that records each wake and may ask for its next one from there.
struct RecordingClient : WakeCalendar::Client {
    WakeCalendar *calendar = nullptr;
    int id = -1;
    std::vector<Wake> *log = nullptr;
    std::vector<sc_time> next;  // times asked for from the wakes, in turn
    void wake_due() override
    {
        log->push_back({sc_core::sc_time_stamp(), id, sc_core::sc_delta_count()});
        if (next.empty()) return;
        calendar->wake_at(id, next.front());
        next.erase(next.begin());
    }
};

struct Outcome {
    std::vector<Wake> wakes;
    sc_time end;              // simulation time when nothing was left to do
    size_t pending_left = 0;  // clients with a wake pending at the end
    bool due_after_ask = false, due_after_wake = true;
    sc_time due_seen;
    std::vector<int> ids;                          // what add() returned, in the order the clients were added
    std::vector<Wake> crowd;                       // the wakes of the crowd below
    std::vector<Wake> solo;                        // the wakes of a calendar with one client (its tree is a leaf)
    std::vector<std::vector<sc_time>> crowd_want;  // per crowd client, the times it must be woken at
};

// A crowd of clients (ids 4..): each asks, from time 0, for a later time and then an earlier one
// (which replaces it), and from each wake for the next of its times, 3 in all; times are
// pseudo-random multiples of 1 us in [100, 400) us, so many coincide.
constexpr int kCrowd = 300;
static void plan_crowd(std::vector<RecordingClient> &crowd, Outcome &out)
{
    uint32_t x = 12345;
    auto next = [&x] { return x = x * 1103515245u + 12345u, (x >> 8) % 100; };
    out.crowd_want.resize(crowd.size());
    for (size_t i = 0; i < crowd.size(); i++) {
        sc_time t = us(100 + static_cast<double>(next()));
        for (int k = 0; k < 3; k++, t += us(1 + static_cast<double>(next()))) out.crowd_want[i].push_back(t);
        crowd[i].next = {out.crowd_want[i][1], out.crowd_want[i][2]};
    }
}

// Asks for wakes at time 0 and at 5 us.
struct Asker : sc_core::sc_module {
    WakeCalendar &calendar;
    Outcome &out;
    Asker(sc_core::sc_module_name n, WakeCalendar &c, Outcome &o) : sc_module(n), calendar(c), out(o)
    {
        SC_HAS_PROCESS(Asker);
        SC_THREAD(run);
    }
    void run()
    {
        // 10 us: clients 2, 0, 3 ask in that order; woken 0, 2, 3.
        calendar.wake_at(2, us(10));
        calendar.wake_at(0, us(10));
        calendar.wake_at(3, us(10));
        // Client 1 asks for 60 us, then (at 5 us) for 20 us: woken at 20 us only.
        calendar.wake_at(1, us(60));
        // Client 3 asks for 40 us while due at 10 us: no effect.
        calendar.wake_at(3, us(40));
        out.due_after_ask = calendar.due_time(1, out.due_seen);
        sc_core::wait(us(5));
        calendar.wake_at(1, us(20));
    }
};

static Outcome simulate()
{
    Outcome out;
    WakeCalendar calendar("calendar");
    std::vector<RecordingClient> clients(4);
    for (RecordingClient &c : clients) {
        c.calendar = &calendar;
        c.id = calendar.add(c);
        out.ids.push_back(c.id);
        c.log = &out.wakes;
    }
    // Client 0 asks again from its wake at 10 us for 15 us, then from there for 30 us.
    clients[0].next = {us(15), us(30)};
    // Client 2 asks from its wake at 10 us for 12 us: earlier than the 15 us asked just before.
    clients[2].next = {us(12)};
    std::vector<RecordingClient> crowd(kCrowd);
    for (RecordingClient &c : crowd) {
        c.calendar = &calendar;
        c.id = calendar.add(c);
        c.log = &out.crowd;
    }
    plan_crowd(crowd, out);
    for (size_t i = 0; i < crowd.size(); i++) {
        calendar.wake_at(crowd[i].id, out.crowd_want[i][0] + us(500));  // replaced just below
        calendar.wake_at(crowd[i].id, out.crowd_want[i][0]);
    }
    // One client alone: asks for 7 us, then 3 us (replacing it), and from its wake for 8 us.
    WakeCalendar solo_calendar("solo_calendar");
    RecordingClient solo;
    solo.calendar = &solo_calendar;
    solo.id = solo_calendar.add(solo);
    solo.log = &out.solo;
    solo.next = {us(8)};
    solo_calendar.wake_at(solo.id, us(7));
    solo_calendar.wake_at(solo.id, us(3));
    Asker asker("asker", calendar, out);
    sc_core::sc_start();
    out.end = sc_core::sc_time_stamp();
    out.pending_left = calendar.pending();
    sc_time unused;
    out.due_after_wake = calendar.due_time(1, unused);
    return out;
}

static const Outcome &run()
{
    static const Outcome r = simulate();
    return r;
}

TEST(WakeCalendar, AddGivesIdsInOrder)
{
    // Ids are the ranks among simultaneous wakes: 0, 1, 2, 3 in the order added.
    EXPECT_EQ(run().ids, (std::vector<int>{0, 1, 2, 3}));
}

TEST(WakeCalendar, SimultaneousWakesInClientOrder)
{
    const auto &w = run().wakes;
    ASSERT_GE(w.size(), 3u);
    // Asked 2, 0, 3 at time 0 for 10 us: woken 0, 2, 3, all in one delta.
    EXPECT_EQ(w[0].client, 0);
    EXPECT_EQ(w[1].client, 2);
    EXPECT_EQ(w[2].client, 3);
    for (int i = 0; i < 3; i++) EXPECT_EQ(w[i].at, us(10));
    EXPECT_EQ(w[0].delta, w[2].delta);
}

TEST(WakeCalendar, ClientWokenAgainWhereItAsked)
{
    const auto &w = run().wakes;
    ASSERT_EQ(w.size(), 7u);
    // From the 10 us wakes: client 0 asked for 15 us, client 2 for 12 us (so the calendar is
    // re-notified earlier than it was); then client 1 at 20 us, client 0 again at 30 us.
    std::vector<std::pair<sc_time, int>> rest;
    for (size_t i = 3; i < w.size(); i++) rest.push_back({w[i].at, w[i].client});
    std::vector<std::pair<sc_time, int>> want = {{us(12), 2}, {us(15), 0}, {us(20), 1}, {us(30), 0}};
    EXPECT_EQ(rest, want);
}

TEST(WakeCalendar, EarlierWakeReplacesLaterOne)
{
    // Client 1 asked for 60 us, then for 20 us: woken once, at 20 us; and client 3's later ask
    // (40 us) while due at 10 us left it woken once.
    int ones = 0, threes = 0;
    for (const Wake &w : run().wakes) {
        ones += w.client == 1;
        threes += w.client == 3;
    }
    EXPECT_EQ(ones, 1);
    EXPECT_EQ(threes, 1);
    EXPECT_TRUE(run().due_after_ask);
    EXPECT_EQ(run().due_seen, us(60));
    EXPECT_FALSE(run().due_after_wake);
}

TEST(WakeCalendar, StaleKeySpendsNoTime)
{
    // The replaced 60 us key (and the crowd's replaced ones, 500 us later than their first) are
    // dropped without an event: the run ends at the last wake, with nothing pending.
    sc_time last = run().wakes.back().at;
    for (const Wake &w : run().crowd) last = w.at > last ? w.at : last;
    EXPECT_EQ(run().end, last);
    EXPECT_EQ(run().pending_left, 0u);
}

TEST(WakeCalendar, CrowdWokenInTimeThenClientOrder)
{
    const auto &c = run().crowd;
    ASSERT_EQ(c.size(), static_cast<size_t>(3 * kCrowd));
    for (size_t i = 1; i < c.size(); i++) {
        bool ordered = c[i - 1].at < c[i].at || (c[i - 1].at == c[i].at && c[i - 1].client < c[i].client);
        EXPECT_TRUE(ordered) << "wake " << i;
    }
    // Each client woken at exactly the times it asked for (the first ask's replacement included).
    std::vector<std::vector<sc_time>> got(kCrowd);
    for (const Wake &w : c) got[static_cast<size_t>(w.client - 4)].push_back(w.at);
    EXPECT_EQ(got, run().crowd_want);
}

TEST(WakeCalendar, OneClientAlone)
{
    // A calendar of one client: the earlier ask replaced the later, the wake asked from the first
    // wake came at its time.
    std::vector<sc_time> at;
    for (const Wake &w : run().solo) at.push_back(w.at);
    EXPECT_EQ(at, (std::vector<sc_time>{us(3), us(8)}));
}
