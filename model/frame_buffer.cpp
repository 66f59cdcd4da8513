// frame_buffer.cpp - accumulates contributions in the kernel's fixed-point frame buffer,
// whose sums do not depend on the order writes arrive in.
#include "frame_buffer.h"

#include "rt_step.h"

namespace torusrt {

FrameBuffer::FrameBuffer(sc_core::sc_module_name name, rt_framebuffer *fb) : sc_module(name), socket("socket"), m_fb(fb)
{
    socket.register_b_transport(this, &FrameBuffer::b_transport);
}

void FrameBuffer::b_transport(int, tlm::tlm_generic_payload &trans, sc_core::sc_time &)
{
    // The write cost is charged by the writer (fb_write in the timing table).
    auto *c = reinterpret_cast<const rt_contribution *>(trans.get_data_ptr());
    size_t n = trans.get_data_length() / sizeof(rt_contribution);
    for (size_t i = 0; i < n; i++) rt_framebuffer_add(m_fb, c[i].x, c[i].y, c[i].rgb);
    m_writes += n;
    trans.set_response_status(tlm::TLM_OK_RESPONSE);
}

}  // namespace torusrt
