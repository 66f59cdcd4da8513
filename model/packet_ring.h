// packet_ring.h - the FIFO store under a packet queue: a circular buffer that grows by doubling
// and never shrinks. A std::deque of 192-byte packets holds two per 512-byte block, so it
// allocates and frees a block every other packet; queues here run thousands deep and turn over
// millions of times, so the ring keeps its storage instead. Elements keep their order through
// erase(), which moves the shorter side of the gap, as a deque does.
#pragma once

#include <cstddef>
#include <memory>
#include <utility>

namespace torusrt {

template <class T> class PacketRing {
  public:
    bool empty() const { return m_size == 0; }
    size_t size() const { return m_size; }
    T &operator[](size_t i) { return m_slots[(m_head + i) & m_mask]; }
    const T &operator[](size_t i) const { return m_slots[(m_head + i) & m_mask]; }
    T &front() { return (*this)[0]; }
    const T &front() const { return (*this)[0]; }
    T &back() { return (*this)[m_size - 1]; }

    void push_back(const T &item)
    {
        if (m_size == m_capacity) grow();
        (*this)[m_size] = item;
        m_size++;
    }
    void pop_front()
    {
        m_head = (m_head + 1) & m_mask;
        m_size--;
    }
    // Removes element `index`; the others keep their order.
    void erase(size_t index)
    {
        if (index < m_size - 1 - index) { // fewer before it: shift those one place back
            for (size_t i = index; i > 0; i--) (*this)[i] = std::move((*this)[i - 1]);
            pop_front();
        } else {
            for (size_t i = index; i + 1 < m_size; i++) (*this)[i] = std::move((*this)[i + 1]);
            m_size--;
        }
    }

  private:
    void grow()
    {
        size_t capacity = m_capacity ? 2 * m_capacity : 8;
        std::unique_ptr<T[]> slots(new T[capacity]);
        for (size_t i = 0; i < m_size; i++) slots[i] = std::move((*this)[i]);
        m_slots = std::move(slots);
        m_capacity = capacity;
        m_mask = capacity - 1;
        m_head = 0;
    }

    std::unique_ptr<T[]> m_slots;
    size_t m_capacity = 0, m_mask = 0, m_head = 0, m_size = 0;
};

}  // namespace torusrt
