// The compiler's back half: input counts, cycle check (Kahn's algorithm; a memory node's
// input is not a dependency), port kinds, duplicate outputs, then one pass in
// topological order that assigns slots, folds constants and emits instructions.
#include "simcore/brain/detail/BrainFlatGraph.h"
#include "simcore/brain/detail/BrainKernels.h"

#include <algorithm>
#include <cstring>
#include <map>
#include <set>

namespace throng::sim::detail {

namespace {

const PortSpec& inputSpec(const FlatNode& n, std::size_t port)
{
    return n.spec->inputs[std::min(port, n.spec->inputs.size() - 1)];
}

std::size_t outputCount(const FlatNode& n)
{
    if (n.pass)
        return 1;
    return n.spec->outputPerInput ? n.inputs.size() : n.spec->outputs.size();
}

// Checks connected inputs against the node's ports; returns false on error.
bool checkInputs(FlatNode& n, BrainErrorList& errors)
{
    if (n.pass)
        return true;
    if (!n.spec->variadic && n.inputs.size() < n.spec->inputs.size())
        n.inputs.resize(n.spec->inputs.size());
    bool ok = true;
    for (std::size_t p = 0; p < n.inputs.size(); ++p)
        if (n.inputs[p].node < 0 && inputSpec(n, p).required && !n.fedByUnknown) {
            errors.at(n, "input " + std::to_string(p) + " '" + inputSpec(n, p).name + "' is not connected");
            ok = false;
        }
    if (n.spec->variadic && int(n.inputs.size()) < n.spec->minInputs) {
        errors.at(n, "needs at least " + std::to_string(n.spec->minInputs) + " connected inputs, has " +
                         std::to_string(n.inputs.size()));
        ok = false;
    }
    const std::string& t = n.node->type;
    const auto needOnePer = [&](const std::string& key, std::size_t have, const char* what) {
        if (have != n.inputs.size()) {
            errors.at(n, "parameter '" + key + "' has " + std::to_string(have) + " " + what + " for " +
                             std::to_string(n.inputs.size()) + " connected inputs");
            ok = false;
        }
    };
    if (t == "defuzz.average")
        needOnePer("values", numbersParam(n, "values")->size(), "values");
    else if (t == "defuzz.winner" && numbersParam(n, "values"))
        needOnePer("values", numbersParam(n, "values")->size(), "values");
    else if (t == "output.action")
        needOnePer("actions", words(textParam(n, "actions")).size(), "actions");
    else if (t == "output.goal")
        needOnePer("goals", words(textParam(n, "goals")).size(), "goals");
    return ok;
}

// Kahn's algorithm over active nodes, ties broken by graph order; reports each cycle once.
std::vector<int> order(const std::vector<FlatNode>& nodes, BrainErrorList& errors)
{
    const std::size_t n = nodes.size();
    std::vector<std::vector<int>> users(n);
    std::vector<int> pending(n, 0);
    for (std::size_t i = 0; i < n; ++i) {
        if (nodes[i].inert || nodes[i].spec->breaksCycles)
            continue;
        for (const FlatSource& s : nodes[i].inputs)
            if (s.node >= 0) {
                users[std::size_t(s.node)].push_back(int(i));
                ++pending[i];
            }
    }
    std::set<int> ready;
    for (std::size_t i = 0; i < n; ++i)
        if (!nodes[i].inert && pending[i] == 0)
            ready.insert(int(i));
    std::vector<int> out;
    while (!ready.empty()) {
        const int i = *ready.begin();
        ready.erase(ready.begin());
        out.push_back(i);
        for (int u : users[std::size_t(i)])
            if (--pending[std::size_t(u)] == 0)
                ready.insert(u);
    }
    std::set<int> reported;
    for (std::size_t start = 0; start < n; ++start) {
        if (nodes[start].inert || pending[start] == 0)
            continue;
        // Walk back through unfinished inputs until a node repeats: that is a cycle.
        std::vector<int> path;
        std::map<int, std::size_t> seen;
        int cur = int(start);
        while (!seen.count(cur)) {
            seen[cur] = path.size();
            path.push_back(cur);
            for (const FlatSource& s : nodes[std::size_t(cur)].inputs)
                if (s.node >= 0 && pending[std::size_t(s.node)] > 0) {
                    cur = s.node;
                    break;
                }
        }
        std::vector<int> cycle(path.begin() + std::ptrdiff_t(seen[cur]), path.end());
        if (std::any_of(cycle.begin(), cycle.end(), [&](int c) { return reported.count(c) > 0; }))
            continue;
        std::reverse(cycle.begin(), cycle.end());
        std::rotate(cycle.begin(), std::min_element(cycle.begin(), cycle.end()), cycle.end());
        std::string ids;
        for (int c : cycle) {
            ids += std::to_string(nodes[std::size_t(c)].node->id) + " -> ";
            reported.insert(c);
        }
        ids += std::to_string(nodes[std::size_t(cycle.front())].node->id);
        errors.at(nodes[std::size_t(cycle.front())],
                  "illegal cycle " + ids + " (a loop must pass through a state.memory node)");
    }
    return out;
}

}  // namespace

// Defined in BrainEmitNodes.cpp: emits one node; the shared state of the pass.
struct EmitPass;
void emitNode(EmitPass& pass, int index);
std::shared_ptr<BrainProgram> emitAll(std::vector<FlatNode>& nodes, const std::vector<int>& sorted,
                                      const std::vector<std::vector<int>>& kinds, const std::vector<std::string>& sets,
                                      const std::string& name);

std::shared_ptr<BrainProgram> emitBrain(std::vector<FlatNode>& nodes, const std::string& name, BrainErrorList& errors)
{
    const std::size_t before = errors.errors().size();
    for (FlatNode& n : nodes)
        if (!n.inert && !n.badParams)
            checkInputs(n, errors);
    const std::vector<int> sorted = order(nodes, errors);
    // Port kinds, in order: -1 = one value per agent, else the item set (neighbours, or
    // the sources of a sound channel) the per-item values belong to. A per-item value may
    // not reach a per-agent input, and one node may not mix two item sets.
    std::vector<std::string> sets;
    std::vector<std::vector<int>> kinds(nodes.size());
    const auto setName = [&](int k) {
        return sets[std::size_t(k)] == "neighbours" ? std::string("neighbour")
                                                    : "source heard on '" + sets[std::size_t(k)].substr(6) + "'";
    };
    for (int i : sorted) {
        FlatNode& n = nodes[std::size_t(i)];
        int set = -1;
        for (std::size_t p = 0; p < n.inputs.size(); ++p) {
            const FlatSource& s = n.inputs[p];
            if (s.node < 0)
                continue;
            const std::vector<int>& from = kinds[std::size_t(s.node)];
            const int srcSet = s.port < from.size() ? from[s.port] : -1;
            const std::string id = std::to_string(nodes[std::size_t(s.node)].node->id);
            if (srcSet >= 0 && set >= 0 && srcSet != set)
                errors.at(n, "input " + std::to_string(p) + " gives one value per " + setName(srcSet) + " (node " + id +
                                 ") but another input one per " + setName(set) + "; filter one of them first");
            if (srcSet >= 0 && set < 0)
                set = srcSet;
            if (n.pass)
                continue;
            const PortKind want = inputSpec(n, p).kind;
            if (want == PortKind::Scalar && srcSet >= 0)
                errors.at(n, "type mismatch: input " + std::to_string(p) + " '" + inputSpec(n, p).name +
                                 "' takes one value per agent but node " + id + " gives one per " + setName(srcSet) +
                                 "; collapse it with a filter node");
            else if (want == PortKind::PerNeighbour && srcSet < 0)
                errors.at(n, "type mismatch: input " + std::to_string(p) + " '" + inputSpec(n, p).name +
                                 "' takes per-neighbour values but node " + id + " gives one value per agent");
        }
        if (n.node->type == "input" && !n.badParams) {
            const SensorSpec* spec = findSensorSpec(textParam(n, "sensor"));
            if (spec && spec->perNeighbour) {
                const std::string key = spec->itemSet == "sound" ? "sound:" + textParam(n, "channel") : spec->itemSet;
                set = int(std::find(sets.begin(), sets.end(), key) - sets.begin());
                if (std::size_t(set) == sets.size())
                    sets.push_back(key);
            }
        }
        std::vector<int>& out = kinds[std::size_t(i)];
        out.assign(outputCount(n), -1);
        for (std::size_t p = 0; p < out.size(); ++p)
            if (n.pass || n.node->type == "input" ||
                n.spec->outputs[std::min(p, n.spec->outputs.size() - 1)].kind == PortKind::Any)
                out[p] = set;
        if (n.node->type == "filter")
            n.filterSet = set;
    }
    // One node per output channel.
    std::map<std::string, const FlatNode*> channels;
    for (const FlatNode& n : nodes) {
        if (n.inert || n.badParams)
            continue;
        std::string key;
        if (n.node->type == "output") {
            key = textParam(n, "channel");
            if (key == "weight")
                key += " " + textParam(n, "behaviour");
            else if (key == "tag")
                key += " " + textParam(n, "tag");
        } else if (n.node->type == "output.action" || n.node->type == "output.goal") {
            key = n.node->type.substr(7);
        }
        if (key.empty())
            continue;
        auto [it, fresh] = channels.emplace(key, &n);
        if (!fresh)
            errors.at(n, "duplicate output channel '" + key + "': node " + std::to_string(it->second->origin) +
                             " already drives it");
    }
    if (errors.errors().size() != before ||
        std::any_of(nodes.begin(), nodes.end(), [](const FlatNode& n) { return n.badParams; }))
        return nullptr;
    if (sets.size() > 255) {
        errors.node(0, "more than 255 sets of per-item values");
        return nullptr;
    }
    return emitAll(nodes, sorted, kinds, sets, name);
}

}  // namespace throng::sim::detail
