#pragma once
// Test helpers: build a brain graph in code, compile it, and run it over a few agents
// with sensor values set by name.

#include "simcore/brain/BrainCompiler.h"
#include "simcore/brain/BrainEvaluator.h"
#include "simcore/brain/NodeCatalogue.h"

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace throng::test {

inline sim::BrainParam num(std::string key, float v) { return {std::move(key), {}, {v}}; }
inline sim::BrainParam nums(std::string key, std::vector<float> v) { return {std::move(key), {}, std::move(v)}; }
inline sim::BrainParam txt(std::string key, std::string v) { return {std::move(key), std::move(v), {}}; }

struct GraphBuilder {
    sim::BrainGraph g;
    sim::NodeId add(std::string type, std::vector<sim::BrainParam> params = {})
    {
        sim::BrainNode n;
        n.id = sim::NodeId(g.nodes.size() + 1);
        n.type = std::move(type);
        n.params = std::move(params);
        g.nodes.push_back(n);
        return n.id;
    }
    sim::NodeId sensor(const std::string& name, std::vector<sim::BrainParam> extra = {})
    {
        extra.insert(extra.begin(), txt("sensor", name));
        return add("input", std::move(extra));
    }
    sim::NodeId constant(float v) { return add("input.constant", {num("value", v)}); }
    void link(sim::NodeId from, std::uint32_t fromPort, sim::NodeId to, std::uint32_t toPort)
    {
        g.links.push_back({from, fromPort, to, toPort});
    }
};

// Compiles a graph (failing loudly) and evaluates it for `agents` agents.
class BrainRig {
public:
    explicit BrainRig(const sim::BrainGraph& g, std::size_t agents = 1, std::vector<sim::BrainGraph> library = {})
    {
        sim::BrainCompileResult r = sim::compileBrain(g, library);
        for (const sim::BrainError& e : r.errors)
            errors += e.format() + "\n";
        if (!r.ok())
            return;
        eval = std::make_unique<sim::BrainEvaluator>(r.program);
        eval->resize(agents);
        keys.resize(agents);
        for (std::size_t i = 0; i < agents; ++i)
            keys[i] = 1000 + i;
        counts.assign(agents, 0);
    }
    bool ok() const { return eval != nullptr; }
    // Sets a sensor's column (agents values, or agents × K for per-neighbour sensors).
    void set(const std::string& sensor, std::vector<float> values, const std::string& argument = {})
    {
        columns[sensor + "/" + argument] = std::move(values);
    }
    void step(float dtS = 0.1f)
    {
        sim::BrainInputs in;
        for (const sim::BrainSensorUse& s : eval->program().sensors) {
            std::vector<float>& c = columns[s.sensor + "/" + s.argument];
            c.resize(eval->agentCount() * (s.perNeighbour ? sim::kBrainNeighbours : 1), 0.0f);
            in.sensors.push_back(c.data());
        }
        for (const std::string& set : eval->program().itemSets) {
            std::vector<std::uint8_t>& c = set == "neighbours" ? counts : sourceCounts[set];
            c.resize(eval->agentCount(), 0);
            in.itemCounts.push_back(c.data());
        }
        in.agentKey = keys.data();
        in.timeS = timeS;
        in.dtS = dtS;
        std::string why;
        if (!eval->evaluate(in, &why, team.get()))
            errors += why;
        timeS += dtS;
    }
    float value(sim::NodeId node, std::uint32_t port = 0, std::size_t agent = 0) const
    {
        const float* v = eval->nodeValues(node, port);
        return v ? v[agent] : -12345.0f;
    }

    std::unique_ptr<sim::BrainEvaluator> eval;
    std::unique_ptr<sim::ThreadTeam> team;  // evaluate on it when set, else on the calling thread
    std::map<std::string, std::vector<float>> columns;
    std::vector<std::uint8_t> counts;  // neighbours per agent
    std::map<std::string, std::vector<std::uint8_t>> sourceCounts;  // "sound:<channel>" -> sources per agent
    std::vector<std::uint64_t> keys;
    float timeS = 0.0f;
    std::string errors;
};

}  // namespace throng::test
