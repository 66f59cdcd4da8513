// host_test.cpp - the host and its primary source: every pixel whose primary ray enters the object
// space is handed out by the node owning its entry cell, in pixel order, stamped (pixel + 1) x
// host_inject; the rays that miss get the background written at the start and count as missed;
// every entering primary counts as created at once.
#include <systemc>
#include <tlm>
#include <tlm_utils/simple_target_socket.h>
#include <string>
#include <vector>

#include "harness.h"
#include "host.h"
#include "rt_packet.h"

using harness::check;
using sc_core::sc_time;
using namespace torusrt;

static sc_time us(double v) { return sc_time(v, sc_core::SC_US); }

struct FrameBufferStub : sc_core::sc_module {
    tlm_utils::simple_target_socket<FrameBufferStub> socket;
    std::vector<uint32_t> pixels; // y * width + x
    std::vector<sc_time> times;
    bool colour_ok = true;
    rt_vec3 want{};
    uint32_t width = 0;
    explicit FrameBufferStub(sc_core::sc_module_name n) : sc_module(n), socket("socket")
    {
        socket.register_b_transport(this, &FrameBufferStub::b_transport);
    }
    void b_transport(tlm::tlm_generic_payload &t, sc_time &delay)
    {
        auto *c = reinterpret_cast<const rt_contribution *>(t.get_data_ptr());
        for (size_t i = 0; i < t.get_data_length() / sizeof *c; i++) {
            pixels.push_back(c[i].y * width + c[i].x);
            colour_ok = colour_ok && c[i].rgb.x == want.x && c[i].rgb.y == want.y && c[i].rgb.z == want.z;
        }
        times.push_back(sc_core::sc_time_stamp() + delay);
        t.set_response_status(tlm::TLM_OK_RESPONSE);
    }
};

int sc_main(int, char *[])
{
    const uint32_t w = 16, h = 12;
    char msg[256];
    rt_scene *scene = rt_scene_new();
    rt_scene_set_view(scene, rt_vec(0, 0, 5), rt_vec(0, 0, 0), rt_vec(0, 1, 0), 45.0, w, h);
    rt_scene_set_background(scene, rt_vec(0.25, 0.5, 0.75));
    rt_scene_add_sphere(scene, rt_vec(0, 0, 0), 1.0);
    rt_scene_finish(scene, msg, sizeof msg);
    rt_grid *grid = rt_grid_new(scene, 2, 2, 2, msg, sizeof msg);
    std::vector<int32_t> owner(rt_grid_cell_count(grid));
    for (size_t c = 0; c < owner.size(); c++) owner[c] = static_cast<int32_t>(c % 3); // 3 nodes

    // Expected: per entry node the entering pixels in order, and the missed pixels.
    std::vector<std::vector<uint32_t>> want_pixels(3);
    std::vector<uint32_t> want_missed;
    for (uint32_t p = 0; p < w * h; p++) {
        rt_packet pk;
        int enters = 0;
        rt_primary_packet(scene, grid, p % w, p / w, &pk, &enters);
        if (enters) want_pixels[owner[rt_packet_cell(grid, &pk)]].push_back(p);
        else want_missed.push_back(p);
    }
    size_t entering = want_pixels[0].size() + want_pixels[1].size() + want_pixels[2].size();
    check(!want_missed.empty() && entering > 0, "the scene has missed and entering primaries");
    check(!want_pixels[0].empty() && !want_pixels[1].empty() && !want_pixels[2].empty(),
          "every node is the entry node of some primary");

    SimConfig config;
    rt_timing_defaults(&config.timing);
    config.timing.host_inject_us = 3;
    config.ips = {3, 1, 1};
    PacketLedger ledger;
    Host host("host", config, scene, grid, owner.data(), ledger);
    FrameBufferStub fb("fb");
    fb.want = rt_vec(0.25, 0.5, 0.75);
    fb.width = w;
    host.fb_socket.bind(fb.socket);

    check(ledger.totals().created[RT_PACKET_RAY] == entering, "every entering primary counts as created at once");
    check(ledger.totals().primary_missed == want_missed.size(), "every missing primary counts as missed");
    check(ledger.image_time() == us(3.0 * (want_missed.back() + 1)), "image time starts at the last missed pixel's injection");
    sc_core::sc_start();

    check(host.done_injecting(), "background written");
    check(fb.pixels == want_missed, "background written to exactly the missed pixels, in pixel order");
    check(fb.colour_ok, "background colour is the scene's");
    bool at_zero = true;
    for (const sc_time &t : fb.times) at_zero = at_zero && t == sc_core::SC_ZERO_TIME;
    check(at_zero, "background written at time 0");
    check(host.injected() == entering, "injected count is the entering primaries");

    PrimarySource &src = host.primaries();
    for (int node = 0; node < 3; node++) {
        std::vector<uint32_t> got;
        bool stamps = true, entry = true, flags = true;
        while (src.pending(node)) {
            sc_time next = src.next_time(node);
            TimedPacket t = src.take(node);
            uint32_t p = t.packet.y * w + t.packet.x;
            got.push_back(p);
            stamps = stamps && t.stamp == us(3.0 * (p + 1)) && next == t.stamp;
            entry = entry && owner[rt_packet_cell(grid, &t.packet)] == node;
            flags = flags && t.from_host && t.packet.kind == RT_PACKET_RAY && t.packet.depth == 0;
        }
        std::string n = " (node " + std::to_string(node) + ")";
        check(got == want_pixels[node], ("primaries in pixel order at their entry node" + n).c_str());
        check(stamps, ("primary stamped (pixel + 1) x 3 us" + n).c_str());
        check(entry, ("primary packet starts in a cell of its node" + n).c_str());
        check(flags, ("primary is a depth-0 ray from the host" + n).c_str());
    }
    int rc = harness::finish();
    rt_grid_free(grid);
    rt_scene_free(scene);
    return rc;
}
