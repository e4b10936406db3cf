#pragma once
// The compiler's working form of a brain: macros expanded into one flat list of nodes,
// each input resolved to the node and port it reads. Private to simcore/brain.
#ifndef THRONG_SIMCORE_BUILD
#error "a detail/ header, private to throng::simcore: include the module's public headers instead"
#endif

#include "simcore/brain/BrainCompiler.h"
#include "simcore/brain/NodeCatalogue.h"

#include <string>
#include <utility>
#include <vector>

namespace throng::sim::detail {

struct FlatSource {
    int node = -1;  // flat index, -1 = not connected
    std::uint32_t port = 0;
};

struct FlatNode {
    const BrainNode* node = nullptr;
    const NodeSpec* spec = nullptr;
    NodeId origin = 0;      // the top-level node errors name (the macro node for expanded ones)
    std::string where;      // "" at top level, else "in macro 'x': "
    std::vector<FlatSource> inputs;  // by input port
    bool pass = false;      // macro.in / macro.out: its output is its input 0
    bool inert = false;     // computes nothing: macro nodes (expanded), notes, bad nodes
    bool badParams = false;
    int filterSet = -1;  // a filter node: the item set of its input
    bool fedByUnknown = false;  // a link from a node of unknown type was dropped
    std::vector<std::pair<std::uint32_t, int>> macroOutputs;  // a macro node: port -> its macro.out node
};

// Collects errors, located through the top-level graph's source map.
class BrainErrorList {
public:
    explicit BrainErrorList(const BrainGraph& top) : m_top(top) {}
    void node(NodeId id, const std::string& message);
    void link(std::size_t index, const std::string& message);
    // "node 4 (rule.and): " or "node 7 (macro): in macro 'x': node 2 (fuzz.triangle): "
    static std::string nodeName(const FlatNode& n);
    void at(const FlatNode& n, const std::string& message) { node(n.origin, nodeName(n) + message); }
    std::vector<BrainError>& errors() { return m_errors; }

private:
    const BrainGraph& m_top;
    std::vector<BrainError> m_errors;
};

// Parameters with the catalogue's defaults filled in.
float numberParam(const FlatNode& n, const std::string& key);
const std::vector<float>* numbersParam(const FlatNode& n, const std::string& key);
std::string textParam(const FlatNode& n, const std::string& key);
// Whitespace-separated words of a text parameter.
std::vector<std::string> words(const std::string& text);

// Expands macros and resolves links of `top`; reports structural and parameter errors.
std::vector<FlatNode> flattenBrain(const BrainGraph& top, const std::vector<BrainGraph>& library,
                                   BrainErrorList& errors);
// Checks one node's parameters against its spec and its own rules.
void checkNodeParams(FlatNode& n, BrainErrorList& errors);
// Orders, types and emits the program; null when errors were found.
std::shared_ptr<BrainProgram> emitBrain(std::vector<FlatNode>& nodes, const std::string& name, BrainErrorList& errors);

}  // namespace throng::sim::detail
