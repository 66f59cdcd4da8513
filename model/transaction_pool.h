// transaction_pool.h - the transactions packets cross links in: a TLM-2.0 memory manager
// (tlm_mm_interface). A crossing takes a transaction, sets it up, acquires it for its
// b_transport and releases it when that returns; the last release gives it back. b_transport
// returns before the next crossing starts, so one transaction serves every link of a machine
// and stays in the cache, where one per link would be thousands of cold lines at 512 nodes. A
// second one is made only if a crossing starts while one is in use.
#pragma once

#include <memory>
#include <tlm>
#include <vector>

#include "timed_packet.h"

namespace torusrt {

class TransactionPool : public tlm::tlm_mm_interface {
  public:
    struct Crossing {
        tlm::tlm_generic_payload *trans;
        PacketExtension *ext;
    };
    TransactionPool() = default;
    TransactionPool(const TransactionPool &) = delete;
    TransactionPool &operator=(const TransactionPool &) = delete;

    // A free transaction with its packet extension, not yet acquired: a write of one packet.
    Crossing take()
    {
        if (m_free.empty()) make();
        Crossing c = m_free.back();
        m_free.pop_back();
        return c;
    }
    // The last release of a transaction taken from this pool (tlm_generic_payload::release).
    void free(tlm::tlm_generic_payload *trans) override
    {
        m_free.push_back({trans, trans->get_extension<PacketExtension>()});
    }

  private:
    void make()
    {
        auto trans = std::make_unique<tlm::tlm_generic_payload>(this);
        auto *ext = new PacketExtension;  // owned by the transaction
        trans->set_extension(ext);
        trans->set_command(tlm::TLM_WRITE_COMMAND);
        trans->set_data_length(sizeof(rt_packet));
        trans->set_streaming_width(sizeof(rt_packet));
        m_free.push_back({trans.get(), ext});
        m_made.push_back(std::move(trans));
    }

    std::vector<Crossing> m_free;
    std::vector<std::unique_ptr<tlm::tlm_generic_payload>> m_made;
};

}  // namespace torusrt
