#include "simcore/scenarios/BenchScenarios.h"

#include "simcore/scenarios/BenchBrains.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

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

Scene makeCrossScenario(std::uint32_t agents, std::uint64_t seed, const CrossLayout& layout)
{
    Scene s;
    s.settings.seed = seed;
    AgentType t = walker();
    t.radiusM = layout.agentRadiusM;
    t.maxSpeed = layout.speed;
    t.variation.speedFactor = {1.0f, 1.0f};
    s.agentTypes.push_back(t);
    s.agents.reserve(agents);
    s.goals.reserve(agents);
    const float spacing = std::max(layout.spacingM, 2.0f * layout.agentRadiusM);
    const float gap = std::max(layout.ringGapM, 2.0f * layout.agentRadiusM);
    float radius = std::max(layout.innerRadiusM, spacing);
    std::uint32_t placed = 0;
    while (placed < agents) {
        const auto onRing = std::min(agents - placed, std::uint32_t(std::floor(6.2831853f * radius / spacing)));
        for (std::uint32_t k = 0; k < onRing; ++k, ++placed) {
            // Each ring turned by its own angle, so rings do not line up radially.
            const float a = 6.2831853f * float(k) / float(onRing) + 0.37f * radius;
            const glm::vec2 p(radius * std::cos(a), radius * std::sin(a));
            Goal g;
            // Appending (not "g" + to_string) sidesteps GCC 12's false -Wrestrict warning.
            g.name = "g";
            g.name += std::to_string(placed);
            g.position = -p;
            g.radiusM = layout.agentRadiusM;
            s.goals.push_back(g);
            Agent agent;
            agent.id = placed + 1;
            agent.type = "walker";
            agent.position = glm::vec3(p.x, 0.0f, p.y);
            agent.headingDeg = std::atan2(p.y, -p.x) * 57.2957795f;  // facing the centre
            agent.goal = g.name;
            s.agents.push_back(agent);
        }
        radius += gap;
    }
    const float outer = radius - gap;
    s.settings.boundsMin = glm::vec2(-outer - 10.0f);
    s.settings.boundsMax = glm::vec2(outer + 10.0f);
    // The outermost ring's walk across, and as long again for the crowd to get through.
    s.settings.durationS = 2.0f * (2.0f * outer / layout.speed) + 30.0f;
    return s;
}

Scene makeCrossBrainScenario(std::uint32_t agents, std::uint64_t seed)
{
    Scene s = makeCrossScenario(agents, seed);
    s.brains.push_back(benchPedestrianBrain());
    for (AgentType& type : s.agentTypes)
        type.brain = s.brains.back().name;
    return s;
}

std::string crossLayoutDescription(const CrossLayout& layout)
{
    char text[200];
    std::snprintf(text, sizeof text,
                  "concentric rings from %.0f m out, %.1f m apart, agents %.1f m apart on a ring, "
                  "radius %.2f m, %.2f m/s",
                  double(layout.innerRadiusM), double(layout.ringGapM), double(layout.spacingM),
                  double(layout.agentRadiusM), double(layout.speed));
    return text;
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
                    {0.0f, halfWidth - 0.5f}, {}, 0.0f, "east", "", 0};
    SpawnGroup west{"westbound", "walker", agents - agents / 2, AreaShape::Rect, {0.0f, -halfWidth + 0.5f},
                    {x1, halfWidth - 0.5f}, {}, 0.0f, "west", "", 0};
    s.groups = {east, west};
    return s;
}

