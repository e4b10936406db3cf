#include "editor/tools/CrowdBrushPlacement.h"
#include "editor/SegmentDistance.h"

#include "editor/tools/TerrainHeight.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

namespace throng::editor {

namespace {

constexpr int kTriesPerAgent = 30;  // Bridson's k for Poisson-disc sampling

std::string chooseType(const sim::Scene& scene, const std::vector<TypeShare>& mix, float u)
{
    float total = 0.0f;
    for (const TypeShare& s : mix)
        total += std::max(0.0f, s.weight);
    if (total > 0.0f) {
        // A type of weight 0 is never drawn, not even by u = 0 or by rounding at the end.
        float pick = u * total;
        const TypeShare* last = nullptr;
        for (const TypeShare& s : mix) {
            if (s.weight <= 0.0f)
                continue;
            last = &s;
            pick -= s.weight;
            if (pick <= 0.0f)
                return s.type;
        }
        return last->type;
    }
    return defaultBrushType(scene);
}

}  // namespace

std::string defaultBrushType(const sim::Scene& scene)
{
    for (const sim::AgentType& t : scene.agentTypes)
        if (t.kind == sim::AgentKind::Pedestrian)
            return t.name;
    return scene.agentTypes.empty() ? std::string() : scene.agentTypes.front().name;
}

bool isBlocked(const sim::Scene& scene, glm::vec2 p, float r)
{
    const sim::Settings& s = scene.settings;
    if (p.x - r < s.boundsMin.x || p.y - r < s.boundsMin.y || p.x + r > s.boundsMax.x || p.y + r > s.boundsMax.y)
        return true;
    for (const sim::Wall& w : scene.walls)
        for (std::size_t i = 1; i < w.points.size(); ++i)
            if (segmentDistance(p, w.points[i - 1], w.points[i]) < r)
                return true;
    for (const sim::Obstacle& o : scene.obstacles) {
        if (o.shape == sim::ObstacleShape::Circle) {
            if (glm::length(p - o.center) < o.radiusM + r)
                return true;
            continue;
        }
        const float a = glm::radians(o.angleDeg);
        const glm::vec2 d = p - o.center;
        const glm::vec2 local(std::cos(a) * d.x + std::sin(a) * d.y, -std::sin(a) * d.x + std::cos(a) * d.y);
        if (std::abs(local.x) < o.size.x * 0.5f + r && std::abs(local.y) < o.size.y * 0.5f + r)
            return true;
    }
    return false;
}

std::vector<sim::Agent> placeDab(const sim::Scene& scene, const std::vector<sim::Agent>& extra, glm::vec2 centre,
                                 glm::vec2 strokeDir, const CrowdBrushSettings& settings, std::uint64_t seed)
{
    const float r = std::max(settings.radiusM, 0.01f);
    const float reach = r + settings.minSpacingM;
    std::vector<glm::vec2> near;  // agents that may be too close to a candidate
    int inside = 0;
    auto consider = [&](const sim::Agent& a) {
        const glm::vec2 p(a.position.x, a.position.z);
        const float d = glm::length(p - centre);
        if (d <= reach)
            near.push_back(p);
        if (d <= r)
            ++inside;
    };
    for (const sim::Agent& a : scene.agents)
        consider(a);
    for (const sim::Agent& a : extra)
        consider(a);

    const int wanted = int(std::lround(settings.densityPerM2 * std::numbers::pi_v<float> * r * r)) - inside;
    std::vector<sim::Agent> out;
    if (wanted <= 0)
        return out;
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    const float spacing2 = settings.minSpacingM * settings.minSpacingM;
    for (int tries = wanted * kTriesPerAgent; tries > 0 && int(out.size()) < wanted; --tries) {
        // Uniform in the disk: sqrt of a uniform radius fraction.
        const float rho = r * std::sqrt(unit(rng)), phi = 2.0f * std::numbers::pi_v<float> * unit(rng);
        const glm::vec2 p = centre + rho * glm::vec2(std::cos(phi), std::sin(phi));
        const float typeDraw = unit(rng), headingDraw = unit(rng);
        const std::string type = chooseType(scene, settings.mix, typeDraw);
        const sim::AgentType* agentType = scene.findAgentType(type);
        if (!agentType || isBlocked(scene, p, agentType->radiusM))
            continue;
        const bool crowded = std::any_of(near.begin(), near.end(), [&](glm::vec2 q) {
            const glm::vec2 d = q - p;
            return glm::dot(d, d) < spacing2;
        });
        if (crowded)
            continue;
        float headingRad = 2.0f * std::numbers::pi_v<float> * headingDraw;
        glm::vec2 facing(0.0f);
        if (settings.heading == HeadingMode::AlongStroke)
            facing = strokeDir;
        else if (settings.heading == HeadingMode::TowardPoint)
            facing = settings.towardPoint - p;
        if (glm::length(facing) > 1e-6f)
            headingRad = std::atan2(-facing.y, facing.x);
        sim::Agent agent;
        agent.type = type;
        agent.position = glm::vec3(p.x, terrainHeight(scene.terrain, p.x, p.y), p.y);
        agent.headingDeg = glm::degrees(headingRad);
        out.push_back(agent);
        near.push_back(p);
    }
    return out;
}

}  // namespace throng::editor
