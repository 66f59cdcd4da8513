// torus_system.h - the top module: instantiates the host, the frame buffer, and per torus node a
// communication unit, its processor side and its outgoing links, and binds them. Only what the
// configuration needs is built: no links along an axis with one node, no wrap-around links in a
// mesh, no cluster bus for one processor per node.
#pragma once

#include <memory>
#include <systemc>
#include <vector>

#include "activation_queue.h"
#include "comm_unit.h"
#include "frame_buffer.h"
#include "host.h"
#include "intersection_processor.h"
#include "packet_ledger.h"
#include "packet_pool.h"
#include "queue_registry.h"
#include "replica_choice.h"
#include "routing.h"
#include "sim_config.h"
#include "toroidal_link.h"
#include "transaction_pool.h"
#include "wake_calendar.h"

namespace torusrt {

class ClusterNode;

// Whether a flat approximately-timed machine with a positive link time and unbounded buffers
// takes a processor's packets for other nodes on as they are handed over and tells a waiting
// processor of a packet in the delta it arrives (at_once, what every run uses), or one delta
// later as every other machine does (next_delta: for the test that both give the same times).
// next_delta stays in the model: it is the reference order the at_once shortcut must equal, and
// costs one constructor argument.
enum class HandOverTiming { at_once, next_delta };

class TorusSystem : public sc_core::sc_module {
  public:
    TorusSystem(sc_core::sc_module_name name, const MachineConfig &config, const rt_scene *scene, const rt_grid *grid,
                const int32_t *cell_owner, PacketLedger &ledger, rt_framebuffer *fb,
                HandOverTiming hand_over = HandOverTiming::at_once, const rt_replicas *replicas = nullptr);
    ~TorusSystem() override;

    const Routing &routing() const { return m_routing; }
    std::vector<IntersectionProcessor *> processors() const;  // every processor, node-major
    const std::vector<std::unique_ptr<ToroidalLink>> &links() const { return m_links; }
    const std::vector<std::unique_ptr<CommUnit>> &comm_units() const { return m_comm; }
    const std::vector<std::unique_ptr<ClusterNode>> &clusters() const { return m_clusters; }
    Host &host() { return *m_host; }
    FrameBuffer &frame_buffer() { return *m_fb; }
    // Every bounded buffer: processor and dispatcher input queues node by node, then the links.
    const QueueRegistry &queues() const { return m_queues; }
    // Starts an animation frame between two sc_start calls, with the network empty: the
    // frame's image, its primaries from `offset` under the owner table's current contents,
    // and every idle input queue woken to take them up.
    void start_frame(rt_framebuffer *fb, const int32_t *cell_owner, const sc_core::sc_time &offset);
    // Between two frames of a moving scene, after `grid`'s lists changed: each cluster places
    // the objects its cells list again (flat processors read the lists as they go).
    void place_objects(const rt_grid *grid, const int32_t *cell_owner);

  private:
    Routing m_routing;
    std::unique_ptr<ReplicaChoice> m_replica_choice;  // replicated cells' destinations (null: none)
    PacketPool m_pool;               // every packet on the network, by handle (comm units, links, input queues)
    TransactionPool m_transactions;  // the links' crossings (one at a time: one transaction, hot)
    std::unique_ptr<ActivationQueue> m_activations;  // flat processors' state machines, when woken
    std::unique_ptr<WakeCalendar> m_calendar;        // the comm units' and processors' timed wake-ups
    std::unique_ptr<FrameBuffer> m_fb;
    std::unique_ptr<Host> m_host;
    std::vector<std::unique_ptr<CommUnit>> m_comm;
    std::vector<std::unique_ptr<IntersectionProcessor>> m_ips;  // flat torus: one per node
    std::vector<std::unique_ptr<ClusterNode>> m_clusters;       // clusters: one per node
    std::vector<std::unique_ptr<ToroidalLink>> m_links;
    QueueRegistry m_queues;
};

}  // namespace torusrt