Scene makeFlockScenario(std::uint32_t agents, std::uint64_t seed, FlockNumbering numbering)
{
    // Boids (Reynolds 1987) in 3D: separation, alignment and cohesion, and a loose pursuit
    // of a lead bird that flies a closed circuit, so the flock migrates. Density about
    // one bird per 8 m^3.
    Scene s;
    s.settings.seed = seed;
    const float half = 50.0f * std::cbrt(std::max(1.0f, float(agents) / 10000.0f));
    s.settings.boundsMin = glm::vec2(-3.0f * half);
    s.settings.boundsMax = glm::vec2(3.0f * half);
    AgentType bird;
    bird.name = "starling";
    bird.kind = AgentKind::Flier;
    bird.radiusM = 0.2f;
    bird.maxSpeed = 12.0f;
    bird.minSpeed = 4.0f;
    bird.maxForce = 20.0f;
    bird.mass = 1.0f;
    bird.perceptionM = 3.0f;
    bird.viewAngleDeg = 300.0f;
    bird.banking = 0.05f;
    bird.character = "bird";
    bird.behaviours = {{"separation", 2.0f, {{"range", "", {0.6f}}}}, {"alignment", 1.0f, {}},
                       {"cohesion", 1.0f, {}}, {"pursuit", 0.3f, {}}, {"containment", 4.0f, {}},
                       {"wander", 0.2f, {}}};
    AgentType lead = bird;
    lead.name = "lead";
    lead.maxSpeed = 10.0f;  // a little slower than the flock, so it can be caught up with
    lead.behaviours = {{"path_following", 1.0f, {}}, {"containment", 4.0f, {}}};
    s.agentTypes = {bird, lead};
    Path circuit;
    circuit.name = "migration";
    circuit.closed = true;
    circuit.radiusM = 5.0f;
    for (int k = 0; k < 8; ++k) {
        const float a = 6.2831853f * float(k) / 8.0f;
        circuit.points.push_back(2.0f * half * glm::vec2(std::cos(a), std::sin(a)));
    }
    s.paths.push_back(circuit);
    s.agents.reserve(agents);
    Agent leader;
    leader.id = 1;
    leader.type = lead.name;
    leader.position = glm::vec3(2.0f * half, 30.0f, -10.0f);
    leader.headingDeg = 90.0f;
    leader.path = circuit.name;
    s.agents.push_back(leader);
    const auto side = std::uint32_t(std::ceil(std::cbrt(double(agents))));
    const float spacing = 2.0f * half / float(side);
    for (std::uint32_t i = 1; i < agents; ++i) {
        // The lattice point: along x first, or up first (then the bird at each point is
        // the one RowByRow puts there: the same id and jitter).
        const std::uint32_t first = i % side, second = (i / side) % side, zi = i / (side * side);
        const std::uint32_t xi = numbering == FlockNumbering::ByColumn ? second : first,
                            yi = numbering == FlockNumbering::ByColumn ? first : second;
        const std::uint32_t point = xi + side * (yi + side * zi);  // RowByRow's i
        Agent a;
        a.id = point + 1;
        a.type = bird.name;
        const float x = float(xi), y = float(yi), z = float(zi);
        // A lattice, jittered by a fixed pattern so no two birds start in lock-step.
        const float jx = 0.3f * std::sin(float(point) * 12.9898f), jz = 0.3f * std::cos(float(point) * 78.233f);
        a.position = glm::vec3(2.0f * half + (x - 0.5f * float(side)) * spacing + jx, 20.0f + y * spacing * 0.5f,
                               (z - 0.5f * float(side)) * spacing + jz);
        a.headingDeg = 90.0f;
        a.leader = leader.id;
        s.agents.push_back(a);
    }
    s.settings.durationS = 60.0f;
    return s;
}

Scene makeArmyScenario(std::uint32_t agents, std::uint64_t seed)
{
    // Two masses charge each other across a field: the densest head-on crossing.
    Scene s;
    s.settings.seed = seed;
    const float depth = std::max(10.0f, std::sqrt(float(agents)) * 0.9f);
    const float width = 2.0f * depth;
    s.settings.boundsMin = {-3.0f * depth, -width};
    s.settings.boundsMax = {3.0f * depth, width};
    AgentType t = walker();
    t.name = "soldier";
    t.maxSpeed = 2.5f;
    t.maxForce = 8.0f;
    s.agentTypes.push_back(t);
    s.goals.push_back({"east", {2.5f * depth, 0.0f}, 0.6f * width});
    s.goals.push_back({"west", {-2.5f * depth, 0.0f}, 0.6f * width});
    SpawnGroup a{"west_army", "soldier", agents / 2, AreaShape::Rect, {-2.0f * depth, -0.5f * width},
                 {-depth, 0.5f * width}, {}, 0.0f, "east", "", 0, {}};
    SpawnGroup b{"east_army", "soldier", agents - agents / 2, AreaShape::Rect, {depth, -0.5f * width},
                 {2.0f * depth, 0.5f * width}, {}, 0.0f, "west", "", 0, {}};
    s.groups = {a, b};
    s.settings.durationS = 5.0f * depth / 2.5f + 20.0f;
    return s;
}

const std::vector<std::string>& benchScenarioNames()
{
    static const std::vector<std::string> names{"flock", "cross", "cross-brain", "army", "corridor"};
    return names;
}

bool makeBenchScenario(const std::string& name, std::uint32_t agents, Scene& out)
{
    if (name == "flock")
        out = makeFlockScenario(agents);
    else if (name == "cross")
        out = makeCrossScenario(agents);
    else if (name == "cross-brain")
        out = makeCrossBrainScenario(agents);
    else if (name == "army")
        out = makeArmyScenario(agents);
    else if (name == "corridor")
        out = makeCorridorScenario(agents);
    else
        return false;
    return true;
}

}  // namespace throng::sim
