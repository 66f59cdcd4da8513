// load_motion.cpp - moving a per-cell load field by the camera's motion between two frames, and
// blurring it.
#include "load_motion.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace torusrt {

namespace {

// Rows: right, true up, backwards (from - at), as the renderer's camera builds them.
void eye_axes(const rt_camera_pose &p, rt_vec3 axes[3])
{
    rt_vec3 w = rt_vec_normalize(rt_vec_sub(p.from, p.at));
    rt_vec3 u = rt_vec_normalize(rt_vec_cross(p.up, w));
    axes[0] = u;
    axes[1] = rt_vec_cross(w, u);
    axes[2] = w;
}

double component(rt_vec3 v, int i) { return i == 0 ? v.x : i == 1 ? v.y : v.z; }

// Rounding of an exact turn (a multiple of 90 degrees) must not spill work onto neighbours.
double snapped(double t) { return std::fabs(t - std::nearbyint(t)) < 1e-9 ? std::nearbyint(t) : t; }

// Where one cell's share goes: up to 8 cells and their weights.
struct Splat {
    long cell[8];
    double weight[8];
    int count = 0;
};

Splat splat_of(rt_vec3 p, const rt_box &b, const int d[3])
{
    long lo[3];
    double t[3];
    for (int i = 0; i < 3; i++) {
        double span = component(b.hi, i) - component(b.lo, i);
        double f = span > 0 ? snapped((component(p, i) - component(b.lo, i)) / span * d[i] - 0.5) : 0;
        f = std::min(std::max(f, 0.0), static_cast<double>(d[i] - 1));  // clamped: nothing is lost
        lo[i] = static_cast<long>(std::floor(f));
        t[i] = f - static_cast<double>(lo[i]);
    }
    Splat s;
    for (int corner = 0; corner < 8; corner++) {
        double w = 1;
        long idx[3];
        for (int i = 0; i < 3; i++) {
            int up = (corner >> i) & 1;
            w *= up ? t[i] : 1 - t[i];
            idx[i] = std::min<long>(lo[i] + up, d[i] - 1);
        }
        if (w <= 0) continue;
        s.cell[s.count] = idx[0] + d[0] * (idx[1] + static_cast<long>(d[1]) * idx[2]);
        s.weight[s.count++] = w;
    }
    return s;
}

rt_vec3 face_normal(int f)
{
    double s = f % 2 ? 1 : -1;
    return f / 2 == 0 ? rt_vec(s, 0, 0) : f / 2 == 1 ? rt_vec(0, s, 0) : rt_vec(0, 0, s);
}

// face_to[f]: the face whose normal is nearest face f's turned by m.
void face_map(const RigidMotion &m, int face_to[RT_CELL_FACES])
{
    for (int f = 0; f < RT_CELL_FACES; f++) {
        rt_vec3 n = m.turn(face_normal(f));
        int best = 0;
        for (int g = 1; g < RT_CELL_FACES; g++)
            if (rt_vec_dot(n, face_normal(g)) > rt_vec_dot(n, face_normal(best)) + 1e-12) best = g;
        face_to[f] = best;
    }
}

}  // namespace

rt_vec3 RigidMotion::turn(rt_vec3 v) const
{
    return rt_vec(r[0][0] * v.x + r[0][1] * v.y + r[0][2] * v.z, r[1][0] * v.x + r[1][1] * v.y + r[1][2] * v.z,
                  r[2][0] * v.x + r[2][1] * v.y + r[2][2] * v.z);
}

rt_vec3 RigidMotion::apply(rt_vec3 p) const { return rt_vec_add(to, turn(rt_vec_sub(p, from))); }

RigidMotion camera_motion(const rt_camera_pose &a, const rt_camera_pose &b)
{
    rt_vec3 ea[3], eb[3];
    eye_axes(a, ea);
    eye_axes(b, eb);
    RigidMotion m;
    for (int i = 0; i < 3; i++)  // R = Eb^T Ea: a's axis k goes to b's axis k
        for (int j = 0; j < 3; j++) {
            double s = 0;
            for (int k = 0; k < 3; k++) s += component(eb[k], i) * component(ea[k], j);
            m.r[i][j] = std::fabs(s) < 1e-15 ? 0 : s;
        }
    m.from = a.from;
    m.to = b.from;
    return m;
}

