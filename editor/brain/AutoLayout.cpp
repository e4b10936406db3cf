#include "editor/brain/AutoLayout.h"

#include "simcore/brain/NodeCatalogue.h"

#include <algorithm>
#include <map>
#include <vector>

namespace throng::editor {

namespace {
constexpr float kColumnGap = 260.0f;
constexpr float kRowGap = 150.0f;
}

bool needsLayout(const sim::BrainGraph& graph)
{
    for (const sim::BrainNode& n : graph.nodes)
        if (n.position != graph.nodes.front().position)
            return false;
    return graph.nodes.size() > 1;
}

void autoLayout(sim::BrainGraph& graph)
{
    std::map<sim::NodeId, int> column;
    std::map<sim::NodeId, bool> memory;
    for (const sim::BrainNode& n : graph.nodes) {
        column[n.id] = 0;
        const sim::NodeSpec* spec = sim::findNodeSpec(n.type);
        memory[n.id] = spec && spec->breaksCycles;
    }
    // Longest path by relaxation: at most one pass per node, since loops only close
    // through memory nodes (whose incoming links are skipped).
    for (std::size_t pass = 0; pass < graph.nodes.size(); ++pass) {
        bool changed = false;
        for (const sim::BrainLink& l : graph.links) {
            if (memory[l.toNode] || !column.count(l.fromNode) || !column.count(l.toNode))
                continue;
            if (column[l.toNode] < column[l.fromNode] + 1 && column[l.fromNode] + 1 <= int(graph.nodes.size())) {
                column[l.toNode] = column[l.fromNode] + 1;
                changed = true;
            }
        }
        if (!changed)
            break;
    }
    std::map<int, std::vector<sim::NodeId>> columns;
    for (const sim::BrainNode& n : graph.nodes)
        columns[column[n.id]].push_back(n.id);
    std::map<sim::NodeId, float> row;
    for (auto& [c, ids] : columns) {
        std::map<sim::NodeId, float> key;
        for (std::size_t i = 0; i < ids.size(); ++i) {
            float sum = 0.0f;
            int count = 0;
            for (const sim::BrainLink& l : graph.links)
                if (l.toNode == ids[i] && row.count(l.fromNode)) {
                    sum += row[l.fromNode];
                    ++count;
                }
            key[ids[i]] = count > 0 ? sum / float(count) : float(i);
        }
        std::stable_sort(ids.begin(), ids.end(), [&](sim::NodeId a, sim::NodeId b) { return key[a] < key[b]; });
        for (std::size_t i = 0; i < ids.size(); ++i)
            row[ids[i]] = float(i);
    }
    for (sim::BrainNode& n : graph.nodes)
        n.position = {float(column[n.id]) * kColumnGap, row[n.id] * kRowGap};
}

}  // namespace throng::editor
