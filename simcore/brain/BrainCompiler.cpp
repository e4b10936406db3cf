#include "simcore/brain/BrainCompiler.h"

#include "simcore/brain/detail/BrainFlatGraph.h"

#include <map>
#include <sstream>

namespace throng::sim {

std::string BrainError::format() const
{
    if (file.empty())
        return message;
    std::string s = file;
    if (line > 0) {
        s.push_back(':');
        s.append(std::to_string(line));
        if (column > 0) {
            s.push_back(':');
            s.append(std::to_string(column));
        }
    }
    s.append(": error: ");
    s.append(message);
    return s;
}

namespace detail {

void BrainErrorList::node(NodeId id, const std::string& message)
{
    BrainError e;
    e.node = id;
    e.file = m_top.source.file;
    const BrainSourcePos pos = m_top.source.node(id);
    e.line = pos.line;
    e.column = pos.column;
    e.message = message;
    m_errors.push_back(std::move(e));
}

void BrainErrorList::link(std::size_t index, const std::string& message)
{
    BrainError e;
    e.link = int(index);
    if (index < m_top.links.size())
        e.node = m_top.links[index].toNode;
    e.file = m_top.source.file;
    const BrainSourcePos pos = m_top.source.link(index);
    e.line = pos.line;
    e.column = pos.column;
    e.message = "link " + std::to_string(index) + ": " + message;
    m_errors.push_back(std::move(e));
}

std::string BrainErrorList::nodeName(const FlatNode& n)
{
    std::string s = n.where.empty() ? std::string() : "node " + std::to_string(n.origin) + " (macro): " + n.where;
    return s + "node " + std::to_string(n.node->id) + " (" + n.node->type + "): ";
}

namespace {

const BrainParam* findParam(const BrainNode& n, const std::string& key)
{
    for (const BrainParam& p : n.params)
        if (p.key == key)
            return &p;
    return nullptr;
}

const ParamSpec* findParamSpec(const NodeSpec& s, const std::string& key)
{
    for (const ParamSpec& p : s.params)
        if (p.key == key)
            return &p;
    return nullptr;
}

// Expands one graph into `out`; macro nodes recurse into the brain they name.
class Flattener {
public:
    Flattener(const std::vector<BrainGraph>& library, BrainErrorList& errors, std::vector<FlatNode>& out)
        : m_library(library), m_errors(errors), m_out(out) {}

    struct MacroPorts {
        std::map<std::uint32_t, std::vector<int>> ins;  // port -> macro.in nodes
        std::map<std::uint32_t, int> outs;              // port -> macro.out node
    };

