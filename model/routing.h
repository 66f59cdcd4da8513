// routing.h - node coordinates on the torus (or mesh) and dimension-order routing.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace torusrt {

// Link directions: 2 * axis + (0 for +, 1 for -).
constexpr int kDirections = 6;
inline int direction(int axis, bool positive) { return 2 * axis + (positive ? 0 : 1); }
const char *direction_name(int dir);

// Which way a packet goes round an even ring when both ways are equally short (the node
// opposite). split: + when the packet's tie key is even, - when odd, so a ring of two uses both
// of its links; plus: always +, so a ring of two uses one link each way, as two nodes joined by
// one link would. Either keeps a route minimal and in one direction per ring, which is what the
// dateline argument of flow_control.h needs.
enum class RouteTies { split, plus };
constexpr RouteTies kDefaultRouteTies = RouteTies::split;  // two links in a ring of two (docs/flow-control.md)

class Routing {
  public:
    Routing(const std::array<int, 3> &dims, bool torus, RouteTies ties = kDefaultRouteTies);
    std::array<int, 3> coords(int node) const;
    int node(const std::array<int, 3> &c) const;
    // The node one hop from `node` in direction `dir`, or -1 if there is no link (mesh edge,
    // or an axis with one node).
    int neighbour(int node, int dir) const;
    // Direction of the first hop from `from` toward `to` (x, then y, then z; on a ring the
    // shorter way, a tie by the RouteTies rule on `tie_key`), or -1 if from == to. A tie can
    // only arise at a packet's first hop on an axis, so the key decides the whole ring's way.
    int next_direction(int from, int to, uint32_t tie_key) const
    {
        return next_direction_by(from, to, [tie_key] { return tie_key; });
    }
    // The same with the key from `tie_key()`, called only when a tie arises: a hop then reads no
    // more of its packet than it needs.
    template <class TieKey> int next_direction_by(int from, int to, TieKey tie_key) const
    {
        const std::array<int, 3> &a = m_coords[static_cast<size_t>(from)], &b = m_coords[static_cast<size_t>(to)];
        for (int axis = 0; axis < 3; axis++) {
            if (a[axis] == b[axis]) continue;
            if (!m_torus) return direction(axis, b[axis] > a[axis]);
            int p = m_dims[axis];
            int forward = b[axis] - a[axis];
            if (forward < 0) forward += p;  // the hops going + round the ring
            if (forward != p - forward) return direction(axis, forward < p - forward);
            return direction(axis, m_ties == RouteTies::plus || tie_key() % 2 == 0);
        }
        return -1;
    }
    RouteTies ties() const { return m_ties; }
    // Whether the link leaving `node` in direction `dir` is its ring's wrap-around link (from
    // the last coordinate to 0 going +, from 0 to the last going -): the dateline.
    bool wraps(int node, int dir) const;
    // Hops from `from` to `to` by dimension-order routing (the same either way on a tie).
    int hops(int from, int to) const;

  private:
    std::array<int, 3> m_dims;
    bool m_torus;
    RouteTies m_ties;
    // Every node's coordinates, worked out once: a hop asks for two and divisions cost more.
    std::vector<std::array<int, 3>> m_coords;
};

}  // namespace torusrt
