#include "editor/brain/BrainLinkRules.h"

#include <algorithm>
#include <set>

namespace throng::editor {

using sim::BrainGraph;
using sim::BrainLink;
using sim::BrainNode;
using sim::NodeId;
using sim::NodeSpec;
using sim::PortKind;
using sim::PortSpec;

namespace {

int connectedInputs(const BrainGraph& graph, NodeId id)
{
    int highest = -1;
    for (const BrainLink& l : graph.links)
        if (l.toNode == id)
            highest = std::max(highest, int(l.toPort));
    return highest + 1;
}

PortKind outputKindRec(const BrainGraph& graph, NodeId id, int port, std::set<NodeId>& seen)
{
    const BrainNode* node = graph.findNode(id);
    const NodeSpec* spec = node ? sim::findNodeSpec(node->type) : nullptr;
    if (!spec)
        return PortKind::Scalar;
    if (node->type == "input") {
        for (const sim::BrainParam& p : node->params)
            if (p.key == "sensor")
                if (const sim::SensorSpec* s = sim::findSensorSpec(p.text))
                    return s->perNeighbour ? PortKind::PerNeighbour : PortKind::Scalar;
        return PortKind::Scalar;
    }
    const PortSpec* out = outputPortSpec(*spec, port);
    if (!out || out->kind != PortKind::Any)
        return out ? out->kind : PortKind::Scalar;
    if (!seen.insert(id).second || spec->breaksCycles)
        return PortKind::Scalar;
    for (const BrainLink& l : graph.links)
        if (l.toNode == id && outputKindRec(graph, l.fromNode, int(l.fromPort), seen) == PortKind::PerNeighbour)
            return PortKind::PerNeighbour;
    return PortKind::Scalar;
}

bool breaksCycles(const BrainGraph& graph, NodeId id)
{
    const BrainNode* node = graph.findNode(id);
    const NodeSpec* spec = node ? sim::findNodeSpec(node->type) : nullptr;
    return spec && spec->breaksCycles;
}

// True when `to` reaches `from` along links without passing through a memory node.
bool reachesWithoutMemory(const BrainGraph& graph, NodeId to, NodeId from)
{
    std::vector<NodeId> stack{to};
    std::set<NodeId> seen{to};
    while (!stack.empty()) {
        const NodeId n = stack.back();
        stack.pop_back();
        if (n == from)
            return true;
        if (breaksCycles(graph, n))
            continue;
        for (const BrainLink& l : graph.links)
            if (l.fromNode == n && seen.insert(l.toNode).second)
                stack.push_back(l.toNode);
    }
    return false;
}

}  // namespace

const PortSpec* inputPortSpec(const NodeSpec& spec, int port)
{
    if (port < 0 || spec.inputs.empty())
        return nullptr;
    if (std::size_t(port) < spec.inputs.size())
        return &spec.inputs[std::size_t(port)];
    return spec.variadic ? &spec.inputs.back() : nullptr;
}

const PortSpec* outputPortSpec(const NodeSpec& spec, int port)
{
    if (port < 0 || spec.outputs.empty())
        return nullptr;
    if (std::size_t(port) < spec.outputs.size())
        return &spec.outputs[std::size_t(port)];
    return &spec.outputs.back();  // rule.priority and macro nodes repeat their output
}

int inputPortCount(const BrainGraph& graph, const BrainNode& node)
{
    const NodeSpec* spec = sim::findNodeSpec(node.type);
    if (!spec)
        return connectedInputs(graph, node.id);
    if (!spec->variadic)
        return int(spec->inputs.size());
    const int fixed = int(spec->inputs.size()) - 1;
    return std::max({int(spec->inputs.size()), connectedInputs(graph, node.id) + 1, fixed + spec->minInputs});
}

int outputPortCount(const BrainGraph& graph, const BrainNode& node, const std::vector<BrainGraph>* library)
{
    const NodeSpec* spec = sim::findNodeSpec(node.type);
    if (!spec)
        return 1;
    if (node.type == "macro" && library) {
        int ports = 1;
        for (const sim::BrainParam& p : node.params)
            for (const BrainGraph& b : *library)
                if (p.key == "brain" && b.name == p.text)
                    for (const BrainNode& n : b.nodes)
                        for (const sim::BrainParam& q : n.params)
                            if (n.type == "macro.out" && q.key == "port" && !q.numbers.empty())
                                ports = std::max(ports, int(q.numbers[0]) + 1);
        return ports;
    }
    if (spec->outputPerInput)
        return std::max(1, connectedInputs(graph, node.id));
    return int(spec->outputs.size());
}

PortKind outputKind(const BrainGraph& graph, NodeId node, int port)
{
    std::set<NodeId> seen;
    return outputKindRec(graph, node, port, seen);
}

std::string linkProblem(const BrainGraph& graph, const BrainLink& link, const std::vector<BrainGraph>* library)
{
    const BrainNode* from = graph.findNode(link.fromNode);
    const BrainNode* to = graph.findNode(link.toNode);
    if (!from || !to)
        return "the link names a node the brain does not have";
    const NodeSpec* toSpec = sim::findNodeSpec(to->type);
    if (int(link.fromPort) >= outputPortCount(graph, *from, library))
        return "node " + std::to_string(from->id) + " has no output " + std::to_string(link.fromPort);
    if (int(link.toPort) >= inputPortCount(graph, *to) || !toSpec)
        return "node " + std::to_string(to->id) + " has no input " + std::to_string(link.toPort);
    const PortSpec* in = inputPortSpec(*toSpec, int(link.toPort));
    for (const BrainLink& l : graph.links)
        if (l.toNode == link.toNode && l.toPort == link.toPort)
            return "input '" + in->name + "' of node " + std::to_string(to->id) + " is already connected";
    if (in->kind == PortKind::Scalar && outputKind(graph, link.fromNode, int(link.fromPort)) == PortKind::PerNeighbour)
        return "type mismatch: a per-neighbour value cannot feed the per-agent input '" + in->name + "' of " +
               to->type + " (put a filter node between them)";
    const bool memory = breaksCycles(graph, link.fromNode) || breaksCycles(graph, link.toNode);
    if (!memory && (link.fromNode == link.toNode || reachesWithoutMemory(graph, link.toNode, link.fromNode)))
        return "this link would close a loop without a state.memory node";
    return {};
}

std::vector<std::string> compatibleNodeTypes(PortKind kind, bool fromInput)
{
    std::vector<std::string> out;
    for (const NodeSpec& spec : sim::nodeCatalogue()) {
        bool ok = false;
        if (!fromInput) {
            for (const PortSpec& p : spec.inputs)
                ok = ok || kind != PortKind::PerNeighbour || p.kind != PortKind::Scalar;
        } else {
            for (const PortSpec& p : spec.outputs)
                ok = ok || kind != PortKind::Scalar || p.kind != PortKind::PerNeighbour || spec.type == "input";
        }
        if (ok)
            out.push_back(spec.type);
    }
    return out;
}

std::vector<sim::BrainParam> defaultParams(const NodeSpec& spec)
{
    std::vector<sim::BrainParam> params;
    for (const sim::ParamSpec& p : spec.params) {
        if (!p.required)
            continue;
        sim::BrainParam bp{p.key, {}, {}};
        switch (p.type) {
        case sim::ParamType::Number:
            bp.numbers = {std::clamp(p.defaultValue, p.min, p.max)};
            break;
        case sim::ParamType::Numbers:
            for (std::size_t i = 0; i < std::max<std::size_t>(p.count, 1); ++i)
                bp.numbers.push_back(float(i) / float(std::max<std::size_t>(p.count, 2) - 1));
            break;
        case sim::ParamType::Choice:
            bp.text = p.choices.empty() ? std::string() : p.choices.front();
            break;
        case sim::ParamType::Text:
            bp.text = spec.type == "input" ? "speed" : "name";
            break;
        }
        params.push_back(std::move(bp));
    }
    return params;
}

}  // namespace throng::editor
