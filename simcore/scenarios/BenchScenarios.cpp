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
    // The same layout as the DetourCrowd peer's `circle` scenario (shared/peers), so the
    // two can be compared: concentric rings 3 radii apart, spacing 3 radii along a ring,
    // goal = the antipodal point, on a square of 400 m for 10,000 agents (same density
    // for other counts), agent radius 0.5 m, 1.4 m/s.
    Scene s;
    s.settings.seed = seed;
    const float agentRadius = 0.5f, spacing = 3.0f * agentRadius;
    const float half = 200.0f * std::sqrt(std::max(1.0f, float(agents) / 10000.0f));
    s.settings.boundsMin = glm::vec2(-half);
    s.settings.boundsMax = glm::vec2(half);
    AgentType t = walker();
    t.radiusM = agentRadius;
    t.variation.speedFactor = {1.0f, 1.0f};
    s.agentTypes.push_back(t);
    s.agents.reserve(agents);
    s.goals.reserve(agents);
    float ring = half - 10.0f;
    std::uint32_t placed = 0;
    while (placed < agents && ring > spacing) {
        const auto onRing = std::min<std::uint32_t>(agents - placed, std::uint32_t(std::floor(6.2831853f * ring / spacing)));
        for (std::uint32_t k = 0; k < onRing; ++k, ++placed) {
            const float a = 6.2831853f * float(k) / float(onRing) + 0.37f * ring;
            const glm::vec2 p(ring * std::cos(a), ring * std::sin(a));
            Goal g;
            // Appending (not "g" + to_string) sidesteps GCC 12's false -Wrestrict warning.
            g.name = "g";
            g.name += std::to_string(placed);
            g.position = -p;
            g.radiusM = 0.5f;
            s.goals.push_back(g);
            Agent agent;
            agent.id = placed + 1;
            agent.type = "walker";
            agent.position = glm::vec3(p.x, 0.0f, p.y);
            agent.headingDeg = std::atan2(p.y, -p.x) * 57.2957795f;  // facing the centre
            agent.goal = g.name;
            s.agents.push_back(agent);
        }
        ring -= spacing;
    }
    s.settings.durationS = 2.0f * half / 1.4f + 30.0f;
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