    MacroPorts flatten(const BrainGraph& g, NodeId origin, const std::string& where)
    {
        const bool top = where.empty();
        MacroPorts ports;
        std::map<NodeId, int> index;
        std::map<int, MacroPorts> macros;
        for (const BrainNode& bn : g.nodes) {
            const int i = int(m_out.size());
            index[bn.id] = i;
            FlatNode n;
            n.node = &bn;
            n.spec = findNodeSpec(bn.type);
            n.origin = top ? bn.id : origin;
            n.where = where;
            m_out.push_back(n);
            FlatNode& f = m_out.back();
            if (!f.spec) {
                m_errors.at(f, "unknown node type '" + bn.type + "'");
                f.inert = true;
                continue;
            }
            checkNodeParams(f, m_errors);
            if (bn.type == "note")
                m_out[std::size_t(i)].inert = true;
            else if (bn.type == "macro.in" || bn.type == "macro.out") {
                FlatNode& m = m_out[std::size_t(i)];
                m.pass = true;
                m.inputs.resize(1);
                const auto port = std::uint32_t(numberParam(m, "port"));
                if (bn.type == "macro.in")
                    ports.ins[port].push_back(i);
                else if (!ports.outs.emplace(port, i).second)
                    m_errors.at(m, "macro output port " + std::to_string(port) + " is defined twice");
            } else if (bn.type == "macro" && !m_out[std::size_t(i)].badParams) {
                m_out[std::size_t(i)].inert = true;
                macros[i] = expand(i, top ? bn.id : origin, where);
                for (const auto& [port, node] : macros[i].outs)
                    m_out[std::size_t(i)].macroOutputs.emplace_back(port, node);
            }
        }
        for (std::size_t li = 0; li < g.links.size(); ++li)
            connect(g, li, index, macros, top, origin, where);
        return ports;
    }

private:
    MacroPorts expand(int i, NodeId origin, const std::string& where)
    {
        const std::string name = textParam(m_out[std::size_t(i)], "brain");
        const BrainGraph* inner = nullptr;
        for (const BrainGraph& b : m_library)
            if (b.name == name)
                inner = &b;
        if (!inner) {
            m_errors.at(m_out[std::size_t(i)], "no brain named '" + name + "' for this macro");
            return {};
        }
        for (const std::string& s : m_stack)
            if (s == name) {
                m_errors.at(m_out[std::size_t(i)], "macro '" + name + "' uses itself");
                return {};
            }
        // A chain is legal however it nests; these bounds keep a macro used twice at each of
        // many levels (2^depth nodes) from exhausting memory instead of being reported.
        if (m_stack.size() >= kMaxMacroDepth) {
            m_errors.at(m_out[std::size_t(i)], "macro '" + name + "' nests macros more than " +
                                                   std::to_string(kMaxMacroDepth) + " deep");
            return {};
        }
        if (m_overflow)
            return {};  // reported once, at the first macro past the limit
        if (m_out.size() + inner->nodes.size() > kMaxExpandedNodes) {
            m_errors.at(m_out[std::size_t(i)], "macro '" + name + "' expands the brain past " +
                                                   std::to_string(kMaxExpandedNodes) + " nodes");
            m_overflow = true;
            return {};
        }
        m_stack.push_back(name);
        MacroPorts p = flatten(*inner, origin, where + "in macro '" + name + "': ");
        m_stack.pop_back();
        return p;
    }

    void linkError(bool top, std::size_t li, NodeId origin, const std::string& where, const std::string& message)
    {
        if (top)
            m_errors.link(li, message);
        else
            m_errors.node(origin, "node " + std::to_string(origin) + " (macro): " + where + "link " +
                                      std::to_string(li) + ": " + message);
    }

    void connect(const BrainGraph& g, std::size_t li, const std::map<NodeId, int>& index,
                 const std::map<int, MacroPorts>& macros, bool top, NodeId origin, const std::string& where)
    {
        const BrainLink& l = g.links[li];
        const auto from = index.find(l.fromNode), to = index.find(l.toNode);
        if (from == index.end() || to == index.end()) {
            linkError(top, li, origin, where,
                      "no node with id " + std::to_string(from == index.end() ? l.fromNode : l.toNode));
            return;
        }
        const FlatNode& fn = m_out[std::size_t(from->second)];
        FlatNode& tn = m_out[std::size_t(to->second)];
        if (!fn.spec)
            tn.fedByUnknown = true;  // its free input is a consequence, not news
        if (!fn.spec || !tn.spec)
            return;  // already reported
        FlatSource src{from->second, l.fromPort};
        if (auto m = macros.find(from->second); m != macros.end()) {
            auto o = m->second.outs.find(l.fromPort);
            if (o == m->second.outs.end()) {
                linkError(top, li, origin, where,
                          "macro node " + std::to_string(l.fromNode) + " has no output port " +
                              std::to_string(l.fromPort));
                return;
            }
            src = {o->second, 0};
        } else if (fn.node->type == "macro") {
            return;  // a macro that failed to expand: reported
        } else if (l.fromPort >= (fn.pass && fn.node->type == "macro.in" ? 1u : fn.spec->outputs.size()) &&
                   !fn.spec->outputPerInput) {
            linkError(top, li, origin, where, "node " + std::to_string(l.fromNode) + " (" + fn.node->type +
                                                  ") has no output port " + std::to_string(l.fromPort));
            return;
        }
        if (auto m = macros.find(to->second); m != macros.end()) {
            auto in = m->second.ins.find(l.toPort);
            if (in == m->second.ins.end()) {
                linkError(top, li, origin, where,
                          "macro node " + std::to_string(l.toNode) + " has no input port " + std::to_string(l.toPort));
                return;
            }
            for (int k : in->second)
                setInput(k, 0, src, top, li, origin, where);
            return;
        }
        if (tn.node->type == "macro")
            return;
        const std::size_t inputs = tn.pass ? (tn.node->type == "macro.out" ? 1u : 0u) : tn.spec->inputs.size();
        if (tn.spec->variadic && l.toPort >= kMaxVariadicInputs) {
            linkError(top, li, origin, where, "node " + std::to_string(l.toNode) + " (" + tn.node->type +
                                                  ") takes at most " + std::to_string(kMaxVariadicInputs) +
                                                  " inputs (ports 0 to " + std::to_string(kMaxVariadicInputs - 1) +
                                                  "), not port " + std::to_string(l.toPort));
            return;
        }
        if (l.toPort >= inputs && !tn.spec->variadic) {
            linkError(top, li, origin, where, "node " + std::to_string(l.toNode) + " (" + tn.node->type +
                                                  ") has no input port " + std::to_string(l.toPort));
            return;
        }
        setInput(to->second, l.toPort, src, top, li, origin, where);
    }

