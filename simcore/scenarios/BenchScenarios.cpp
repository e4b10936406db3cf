#include "simcore/scenarios/BenchScenarios.h"

#include <algorithm>
#include <cmath>

namespace throng::sim {

namespace {

AgentType walker()
{
    AgentType t;
    t.name = "walker";
    t.radiusM = 0.3f;
    t.maxSpeed = 1.4f;
    t.maxForce = 6.0f;
    return t;
}

}  // namespace

Scene makeCrossScenario(std::uint32_t agents, std::uint64_t seed)
{
    Scene s;
    s.settings.seed = seed;
    // Circumference gives each agent about 1 m of the circle, so density stays fixed as N grows.
    const float radius = std::max(5.0f, float(agents) * 1.0f / 6.2831853f);
    s.settings.boundsMin = glm::vec2(-radius - 5.0f);
    s.settings.boundsMax = glm::vec2(radius + 5.0f);
    s.settings.durationS = 2.0f * radius / 1.2f + 20.0f;
    s.agentTypes.push_back(walker());
    s.agents.reserve(agents);
    s.goals.reserve(agents);
    for (std::uint32_t i = 0; i < agents; ++i) {
        const float a = 6.2831853f * float(i) / float(agents);
        const glm::vec2 p(radius * std::cos(a), radius * std::sin(a));
        Goal g;
        // Appending (not "g" + to_string) sidesteps GCC 12's false -Wrestrict warning.
        g.name = "g";
        g.name += std::to_string(i);
        g.position = -p;
        g.radiusM = 0.5f;
        s.goals.push_back(g);
        Agent agent;
        agent.id = i + 1;
        agent.type = "walker";
        agent.position = glm::vec3(p.x, 0.0f, p.y);
        agent.headingDeg = std::fmod(a * 57.29578f + 180.0f, 360.0f);
        agent.goal = g.name;
        s.agents.push_back(agent);
    }
    return s;
}

Scene makeCorridorScenario(std::uint32_t agents, std::uint64_t seed)
{
    Scene s;
    s.settings.seed = seed;
    const float length = std::max(40.0f, float(agents) / 4.0f);
    const float halfWidth = 5.0f;
    s.settings.boundsMin = glm::vec2(-length / 2 - 10.0f, -halfWidth - 5.0f);
    s.settings.boundsMax = glm::vec2(length / 2 + 10.0f, halfWidth + 5.0f);
    s.settings.durationS = length / 1.2f + 20.0f;
    s.agentTypes.push_back(walker());
    s.walls.push_back({"north", {{-length / 2 - 8.0f, -halfWidth}, {length / 2 + 8.0f, -halfWidth}}});
    s.walls.push_back({"south", {{-length / 2 - 8.0f, halfWidth}, {length / 2 + 8.0f, halfWidth}}});
    s.goals.push_back({"east", {length / 2 + 6.0f, 0.0f}, halfWidth});
    s.goals.push_back({"west", {-length / 2 - 6.0f, 0.0f}, halfWidth});
    const float x0 = -length / 2, x1 = length / 2;
    SpawnGroup east{"eastbound", "walker", agents / 2, AreaShape::Rect, {x0, -halfWidth + 0.5f},
                    {0.0f, halfWidth - 0.5f}, {}, 0.0f, "east", ""};
    SpawnGroup west{"westbound", "walker", agents - agents / 2, AreaShape::Rect, {0.0f, -halfWidth + 0.5f},
                    {x1, halfWidth - 0.5f}, {}, 0.0f, "west", ""};
    s.groups = {east, west};
    return s;
}

const std::vector<std::string>& benchScenarioNames()
{
    static const std::vector<std::string> names{"cross", "corridor"};
    return names;
}

bool makeBenchScenario(const std::string& name, std::uint32_t agents, Scene& out)
{
    if (name == "cross")
        out = makeCrossScenario(agents);
    else if (name == "corridor")
        out = makeCorridorScenario(agents);
    else
        return false;
    return true;
}

}  // namespace throng::sim