void move_load(const rt_cost_pilot &src, const rt_box &bounds, const RigidMotion &m, rt_cost_pilot &dst)
{
    const int *d = src.dims;
    std::vector<double> traffic(src.cells * RT_CELL_FACES, 0.0);
    std::fill(dst.work_us, dst.work_us + src.cells, 0.0);
    int face_to[RT_CELL_FACES];
    face_map(m, face_to);
    rt_vec3 cell_size = rt_vec((bounds.hi.x - bounds.lo.x) / d[0], (bounds.hi.y - bounds.lo.y) / d[1],
                               (bounds.hi.z - bounds.lo.z) / d[2]);
    for (size_t c = 0; c < src.cells; c++) {
        long x = static_cast<long>(c) % d[0], y = static_cast<long>(c) / d[0] % d[1];
        long z = static_cast<long>(c) / (static_cast<long>(d[0]) * d[1]);
        rt_vec3 centre = rt_vec(bounds.lo.x + (x + 0.5) * cell_size.x, bounds.lo.y + (y + 0.5) * cell_size.y,
                                bounds.lo.z + (z + 0.5) * cell_size.z);
        Splat s = splat_of(m.apply(centre), bounds, d);
        for (int i = 0; i < s.count; i++) {
            dst.work_us[s.cell[i]] += src.work_us[c] * s.weight[i];
            for (int f = 0; f < RT_CELL_FACES; f++)
                traffic[static_cast<size_t>(s.cell[i]) * RT_CELL_FACES + face_to[f]] +=
                    static_cast<double>(src.traffic[c * RT_CELL_FACES + f]) * s.weight[i];
        }
    }
    for (size_t i = 0; i < traffic.size(); i++) dst.traffic[i] = static_cast<uint64_t>(std::llround(traffic[i]));
    dst.total_us = src.total_us;
}

long neighbour_cell(const int d[3], long c, int f)
{
    long p[3] = {c % d[0], c / d[0] % d[1], c / (static_cast<long>(d[0]) * d[1])};
    p[f / 2] += (f % 2) ? 1 : -1;
    if (p[f / 2] < 0 || p[f / 2] >= d[f / 2]) return -1;
    return p[0] + d[0] * (p[1] + static_cast<long>(d[1]) * p[2]);
}

std::vector<double> cell_visits(const rt_cost_pilot &load)
{
    std::vector<double> out(load.cells, 0.0), in(load.cells, 0.0);
    for (size_t c = 0; c < load.cells; c++)
        for (int f = 0; f < RT_CELL_FACES; f++) {
            double n = static_cast<double>(load.traffic[c * RT_CELL_FACES + f]);
            out[c] += n;
            long nb = neighbour_cell(load.dims, static_cast<long>(c), f);
            if (nb >= 0) in[static_cast<size_t>(nb)] += n;
        }
    for (size_t c = 0; c < load.cells; c++) out[c] = std::max(out[c], in[c]);
    return out;
}

void move_visits(const rt_cost_pilot &src, const rt_box &bounds, const RigidMotion &m,
                 const std::vector<char> &occupied, rt_cost_pilot &dst)
{
    std::vector<double> visits = cell_visits(src);
    double cls_work[2] = {0, 0}, cls_visits[2] = {0, 0};
    for (size_t c = 0; c < src.cells; c++)
        if (visits[c] > 0)
            cls_work[occupied[c] ? 1 : 0] += src.work_us[c], cls_visits[occupied[c] ? 1 : 0] += visits[c];
    std::vector<double> per_visit(src.cells);
    for (size_t c = 0; c < src.cells; c++) {
        int k = occupied[c] ? 1 : 0;
        per_visit[c] = visits[c] > 0 ? src.work_us[c] / visits[c] : cls_visits[k] > 0 ? cls_work[k] / cls_visits[k] : 0;
    }
    rt_cost_pilot v = src;  // the visits as a load, moved like one
    std::vector<double> vw(visits);
    v.work_us = vw.data();
    move_load(v, bounds, m, dst);
    double total = 0;
    for (size_t c = 0; c < src.cells; c++) total += dst.work_us[c] *= per_visit[c];
    double scale = total > 0 ? src.total_us / total : 0;
    for (size_t c = 0; c < src.cells; c++) dst.work_us[c] *= scale;
    dst.total_us = src.total_us;
}

void blur_load(const rt_cost_pilot &src, double keep, rt_cost_pilot &dst)
{
    std::fill(dst.work_us, dst.work_us + src.cells, 0.0);
    for (size_t c = 0; c < src.cells; c++) {
        long nb[RT_CELL_FACES];
        int n = 0;
        for (int f = 0; f < RT_CELL_FACES; f++)
            if ((nb[n] = neighbour_cell(src.dims, static_cast<long>(c), f)) >= 0) n++;
        double w = src.work_us[c];
        dst.work_us[c] += w * (n ? keep : 1);
        for (int i = 0; i < n; i++) dst.work_us[nb[i]] += w * (1 - keep) / n;
    }
    std::copy(src.traffic, src.traffic + src.cells * RT_CELL_FACES, dst.traffic);
    dst.total_us = src.total_us;
}

}  // namespace torusrt
