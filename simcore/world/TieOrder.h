#pragma once
// How the neighbour searches order candidates at exactly the same distance: by agent id,
// never by where the World happens to store an agent. An agent's rank is its place among
// the World's agents by id. Where ids rise with the index, as the World builds most
// scenes, the rank is the index itself and nothing is kept or looked up. Where they do
// not (a scene stored in the grid's order, GridOrder.h, or ids given out of order), the
// ranks are kept here, and a search that meets two candidates at the same distance
// searches again with the ranks in its keys (NearestList.h). So a crowd stored in any
// order makes the same choices, bit for bit: in a lattice, where a bird's neighbours lie
// at equal distances, which of them it keeps among its k nearest and the order it sums
// them in would otherwise follow the storage order.

#include "simcore/world/FrameCache.h"

#include <cstdint>
#include <span>
#include <vector>

namespace throng::sim {

class TieOrder {
public:
    // From the World's agents (their ids are unique).
    void build(std::span<const AgentInfo> agents);

    // Agent j's rank (the low word of its key in a search by rank), and back to its index.
    std::uint32_t rank(std::uint32_t j) const { return m_rank.empty() ? j : m_rank[j]; }
    std::uint32_t index(std::uint32_t rank) const { return m_index.empty() ? rank : m_index[rank]; }
    // Whether ranks are the indices (ids rise with the index).
    bool byIndex() const { return m_rank.empty(); }

private:
    std::vector<std::uint32_t> m_rank, m_index;  // empty when ids rise with the index
};

}  // namespace throng::sim
