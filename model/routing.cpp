// routing.cpp - dimension-order routing on rings (torus) or lines (mesh).
#include "routing.h"

#include <cstdlib>

namespace torusrt {

const char *direction_name(int dir)
{
    static const char *names[kDirections] = {"xp", "xm", "yp", "ym", "zp", "zm"};
    return dir >= 0 && dir < kDirections ? names[dir] : "none";
}

Routing::Routing(const std::array<int, 3> &dims, bool torus, RouteTies ties)
    : m_dims(dims), m_torus(torus), m_ties(ties)
{
    int nodes = dims[0] * dims[1] * dims[2];
    m_coords.reserve(static_cast<size_t>(nodes > 0 ? nodes : 0));
    for (int n = 0; n < nodes; n++) m_coords.push_back({n % dims[0], (n / dims[0]) % dims[1], n / (dims[0] * dims[1])});
}

std::array<int, 3> Routing::coords(int node) const { return m_coords[static_cast<size_t>(node)]; }

int Routing::node(const std::array<int, 3> &c) const { return c[0] + m_dims[0] * (c[1] + m_dims[1] * c[2]); }

int Routing::neighbour(int n, int dir) const
{
    int axis = dir / 2, step = dir % 2 == 0 ? 1 : -1;
    if (m_dims[axis] < 2) return -1;
    auto c = coords(n);
    int v = c[axis] + step;
    if (v < 0 || v >= m_dims[axis]) {
        if (!m_torus) return -1;
        v = (v + m_dims[axis]) % m_dims[axis];
    }
    c[axis] = v;
    return node(c);
}

bool Routing::wraps(int n, int dir) const
{
    int axis = dir / 2;
    if (!m_torus || m_dims[axis] < 2) return false;
    int c = coords(n)[axis];
    return dir % 2 == 0 ? c == m_dims[axis] - 1 : c == 0;
}

int Routing::hops(int from, int to) const
{
    int h = 0;
    while (from != to) {
        from = neighbour(from, next_direction(from, to, 0));
        h++;
    }
    return h;
}

}  // namespace torusrt
