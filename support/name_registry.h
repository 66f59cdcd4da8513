// name_registry.h - policies registered by name, in the order the help lists them: the names an
// option accepts are the entries, and a new policy is one entry (Noxim's routing register,
// pbrt's Create(name, ...)).
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace torusrt {

template <class Factory> class NameRegistry {
  public:
    NameRegistry(std::initializer_list<std::pair<std::string, Factory>> entries) : m_entries(entries) {}

    // The factory registered as `name`, or null.
    const Factory *find(const std::string &name) const
    {
        for (const auto &e : m_entries)
            if (e.first == name) return &e.second;
        return nullptr;
    }
    std::vector<std::string> names() const
    {
        std::vector<std::string> out;
        for (const auto &e : m_entries) out.push_back(e.first);
        return out;
    }

  private:
    std::vector<std::pair<std::string, Factory>> m_entries;
};

}  // namespace torusrt
