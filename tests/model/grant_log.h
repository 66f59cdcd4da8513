// The grants of a cluster bus, in grant order, as its observer hears them.
#pragma once

#include <vector>

#include "cluster_bus.h"

namespace torusrt {

struct GrantLog final : ClusterBus::GrantObserver {
    std::vector<ClusterBus::Grant> grants;
    void granted(const ClusterBus::Grant &grant) override { grants.push_back(grant); }
};

}  // namespace torusrt
