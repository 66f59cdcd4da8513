// delivery_round_if.h - what a processor that runs after its own node's deliveries asks of its
// communication unit (ProcessorSetup::order_after): whether an arrival is still due, and to be
// run once the unit's delivery round is over.
#pragma once

#include "activation_queue.h"

namespace torusrt {

class DeliveryRoundIf {
  public:
    // Whether an arrival due by now still waits for its delivery (in this delta or the next).
    virtual bool arrival_due() const = 0;
    // Within a delivery round: runs `client` once the round is over and returns true; else false.
    virtual bool run_after_delivery(ActivationQueue::Client &client) = 0;

  protected:
    ~DeliveryRoundIf() = default;
};

}  // namespace torusrt
