#include "RandomScene.h"

#include <random>

namespace throng::test {

using namespace throng::sim;

sim::Scene makeRandomScene(std::uint32_t seed, std::uint32_t agentCount)
{
    std::mt19937 gen(seed);
    // Awkward floats on purpose: values with no short decimal form must survive too.
    auto f = [&](float lo, float hi) { return std::uniform_real_distribution<float>(lo, hi)(gen); };
    auto pt = [&] { return glm::vec2(f(-40, 40), f(-40, 40)); };
    auto line = [&](int n) {
        std::vector<glm::vec2> p;
        for (int i = 0; i < n; ++i)
            p.push_back(pt());
        return p;
    };
    Scene s;
    s.settings.fps = f(12, 60);
    s.settings.durationS = f(1, 100);
    s.settings.seed = (std::uint64_t(gen()) << 32) | gen();
    s.settings.boundsMin = {-50.5f, -60.25f};
    s.settings.boundsMax = {f(50, 90), f(60, 90)};

    BrainGraph brain;
    brain.name = "brain_" + std::to_string(seed);
    for (NodeId id = 1; id <= 4; ++id) {
        BrainNode n;
        n.id = id * 3;
        n.type = id == 1 ? "input" : (id == 4 ? "output" : "fuzz.triangle");
        n.label = id == 2 ? "near: \"quoted\" # not a comment" : "";
        n.position = pt();
        n.params.push_back({"points", "", {f(0, 1), f(1, 2), f(2, 3)}});
        n.params.push_back({"sensor", "goal distance", {}});
        n.params.push_back({"digits", "42", {}});
        n.params.push_back({"gain", "", {f(-1, 1)}});
        brain.nodes.push_back(n);
    }
    brain.links = {{3, 0, 6, 0}, {6, 0, 9, 1}, {9, 2, 12, 0}};
    s.brains.push_back(brain);

    const AgentKind kinds[3] = {AgentKind::Pedestrian, AgentKind::Vehicle, AgentKind::Flier};
    for (int t = 0; t < 3; ++t) {
        AgentType type;
        type.name = "type" + std::to_string(t);
        type.kind = kinds[t];
        type.radiusM = f(0.1f, 2.0f);
        type.maxSpeed = f(0, 20);
        type.maxForce = f(0, 100);
        type.mass = f(0.1f, 2000);
        type.perceptionM = f(1, 10);
        type.viewAngleDeg = f(10, 360);
        type.brain = t == 0 ? brain.name : "";
        type.character = t == 0 ? "woman" : (t == 1 ? "car" : "bird");
        type.variation.looks = {"man", "child"};
        type.variation.tints = {{f(0, 1), f(0, 1), f(0, 1)}, {0.5f, 0.25f, 1.0f}};
        type.variation.heightScale = {0.9f, f(1, 1.2f)};
        type.variation.speedFactor = {0.75f, f(1, 1.5f)};
        type.variation.phaseOffset = {0.0f, f(0.5f, 1)};
        type.behaviours = {{"seek", f(0, 2), {}},
                           {"separation", f(0, 5), {{"range", "", {f(0, 2)}}}},
                           {"obstacle_avoidance", 2.0f, {{"response", "repulsive", {}}, {"margin", "", {f(0, 1)}}}},
                           {"offset_pursuit", 1.0f, {{"offset", "", {f(-2, 2), 0.0f, f(-3, 0)}}}}};
        type.priorityCombination = t == 1;
        type.minSpeed = t == 2 ? f(0, type.maxSpeed) : 0.0f;
        type.banking = t == 2 ? f(0, 0.2f) : 0.0f;
        // Set on one type, each action's own on the others; drawn from no random number, so
        // the scenes the golden runs hash stay the same.
        type.actionBlendS = t == 0 ? 0.35f : -1.0f;
        s.agentTypes.push_back(type);
    }
    s.goals = {{"exit", pt(), f(0.5f, 3)}, {"door", pt(), 1.0f}};
    s.paths = {{"main", line(5), f(0.5f, 3), false}, {"ring", line(4), 2.0f, true}};
    s.walls = {{"north", line(3), f(0.1f, 8)}, {"", line(2)}};  // the second keeps the default height
    s.obstacles = {{"pillar", ObstacleShape::Circle, pt(), f(0.2f, 2), glm::vec2(1.0f), 0.0f},
                   {"", ObstacleShape::Box, pt(), 0.5f, {f(1, 4), f(1, 4)}, f(-180, 180)}};
    s.terrain.origin = pt();
    s.terrain.cellM = f(0.5f, 4);
    s.terrain.cols = 4;
    s.terrain.rows = 3;
    for (int i = 0; i < 12; ++i)
        s.terrain.heights.push_back(f(-5, 5));
    s.flowStrokes = {{line(4), f(1, 5)}};
    s.lanes = {{"east", line(3), f(2.5f, 4), f(5, 20), true}, {"west", line(2), 3.5f, 13.9f, false}};
    s.crosswalks = {{"cw", {0, 8}, {0, -8}, f(2, 5)}};
    TrafficLight light;
    light.name = "signal";
    light.greenS = f(5, 30);
    light.yellowS = f(1, 4);
    light.redS = f(5, 30);
    light.offsetS = f(-10, 10);
    light.position = pt();
    light.stopLines = {{"east", f(0, 30), ""}, {"", 0.0f, "cw"}};
    s.trafficLights = {light};
    std::uint32_t id = 1;
    for (std::uint32_t i = 0; i < agentCount; ++i) {
        Agent a;
        a.id = id++;
        a.type = "type0";
        a.position = {f(-40, 40), i % 3 == 0 ? f(0, 10) : 0.0f, f(-40, 40)};
        a.headingDeg = f(-180, 180);
        a.goal = i % 2 ? "exit" : "";
        a.path = i % 5 == 0 ? "main" : "";
        a.leader = i > 0 && i % 4 == 0 ? 1u : 0u;
        a.brain = i % 3 == 1 ? s.brains.front().name : "";
        a.group = i % 4 == 2 ? "squad" : "";
        s.agents.push_back(a);
    }
    s.groups = {{"shoppers", "type0", 25, AreaShape::Rect, {-10, -10}, {f(0, 10), f(0, 10)}, {}, 0.0f, "door", "", agentCount > 0 ? 1u : 0u},
                {"circle", "type2", 7, AreaShape::Circle, {}, {}, pt(), f(1, 5), "", "ring", 0u}};
    // A concave L: the notch is cut from the corner opposite o.
    const glm::vec2 o = pt(), size(f(4, 12), f(4, 12)), notch = size * glm::vec2(f(0.2f, 0.8f), f(0.2f, 0.8f));
    s.groups.push_back({"yard", "type0", 9, AreaShape::Polygon, {}, {}, {}, 0.0f, "", "", 0u, {}, {o, o + glm::vec2(size.x, 0.0f), o + glm::vec2(size.x, notch.y), o + notch, o + glm::vec2(notch.x, size.y), o + glm::vec2(0.0f, size.y)}});
    s.vehicles = {{id++, "type1", "east", f(0, 20), f(0, 10)}};
    s.heroes = {{id++, "lead", "type0", f(0, 4), "", {{0.0f, {1, 0, 2}}, {f(0.5f, 2), {3, 0.5f, 4}}, {5.0f, {6, 0, 7}}}}};
    return s;
}

}  // namespace throng::test