    void setInput(int node, std::uint32_t port, FlatSource src, bool top, std::size_t li, NodeId origin,
                  const std::string& where)
    {
        FlatNode& n = m_out[std::size_t(node)];
        if (n.inputs.size() <= port)
            n.inputs.resize(port + 1);
        if (n.inputs[port].node >= 0) {
            linkError(top, li, origin, where,
                      "input " + std::to_string(port) + " of node " + std::to_string(n.node->id) +
                          " is connected twice");
            return;
        }
        n.inputs[port] = src;
    }

    const std::vector<BrainGraph>& m_library;
    BrainErrorList& m_errors;
    std::vector<FlatNode>& m_out;
    std::vector<std::string> m_stack;
    bool m_overflow = false;
};

}  // namespace

float numberParam(const FlatNode& n, const std::string& key)
{
    if (const BrainParam* p = findParam(*n.node, key); p && p->numbers.size() == 1 && p->text.empty())
        return p->numbers[0];
    const ParamSpec* s = findParamSpec(*n.spec, key);
    return s ? s->defaultValue : 0.0f;
}

const std::vector<float>* numbersParam(const FlatNode& n, const std::string& key)
{
    const BrainParam* p = findParam(*n.node, key);
    return p && p->text.empty() ? &p->numbers : nullptr;
}

std::string textParam(const FlatNode& n, const std::string& key)
{
    if (const BrainParam* p = findParam(*n.node, key); p && !p->text.empty())
        return p->text;
    const ParamSpec* s = findParamSpec(*n.spec, key);
    return s && s->type == ParamType::Choice ? s->choices.front() : std::string();
}

std::vector<std::string> words(const std::string& text)
{
    std::istringstream in(text);
    std::vector<std::string> out;
    for (std::string w; in >> w;)
        out.push_back(w);
    return out;
}

std::vector<FlatNode> flattenBrain(const BrainGraph& top, const std::vector<BrainGraph>& library,
                                   BrainErrorList& errors)
{
    std::vector<FlatNode> nodes;
    nodes.reserve(top.nodes.size());
    Flattener f(library, errors, nodes);
    f.flatten(top, 0, "");
    return nodes;
}

}  // namespace detail

BrainCompileResult compileBrain(const BrainGraph& graph, const std::vector<BrainGraph>& library)
{
    detail::BrainErrorList errors(graph);
    std::vector<detail::FlatNode> nodes = detail::flattenBrain(graph, library, errors);
    BrainCompileResult r;
    std::shared_ptr<BrainProgram> program = detail::emitBrain(nodes, graph.name, errors);
    r.errors = std::move(errors.errors());
    if (r.errors.empty())
        r.program = std::move(program);
    return r;
}

}  // namespace throng::sim
