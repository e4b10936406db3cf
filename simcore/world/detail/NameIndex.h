#pragma once
// Name -> index lookups of a scene's items for building a World (World.cpp, WorldStarts.cpp).
#ifndef THRONG_SIMCORE_BUILD
#error "a detail/ header, private to throng::simcore: include the module's public headers instead"
#endif

#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace throng::sim::detail {

// Name -> index for one kind of scene item, built once so that resolving a million
// agents' references costs O(N log K), not O(N K).
class NameIndex {
public:
    template <typename T>
    explicit NameIndex(const std::vector<T>& items)
    {
        for (std::size_t k = 0; k < items.size(); ++k)
            m_index.emplace(items[k].name, int(k));
    }
    int operator()(const std::string& name) const
    {
        if (name.empty())
            return -1;
        const auto it = m_index.find(name);
        return it == m_index.end() ? -1 : it->second;
    }

private:
    std::map<std::string, int> m_index;
};

}  // namespace throng::sim::detail
