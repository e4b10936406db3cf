#pragma once
// Random brain graphs for the fuzz and round-trip tests: mostly real node types with
// plausible or wrong parameters, random links (some to missing ports or nodes).

#include "BrainRig.h"

#include <algorithm>
#include <random>

namespace throng::test {

inline sim::BrainGraph randomBrain(std::mt19937& gen, const std::string& name, const std::vector<std::string>& macroNames)
{
    const auto& cat = sim::nodeCatalogue();
    const auto& sensors = sim::sensorCatalogue();
    std::uniform_int_distribution<int> pct(0, 99);
    std::uniform_real_distribution<float> val(-5.0f, 5.0f);
    const auto pick = [&](std::size_t n) { return std::uniform_int_distribution<std::size_t>(0, n - 1)(gen); };
    sim::BrainGraph g;
    g.name = name;
    const std::size_t count = 1 + pick(30);
    for (std::size_t i = 0; i < count; ++i) {
        sim::BrainNode n;
        n.id = sim::NodeId(i + 1 + (pct(gen) < 5 ? 1000 : 0));
        const sim::NodeSpec& spec = cat[pick(cat.size())];
        n.type = pct(gen) < 3 ? "bogus.type" : spec.type;
        n.label = pct(gen) < 50 ? "node \"" + std::to_string(i) + "\": a: b" : "";
        n.position = {val(gen) * 100.0f, val(gen) * 37.0f};
        for (const sim::ParamSpec& p : spec.params) {
            if (pct(gen) < 20 && !p.required)
                continue;
            sim::BrainParam bp;
            bp.key = pct(gen) < 2 ? "mystery" : p.key;
            switch (pct(gen) < 90 ? p.type : sim::ParamType(pick(4))) {
            case sim::ParamType::Number: bp.numbers = {val(gen)}; break;
            case sim::ParamType::Numbers: {
                const std::size_t k = p.count && pct(gen) < 85 ? p.count : pick(6);
                for (std::size_t j = 0; j < k; ++j)
                    bp.numbers.push_back(val(gen));
                if (pct(gen) < 70)
                    std::sort(bp.numbers.begin(), bp.numbers.end());
                break;
            }
            case sim::ParamType::Text:
                if (p.key == "sensor")
                    bp.text = pct(gen) < 95 ? sensors[pick(sensors.size())].name : "smell";
                else if (p.key == "brain")
                    bp.text = macroNames.empty() || pct(gen) < 10 ? "nowhere" : macroNames[pick(macroNames.size())];
                else if (p.key == "behaviour")
                    bp.text = pct(gen) < 80 ? "separation" : "dance";
                else
                    bp.text = pct(gen) < 50 ? "idle walk" : "a";
                break;
            case sim::ParamType::Choice:
                bp.text = p.choices.empty() || pct(gen) < 5 ? "nonsense" : p.choices[pick(p.choices.size())];
                break;
            }
            if (bp.text.empty() && bp.numbers.empty())
                bp.numbers = {1.0f};
            if (std::none_of(n.params.begin(), n.params.end(), [&](const sim::BrainParam& q) { return q.key == bp.key; }))
                n.params.push_back(bp);
        }
        g.nodes.push_back(n);
    }
    const std::size_t links = pick(count * 2 + 1);
    for (std::size_t l = 0; l < links; ++l) {
        sim::BrainLink link;
        link.fromNode = g.nodes[pick(count)].id;
        link.toNode = g.nodes[pick(count)].id;
        link.fromPort = std::uint32_t(pct(gen) < 85 ? 0 : pick(4));
        link.toPort = std::uint32_t(pick(4));
        if (pct(gen) < 2)
            link.toNode = 4000;  // no such node
        g.links.push_back(link);
    }
    return g;
}

// A working brain with a few random changes: numbers nudged (kept in order where a node
// needs that), and with `breakIt`, links dropped or added and parameters removed.
inline sim::BrainGraph mutateBrain(std::mt19937& gen, sim::BrainGraph g, bool breakIt)
{
    std::uniform_int_distribution<int> pct(0, 99);
    const auto pick = [&](std::size_t n) { return std::uniform_int_distribution<std::size_t>(0, n - 1)(gen); };
    std::normal_distribution<float> nudge(0.0f, 2.0f);
    for (int m = 0; m < 6; ++m) {
        sim::BrainNode& n = g.nodes[pick(g.nodes.size())];
        for (sim::BrainParam& p : n.params) {
            for (float& v : p.numbers)
                if (pct(gen) < 50)
                    v = std::max(v + nudge(gen), p.key == "width" || p.key == "tau" || p.key == "frequency" ? 0.01f : -1e6f);
            std::sort(p.numbers.begin(), p.numbers.end());
            if (p.key == "from" && p.numbers.size() == 2 && p.numbers[0] == p.numbers[1])
                p.numbers[1] += 1.0f;
        }
        if (!breakIt)
            continue;
        switch (pct(gen) % 4) {
        case 0: if (!g.links.empty()) g.links.erase(g.links.begin() + std::ptrdiff_t(pick(g.links.size()))); break;
        case 1: g.links.push_back({g.nodes[pick(g.nodes.size())].id, 0, g.nodes[pick(g.nodes.size())].id, std::uint32_t(pick(3))}); break;
        case 2: if (!n.params.empty()) n.params.pop_back(); break;
        default: n.type = g.nodes[pick(g.nodes.size())].type; break;
        }
    }
    return g;
}

}  // namespace throng::test
