// packet_latency.h - latency statistics in fixed memory: per packet kind, the time from a
// packet's making (a primary: its first step) to its consumption, split into time in processing
// (the steps that handed it on and the one that consumed it), on links (its hops times a link's
// packet time) and queued (the rest: buffers, link queues, the bus, held for room); per pixel,
// from the start of its primary's first step to its last frame-buffer contribution. Totals go into a log
// histogram of fixed size (16 buckets per octave), so recording allocates nothing.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <systemc>
#include <vector>

namespace torusrt {

// Microseconds in buckets: [0, 1), then 16 per octave from 1 us to 2^40 us (the last one open).
class LogHistogram {
  public:
    static constexpr int kSub = 16, kOctaves = 40, kBuckets = 1 + kSub * kOctaves;

    void add(double us)
    {
        m_count++;
        m_sum += us;
        if (m_count == 1 || us < m_min) m_min = us;
        if (us > m_max) m_max = us;
        m_bucket[bucket_of(us)]++;
    }
    uint64_t count() const { return m_count; }
    double mean() const { return m_count ? m_sum / static_cast<double>(m_count) : 0.0; }
    double min() const { return m_min; }
    double max() const { return m_max; }
    // The p-th percentile (0 < p <= 100): the upper edge of the bucket holding the sample of rank
    // ceil(p/100 count), within the observed minimum and maximum (exact for one sample).
    double percentile(double p) const
    {
        if (!m_count) return 0.0;
        uint64_t rank = static_cast<uint64_t>(std::ceil(p / 100.0 * static_cast<double>(m_count)));
        if (rank < 1) rank = 1;
        uint64_t seen = 0;
        for (int b = 0; b < kBuckets; b++) {
            seen += m_bucket[b];
            if (seen >= rank) return std::fmin(m_max, std::fmax(m_min, upper_edge(b)));
        }
        return m_max;
    }
    // Samples in octave k ([2^k, 2^(k+1)) us; k = -1: below 1 us).
    uint64_t octave_count(int k) const
    {
        if (k < 0) return m_bucket[0];
        uint64_t n = 0;
        for (int s = 0; s < kSub; s++) n += m_bucket[1 + k * kSub + s];
        return n;
    }

  private:
    // Read from the double's bits (every consumed packet passes here): the exponent is the
    // octave, the top four bits of the fraction the sixteenth within it.
    static int bucket_of(double us)
    {
        static_assert(kSub == 16, "four bits of the fraction");
        if (!(us >= 1.0)) return 0;
        uint64_t bits;
        std::memcpy(&bits, &us, sizeof bits);
        int octave = static_cast<int>(bits >> 52) - 1023;  // us >= 1: positive, normal
        if (octave >= kOctaves) return kBuckets - 1;
        return 1 + octave * kSub + static_cast<int>((bits >> 48) & (kSub - 1));
    }
    static double upper_edge(int b)
    {
        if (b == 0) return 1.0;
        int octave = (b - 1) / kSub, sub = (b - 1) % kSub;
        return std::ldexp(1.0 + (sub + 1.0) / kSub, octave);
    }
    std::array<uint64_t, kBuckets> m_bucket{};
    uint64_t m_count = 0;
    double m_sum = 0, m_min = 0, m_max = 0;
};

// One packet kind's latencies.
struct KindLatency {
    LogHistogram total;
    double queued_us = 0, links_us = 0, processing_us = 0;  // sums over the packets
    double queued_max_us = 0, links_max_us = 0, processing_max_us = 0;
    uint64_t hops = 0, hops_max = 0;

    // Times in SystemC time values (picoseconds), so the parts add up exactly.
    void add(uint64_t total_ps, uint64_t links_ps, uint64_t processing_ps, uint64_t h)
    {
        uint64_t known = links_ps + processing_ps;
        double queued = total_ps > known ? us(total_ps - known) : 0.0, links = us(links_ps),
               processing = us(processing_ps);
        total.add(us(total_ps));
        queued_us += queued;
        links_us += links;
        processing_us += processing;
        if (queued > queued_max_us) queued_max_us = queued;
        if (links > links_max_us) links_max_us = links;
        if (processing > processing_max_us) processing_max_us = processing;
        hops += h;
        if (h > hops_max) hops_max = h;
    }
    // Microseconds of a time value (picoseconds, as module_stats.h counts them): no SystemC call
    // on the way, as every consumed packet passes here.
    static double us(uint64_t value) { return static_cast<double>(value) * 1e-6; }
};

class PacketLatency {
    static constexpr uint64_t kNone = UINT64_MAX;
    // Per pixel, SystemC time values side by side: a pixel's start and its contributions touch
    // one cache line.
    struct PixelSpan {
        uint64_t start = kNone, last = 0;
    };

  public:
    enum Kind { primary, ray, shadow, kKinds };
    static const char *kind_name(int k) { return k == primary ? "primary" : k == ray ? "ray" : "shadow"; }

    // The image size, for the per-pixel figures (elaboration).
    void set_image(uint32_t width, uint32_t height)
    {
        m_width = width;
        m_pixel.assign(static_cast<size_t>(width) * height, PixelSpan{});
    }
    // Memory the per-pixel figures take for each pixel (the run's budget holds it).
    static constexpr uint64_t bytes_per_pixel() { return sizeof(PixelSpan); }
    void set_link_time(const sc_core::sc_time &t) { m_link = t.value(); }

    // A packet consumed at `when`: made at `born`, `worked` (a time value) in the steps before,
    // `step` in the last one, over `hops` links.
    void consumed(int kind, const sc_core::sc_time &born, uint64_t worked, const sc_core::sc_time &step, uint64_t hops,
                  const sc_core::sc_time &when)
    {
        m_kind[kind].add(when.value() - born.value(), hops * m_link, worked + step.value(), hops);
    }
    // The primary of pixel (x, y) began its first step at `when`.
    void primary_started(uint32_t x, uint32_t y, const sc_core::sc_time &when)
    {
        size_t i = index(x, y);
        if (i < m_pixel.size()) m_pixel[i].start = when.value();
    }
    // Pixel (x, y) got a contribution at `when`.
    void contributed(uint32_t x, uint32_t y, const sc_core::sc_time &when)
    {
        size_t i = index(x, y);
        if (i < m_pixel.size() && when.value() > m_pixel[i].last) m_pixel[i].last = when.value();
    }

    const KindLatency &kind(int k) const { return m_kind[k]; }
    // Per pixel whose primary entered the machine: its primary's first step to its last contribution.
    LogHistogram pixels() const
    {
        LogHistogram h;
        for (const PixelSpan &p : m_pixel)
            if (p.start != kNone && p.last >= p.start) h.add(KindLatency::us(p.last - p.start));
        return h;
    }

  private:
    size_t index(uint32_t x, uint32_t y) const { return x < m_width ? static_cast<size_t>(y) * m_width + x : SIZE_MAX; }
    std::array<KindLatency, kKinds> m_kind{};
    uint64_t m_link = 0;  // a link's packet time (time value)
    uint32_t m_width = 0;
    std::vector<PixelSpan> m_pixel;
};

}  // namespace torusrt
