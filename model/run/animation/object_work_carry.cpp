// object_work_carry.cpp - moving objects' measured work carried into their next frame's cells.
#include "object_work_carry.h"

#include <algorithm>
#include <cmath>

#include "motion_update.h"

namespace torusrt {

namespace {

// The cell holding point p, clamped into the grid.
size_t cell_at(const rt_grid *grid, const int dims[3], rt_vec3 p)
{
    rt_box b = rt_grid_bounds(grid);
    rt_vec3 size = rt_grid_cell_size(grid);
    double v[3] = {p.x - b.lo.x, p.y - b.lo.y, p.z - b.lo.z}, s[3] = {size.x, size.y, size.z};
    size_t index[3];
    for (int k = 0; k < 3; k++) {
        double i = s[k] > 0 ? std::floor(v[k] / s[k]) : 0;
        index[k] = static_cast<size_t>(std::clamp(i, 0.0, static_cast<double>(dims[k] - 1)));
    }
    return index[0] + static_cast<size_t>(dims[0]) * (index[1] + static_cast<size_t>(dims[1]) * index[2]);
}

rt_vec3 cell_centre(const rt_grid *grid, const int dims[3], size_t c)
{
    int x = static_cast<int>(c % static_cast<size_t>(dims[0]));
    int y = static_cast<int>(c / static_cast<size_t>(dims[0]) % static_cast<size_t>(dims[1]));
    int z = static_cast<int>(c / (static_cast<size_t>(dims[0]) * static_cast<size_t>(dims[1])));
    rt_box b = rt_grid_cell_box(grid, x, y, z);
    return {(b.lo.x + b.hi.x) / 2, (b.lo.y + b.hi.y) / 2, (b.lo.z + b.hi.z) / 2};
}

}  // namespace

void carry_object_work(const rt_cost_pilot &src, const rt_grid *next, const ObjectShifts &shifts, rt_cost_pilot &dst)
{
    std::copy(src.work_us, src.work_us + src.cells, dst.work_us);
    std::copy(src.traffic, src.traffic + src.cells * RT_CELL_FACES, dst.traffic);
    std::vector<ObjectCell> after = moved_entries(next, shifts.moved);  // by object, then cell
    auto lists = [&](uint32_t o, uint32_t c) {
        auto it = std::lower_bound(after.begin(), after.end(), ObjectCell{o, c},
                                   [](const ObjectCell &a, const ObjectCell &b) {
                                       return a.object != b.object ? a.object < b.object : a.cell < b.cell;
                                   });
        return it != after.end() && it->object == o && it->cell == c;
    };
    size_t e = 0;
    while (e < src.object_us_count) {
        uint32_t o = src.object_us[e].object;
        size_t end = e;
        while (end < src.object_us_count && src.object_us[end].object == o) end++;
        if (o >= shifts.moved.size() || !shifts.moved[o]) {
            e = end;
            continue;
        }
        auto first = std::lower_bound(after.begin(), after.end(), o,
                                      [](const ObjectCell &a, uint32_t obj) { return a.object < obj; });
        auto last = std::find_if(first, after.end(), [o](const ObjectCell &a) { return a.object != o; });
        if (first == last) {  // listed nowhere in frame k: its work stays where it was
            e = end;
            continue;
        }
        double spill = 0;
        rt_vec3 d = shifts.shift[o];
        for (; e < end; e++) {
            const rt_object_cell_us &w = src.object_us[e];
            dst.work_us[w.cell] -= w.us;
            rt_vec3 p = cell_centre(next, src.dims, w.cell);
            size_t to = cell_at(next, src.dims, {p.x + d.x, p.y + d.y, p.z + d.z});
            if (lists(o, static_cast<uint32_t>(to))) dst.work_us[to] += w.us;
            else spill += w.us;
        }
        double share = spill / static_cast<double>(last - first);
        for (auto it = first; it != last; it++) dst.work_us[it->cell] += share;
    }
    dst.total_us = 0;
    for (size_t c = 0; c < src.cells; c++) dst.total_us += dst.work_us[c] = std::max(0.0, dst.work_us[c]);
}

}  // namespace torusrt
