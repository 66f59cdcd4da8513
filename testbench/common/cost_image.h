// cost_image.h - --cost-image: each step's modelled cost added to its packet's pixel.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "rt_render.h"
#include "rt_timing.h"

namespace torusrt {

class CostImage {
  public:
    // An empty path switches it off (attach, write and json then do nothing).
    CostImage(const std::string &path, unsigned width, unsigned height, const rt_timing *timing);
    // Memory a cost image of width x height pixels takes: its sums (8 bytes a pixel) and the
    // canvas its picture is drawn in (the memory budget holds it).
    static uint64_t bytes(unsigned width, unsigned height);
    void attach(rt_render_options *options);
    // Writes the PNG to `write_path` (the output set's name for it; UserError on failure).
    void write(const std::string &write_path) const;
    // JSON `cost_image`: file, total_us (equals the op-count total), max_pixel_us; null when off.
    nlohmann::json json() const;

  private:
    static void on_step(void *ctx, uint32_t cell, const rt_packet *packet, const rt_step_result *r);
    std::string m_path;
    unsigned m_width, m_height;
    const rt_timing *m_timing;
    std::vector<double> m_us;
};

}  // namespace torusrt
