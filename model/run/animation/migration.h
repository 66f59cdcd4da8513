// migration.h - what moving cells between nodes costs between two frames of an animation.
// A cell that changes owner travels from its old owner to its new one: its cell list (a 4-byte
// header plus 4 bytes per entry, as rt_memory counts it) and every object record it lists that
// the new owner does not hold yet (rt_scene_object_bytes; each object at most once per node;
// materials are not counted). A transfer goes along the routing's dimension-order path and
// loads every link on it with its bytes. Links work in parallel, each sending its bytes back to
// back: the migration takes as long as the busiest link, at the link timing (bytes / the link's
// bandwidth when link_bytes_per_us > 0, otherwise link_us per packet_bytes piece, rounded up).
#pragma once

#include <cstdint>
#include <vector>

#include "routing.h"
#include "rt_grid.h"
#include "rt_scene.h"
#include "rt_timing.h"

namespace torusrt {

struct MigrationCost {
    uint64_t cells = 0;         // cells that change owner
    uint64_t objects = 0;       // object records sent
    uint64_t list_bytes = 0;    // cell-list bytes sent
    uint64_t object_bytes = 0;  // object bytes sent
    uint64_t bytes() const { return list_bytes + object_bytes; }
    uint64_t byte_hops = 0;  // bytes times the hops they travel
    int max_hops = 0;        // the longest transfer's path
    uint64_t busiest_link_bytes = 0;
    double time_s = 0;  // the busiest link's time
};

// Microseconds one link takes for `bytes` bytes under `timing`.
double link_transfer_us(const rt_timing &timing, uint64_t bytes);

// The links' load of a set of transfers between frames: each transfer goes along the routing's
// dimension-order path and loads every link on it with its bytes.
class LinkLoad {
  public:
    LinkLoad(const Routing &routing, int nodes);
    // One transfer of `bytes` from node `from` to node `to` (nothing when they are the same);
    // `tie_key` (the cell or object moved) picks the way round an even ring on a tie.
    void send(int from, int to, uint64_t bytes, uint32_t tie_key);
    // Fills m's byte_hops, max_hops, busiest_link_bytes and time_s (the busiest link's time).
    void finish(const rt_timing &timing, MigrationCost &m) const;

  private:
    const Routing &m_routing;
    std::vector<uint64_t> m_link_bytes;  // node x direction
    uint64_t m_byte_hops = 0;
    int m_max_hops = 0;
};

// Bytes cell `cell` takes when it moves to a node holding none of its objects.
uint64_t cell_move_bytes(const rt_scene *scene, const rt_grid *grid, size_t cell);

// The cost of going from `old_owner` to `new_owner` (one node id per cell, `nodes` nodes).
MigrationCost migration_cost(const rt_scene *scene, const rt_grid *grid, const Routing &routing, int nodes,
                             const rt_timing &timing, const std::vector<int32_t> &old_owner,
                             const std::vector<int32_t> &new_owner);

}  // namespace torusrt
