#pragma once
// A brain as plain data: nodes with integer ids, typed by name, with parameters, and
// links {fromNode, fromPort, toNode, toPort}. Knows nothing of how a brain is evaluated.

#include <glm/vec2.hpp>

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace throng::sim {

using NodeId = std::uint32_t;

struct BrainParam {
    std::string key;
    std::string text;            // a string parameter (sensor name, mode, ...)
    std::vector<float> numbers;  // a number or a list of numbers; used when text is empty
    bool operator==(const BrainParam&) const = default;
};

struct BrainNode {
    NodeId id = 0;
    std::string type;  // node type, e.g. "input", "fuzz.triangle", "rule.and", "output"
    std::string label;
    glm::vec2 position{0.0f};  // editor canvas position
    std::vector<BrainParam> params;
    bool operator==(const BrainNode&) const = default;
};

struct BrainLink {
    NodeId fromNode = 0;
    std::uint32_t fromPort = 0;
    NodeId toNode = 0;
    std::uint32_t toPort = 0;
    bool operator==(const BrainLink&) const = default;
};

// Where a node or link was written (1-based), when the graph came from a file.
struct BrainSourcePos {
    int line = 0;    // 0 = unknown
    int column = 0;
};

// Source positions of a graph read from YAML, for compiler messages (file:line:col).
// Not part of the graph's content: graphs that differ only here compare equal. Editing
// a graph leaves positions stale; an editor should clear them.
struct BrainSourceMap {
    std::string file;  // the file the positions refer to (a scene or a .brain.yaml)
    std::vector<std::pair<NodeId, BrainSourcePos>> nodes;  // in file order
    std::vector<BrainSourcePos> links;                     // parallel to BrainGraph::links
    bool operator==(const BrainSourceMap&) const { return true; }

    BrainSourcePos node(NodeId id) const
    {
        for (const auto& [n, pos] : nodes)
            if (n == id)
                return pos;
        return {};
    }
    BrainSourcePos link(std::size_t index) const { return index < links.size() ? links[index] : BrainSourcePos{}; }
};

struct BrainGraph {
    std::string name;
    std::string file;  // when set, the graph was loaded from this .brain.yaml and is saved there
    std::vector<BrainNode> nodes;
    std::vector<BrainLink> links;
    BrainSourceMap source;  // filled by the reader; ignored by operator==
    bool operator==(const BrainGraph&) const = default;

    const BrainNode* findNode(NodeId id) const;
};

}  // namespace throng::sim
