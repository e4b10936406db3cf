#pragma once
// A brain as plain data: nodes with integer ids, typed by name, with parameters, and
// links {fromNode, fromPort, toNode, toPort}. Knows nothing of how a brain is evaluated.

#include <glm/vec2.hpp>

#include <cstdint>
#include <string>
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

struct BrainGraph {
    std::string name;
    std::string file;  // when set, the graph was loaded from this .brain.yaml and is saved there
    std::vector<BrainNode> nodes;
    std::vector<BrainLink> links;
    bool operator==(const BrainGraph&) const = default;

    const BrainNode* findNode(NodeId id) const;
};

}  // namespace throng::sim
