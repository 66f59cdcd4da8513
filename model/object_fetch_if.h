// object_fetch_if.h - how a processor in a cluster with shared object data reads an object held
// in another processor's 2-port memory (over the cluster bus). Unbound in flat and replicated
// systems, where every object a processor tests is in its own memory.
#pragma once

#include <cstdint>
#include <systemc>

#include "time_keeper.h"

namespace torusrt {

class ObjectFetchIf : public virtual sc_core::sc_interface {
  public:
    // Makes `object` available to processor `reader`, spending bus and memory time through `time`.
    virtual void fetch(int reader, uint32_t object, TimeKeeper &time) = 0;
};

}  // namespace torusrt
