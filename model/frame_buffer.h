// frame_buffer.h - the frame buffer as a TLM-2.0 target: IPs and the host write pixel
// contributions (a generic payload whose data is an array of rt_contribution).
#pragma once

#include <systemc>
#include <tlm>
#include <tlm_utils/multi_passthrough_target_socket.h>

#include "rt_framebuffer.h"

namespace torusrt {

class FrameBuffer : public sc_core::sc_module {
  public:
    tlm_utils::multi_passthrough_target_socket<FrameBuffer> socket;  // contributions from IPs and host

    FrameBuffer(sc_core::sc_module_name name, rt_framebuffer *fb);

    uint64_t writes() const { return m_writes; }
    // The next frame's image (between frames of an animation).
    void retarget(rt_framebuffer *fb) { m_fb = fb; }

  private:
    void b_transport(int id, tlm::tlm_generic_payload &trans, sc_core::sc_time &delay);

    rt_framebuffer *m_fb;
    uint64_t m_writes = 0;
};

}  // namespace torusrt
