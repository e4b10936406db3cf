#include "editor/brain/BrainMacro.h"

#include "editor/brain/FuzzCurve.h"

#include <glm/common.hpp>

#include <algorithm>
#include <map>
#include <set>

namespace throng::editor {

using sim::BrainGraph;
using sim::BrainLink;
using sim::BrainNode;
using sim::NodeId;

namespace {

NodeId maxId(const BrainGraph& g)
{
    NodeId id = 0;
    for (const BrainNode& n : g.nodes)
        id = std::max(id, n.id);
    return id;
}

BrainNode portNode(NodeId id, const char* type, std::uint32_t port, glm::vec2 pos)
{
    BrainNode n;
    n.id = id;
    n.type = type;
    n.position = pos;
    n.params.push_back({"port", {}, {float(port)}});
    return n;
}

}  // namespace

std::optional<MacroCollapse> collapseToMacro(const BrainGraph& graph, const std::vector<NodeId>& nodes,
                                             const std::string& name, std::string* problem)
{
    const std::set<NodeId> sel(nodes.begin(), nodes.end());
    if (sel.empty()) {
        if (problem)
            *problem = "select the nodes to collapse first";
        return std::nullopt;
    }
    MacroCollapse out;
    out.inner.name = name;
    glm::vec2 lo(1e30f), hi(-1e30f);
    for (const BrainNode& n : graph.nodes) {
        if (sel.count(n.id)) {
            out.inner.nodes.push_back(n);
            lo = glm::min(lo, n.position);
            hi = glm::max(hi, n.position);
        } else {
            out.outer.nodes.push_back(n);
        }
    }
    out.outer.name = graph.name;
    out.outer.file = graph.file;
    NodeId innerNext = maxId(out.inner) + 1;
    out.macroNode = maxId(graph) + 1;
    std::uint32_t inPorts = 0;
    std::map<std::pair<NodeId, std::uint32_t>, std::uint32_t> outPorts;  // inner source -> macro output
    std::vector<BrainLink> outerLinks;
    for (const BrainLink& l : graph.links) {
        const bool from = sel.count(l.fromNode) > 0, to = sel.count(l.toNode) > 0;
        if (from && to) {
            out.inner.links.push_back(l);
        } else if (!from && to) {
            const std::uint32_t port = inPorts++;
            out.inner.nodes.push_back(portNode(innerNext, "macro.in", port, {lo.x - 260.0f, lo.y + 120.0f * float(port)}));
            out.inner.links.push_back({innerNext++, 0, l.toNode, l.toPort});
            outerLinks.push_back({l.fromNode, l.fromPort, out.macroNode, port});
        } else if (from && !to) {
            auto [it, added] = outPorts.try_emplace({l.fromNode, l.fromPort}, std::uint32_t(outPorts.size()));
            if (added) {
                out.inner.nodes.push_back(
                    portNode(innerNext, "macro.out", it->second, {hi.x + 260.0f, lo.y + 120.0f * float(it->second)}));
                out.inner.links.push_back({l.fromNode, l.fromPort, innerNext++, 0});
            }
            outerLinks.push_back({out.macroNode, it->second, l.toNode, l.toPort});
        } else {
            outerLinks.push_back(l);
        }
    }
    BrainNode macro;
    macro.id = out.macroNode;
    macro.type = "macro";
    macro.label = name;
    macro.position = (lo + hi) * 0.5f;
    macro.params.push_back({"brain", name, {}});
    out.outer.nodes.push_back(macro);
    out.outer.links = outerLinks;
    return out;
}

std::optional<BrainGraph> expandMacro(const BrainGraph& graph, NodeId macroNode, const std::vector<BrainGraph>& library,
                                      std::string* problem)
{
    const BrainNode* macro = graph.findNode(macroNode);
    const BrainGraph* inner = nullptr;
    if (macro && macro->type == "macro")
        for (const sim::BrainParam& p : macro->params)
            if (p.key == "brain")
                for (const BrainGraph& b : library)
                    if (b.name == p.text)
                        inner = &b;
    if (!inner) {
        if (problem)
            *problem = "select one macro node whose brain exists";
        return std::nullopt;
    }
    BrainGraph out = graph;
    std::erase_if(out.nodes, [&](const BrainNode& n) { return n.id == macroNode; });
    std::map<NodeId, NodeId> ids;
    std::map<NodeId, std::uint32_t> ins, outs;  // inner macro.in / macro.out node -> port
    NodeId next = maxId(graph) + 1;
    glm::vec2 lo(1e30f);
    for (const BrainNode& n : inner->nodes)
        lo = glm::min(lo, n.position);
    for (const BrainNode& n : inner->nodes) {
        const std::vector<float> port = paramNumbers(n.params, "port");
        if (n.type == "macro.in" || n.type == "macro.out") {
            (n.type == "macro.in" ? ins : outs)[n.id] = port.empty() ? 0u : std::uint32_t(port[0]);
            continue;
        }
        BrainNode copy = n;
        copy.id = ids[n.id] = next++;
        copy.position = macro->position + (n.position - lo);
        out.nodes.push_back(copy);
    }
    std::vector<BrainLink> links;
    for (const BrainLink& l : graph.links) {
        if (l.toNode == macroNode) {
            for (const BrainLink& il : inner->links)
                if (ins.count(il.fromNode) && ins[il.fromNode] == l.toPort && ids.count(il.toNode))
                    links.push_back({l.fromNode, l.fromPort, ids[il.toNode], il.toPort});
        } else if (l.fromNode == macroNode) {
            for (const BrainLink& il : inner->links)
                if (outs.count(il.toNode) && outs[il.toNode] == l.fromPort && ids.count(il.fromNode))
                    links.push_back({ids[il.fromNode], il.fromPort, l.toNode, l.toPort});
        } else {
            links.push_back(l);
        }
    }
    for (const BrainLink& il : inner->links)
        if (ids.count(il.fromNode) && ids.count(il.toNode))
            links.push_back({ids[il.fromNode], il.fromPort, ids[il.toNode], il.toPort});
    out.links = links;
    return out;
}

}  // namespace throng::editor
