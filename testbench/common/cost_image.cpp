// cost_image.cpp - per-pixel modelled cost: every step's cost goes to its packet's pixel, so
// the pixels sum to the run's op-count total.
#include "cost_image.h"

#include <algorithm>

#include "output_files.h"
#include "rt_load_image.h"
#include "user_error.h"

namespace torusrt {

CostImage::CostImage(const std::string &path, unsigned width, unsigned height, const rt_timing *timing)
    : m_path(path), m_width(width), m_height(height), m_timing(timing)
{
    if (!m_path.empty()) m_us.assign(static_cast<size_t>(width) * height, 0.0);
}

uint64_t CostImage::bytes(unsigned width, unsigned height)
{
    return static_cast<uint64_t>(width) * height * sizeof(double) + rt_cost_image_canvas_bytes(width, height);
}

void CostImage::on_step(void *ctx, uint32_t, const rt_packet *p, const rt_step_result *r)
{
    auto *self = static_cast<CostImage *>(ctx);
    self->m_us[static_cast<size_t>(p->y) * self->m_width + p->x] += rt_timing_step_us(self->m_timing, &r->ops);
}

void CostImage::attach(rt_render_options *o)
{
    if (m_path.empty()) return;
    o->on_step = &CostImage::on_step;
    o->on_step_ctx = this;
}

void CostImage::write(const std::string &write_path) const
{
    if (m_path.empty()) return;
    write_stream_file(write_path, m_path, "--cost-image", [this](FILE *fp, char *msg, size_t msg_len) {
        return rt_cost_image_write(fp, m_path.c_str(), m_width, m_height, m_us.data(), msg, msg_len);
    });
}

nlohmann::json CostImage::json() const
{
    if (m_path.empty()) return nullptr;
    double total = 0;
    for (double v : m_us) total += v;
    return {{"file", m_path},
            {"total_us", total},
            {"max_pixel_us", m_us.empty() ? 0.0 : *std::max_element(m_us.begin(), m_us.end())}};
}

}  // namespace torusrt
