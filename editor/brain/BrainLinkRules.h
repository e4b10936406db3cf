#pragma once
// What the brain editor may draw and connect, read from the node catalogue: how many
// ports a node shows, which kind of value each output carries, and why a link would be
// refused (type mismatch, occupied input, loop without a memory node). Never edits a graph.

#include "simcore/brain/NodeCatalogue.h"
#include "simcore/scene/BrainGraph.h"

#include <string>
#include <vector>

namespace throng::editor {

// Input ports a node shows: a repeating input shows one free port after the connected ones.
int inputPortCount(const sim::BrainGraph& graph, const sim::BrainNode& node);
// A macro node has one output per macro.out of the brain it names in `library`.
int outputPortCount(const sim::BrainGraph& graph, const sim::BrainNode& node,
                    const std::vector<sim::BrainGraph>* library = nullptr);
// The spec of port `port` (the repeating one for ports past the list); null when the
// node has no such ports at all.
const sim::PortSpec* inputPortSpec(const sim::NodeSpec& spec, int port);
const sim::PortSpec* outputPortSpec(const sim::NodeSpec& spec, int port);
// What an output carries once the graph is wired: Scalar or PerNeighbour (never Any).
sim::PortKind outputKind(const sim::BrainGraph& graph, sim::NodeId node, int port);
// Why `link` may not be added to `graph`; empty when it may.
std::string linkProblem(const sim::BrainGraph& graph, const sim::BrainLink& link,
                        const std::vector<sim::BrainGraph>* library = nullptr);
// Node types with an input that accepts `kind` (dropping an output's link on empty
// space), or with an output an input of kind `kind` accepts (fromInput).
std::vector<std::string> compatibleNodeTypes(sim::PortKind kind, bool fromInput);
// The parameters a new node of `type` starts with: every required one, with a usable value.
std::vector<sim::BrainParam> defaultParams(const sim::NodeSpec& spec);

}  // namespace throng::editor
