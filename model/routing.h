// routing.h - node coordinates on the torus (or mesh) and dimension-order routing.
#pragma once

#include <array>
#include <vector>

namespace torusrt {

// Link directions: 2 * axis + (0 for +, 1 for -).
constexpr int kDirections = 6;
inline int direction(int axis, bool positive) { return 2 * axis + (positive ? 0 : 1); }
const char *direction_name(int dir);

class Routing {
  public:
    Routing(const std::array<int, 3> &dims, bool torus);
    std::array<int, 3> coords(int node) const;
    int node(const std::array<int, 3> &c) const;
    // The node one hop from `node` in direction `dir`, or -1 if there is no link (mesh edge,
    // or an axis with one node).
    int neighbour(int node, int dir) const;
    // Direction of the first hop from `from` toward `to` (x, then y, then z; on a ring the
    // shorter way, + on a tie), or -1 if from == to.
    int next_direction(int from, int to) const;
    // Whether the link leaving `node` in direction `dir` is its ring's wrap-around link (from
    // the last coordinate to 0 going +, from 0 to the last going -): the dateline.
    bool wraps(int node, int dir) const;
    // Hops from `from` to `to` by dimension-order routing.
    int hops(int from, int to) const;

  private:
    std::array<int, 3> m_dims;
    bool m_torus;
    // Every node's coordinates, worked out once: a hop asks for two and divisions cost more.
    std::vector<std::array<int, 3>> m_coords;
};

}  // namespace torusrt
