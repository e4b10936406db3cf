#include "simcore/io/detail/SceneSizeCheck.h"

#include "simcore/io/SceneLimits.h"
#include "simcore/scene/SpawnArea.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace throng::sim::detail {

namespace {

std::string withCommas(double v)
{
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.0f", std::min(v, 1e30));
    const std::string s = buf;
    std::string out;
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (i > 0 && (s.size() - i) % 3 == 0)
            out += ',';
        out += s[i];
    }
    return out;
}

// root[name], or an empty node where it is missing (yaml-cpp throws on a missing key's
// node for anything but IsDefined()).
YAML::Node section(const YAML::Node& root, const char* name)
{
    if (root.IsMap())
        if (YAML::Node n = root[name]; n.IsDefined())
            return n;
    return YAML::Node();
}

// The first of `names` that the map holds, else the map itself, else `fallback` (a
// missing section): where a size is set.
YAML::Mark markOf(const YAML::Node& map, std::initializer_list<const char*> names, const YAML::Mark& fallback)
{
    if (map.IsMap())
        for (const char* n : names)
            if (YAML::Node v = map[n]; v.IsDefined())
                return v.Mark();
    return map.IsMap() || map.IsSequence() || map.IsScalar() ? map.Mark() : fallback;
}

bool usesNavGrid(const Scene& scene)
{
    if (!scene.flowStrokes.empty())
        return true;
    for (const Path& p : scene.paths)
        if (p.planned)
            return true;
    for (const AgentType& t : scene.agentTypes)
        if (t.kind == AgentKind::Pedestrian && t.navigation != Navigation::Direct)
            return true;
    return false;
}

// Metres outside the bounds (0 inside).
float outsideM(glm::vec2 p, const Settings& s)
{
    const glm::vec2 d = glm::max(glm::max(s.boundsMin - p, p - s.boundsMax), glm::vec2(0.0f));
    return std::max(d.x, d.y);
}

void checkNavGrid(YamlFields& f, const YAML::Node& root, const Scene& scene)
{
    if (!usesNavGrid(scene))
        return;
    const Settings& s = scene.settings;
    const double cell = s.navCellM > 0.0f ? double(s.navCellM) : 1.0;
    const double w = double(s.boundsMax.x) - double(s.boundsMin.x), d = double(s.boundsMax.y) - double(s.boundsMin.y);
    const double cells = std::ceil(std::max(w, 0.0) / cell) * std::ceil(std::max(d, 0.0) / cell);
    if (!(cells > double(kMaxNavCells)))
        return;
    const YAML::Node settings = section(root, "settings");
    const bool own = settings.IsMap() && settings["nav_cell"].IsDefined();
    char size[96];
    std::snprintf(size, sizeof size, "%g x %g m at %g m a cell", w, d, cell);
    f.error(markOf(settings, {"nav_cell", "bounds"}, root.Mark()),
            own ? "settings.nav_cell" : "settings.bounds",
            "the navigation grid would need " + withCommas(cells) + " cells (" + size + "), more than " +
                withCommas(double(kMaxNavCells)) + ": raise nav_cell or shrink the bounds");
}

void checkAgents(YamlFields& f, const YAML::Node& root, const Scene& scene)
{
    double total = double(scene.agents.size()) + double(scene.vehicles.size()) + double(scene.heroes.size());
    const YAML::Node groups = section(root, "groups");
    for (std::size_t i = 0; i < scene.groups.size(); ++i) {
        total += double(scene.groups[i].count);
        if (total <= double(kMaxSceneAgents))
            continue;
        const bool located = groups.IsSequence() && groups.size() == scene.groups.size();
        f.error(located ? markOf(groups[i], {"count"}, root.Mark()) : root.Mark(),
                "groups[" + std::to_string(i) + "].count",
                "the scene would hold " + withCommas(total) + " agents with this group, more than " +
                    withCommas(double(kMaxSceneAgents)));
        return;
    }
}

// A group packed far past the bodies' own packing: every agent would have thousands of
// neighbours within reach, and each step would crawl (10,000,000 walkers on a 100 m
// square ran for hours). Fliers pack in the volume their altitude range spans.
void checkGroupDensity(YamlFields& f, const YAML::Node& root, const Scene& scene)
{
    const YAML::Node groups = section(root, "groups");
    const bool located = groups.IsSequence() && groups.size() == scene.groups.size();
    for (std::size_t i = 0; i < scene.groups.size(); ++i) {
        const SpawnGroup& g = scene.groups[i];
        const AgentType* type = nullptr;
        for (const AgentType& t : scene.agentTypes)
            if (t.name == g.type)
                type = &t;
        if (!type || g.count <= kDenseGroupFloor)
            continue;
        const double r = std::max(double(type->radiusM), 0.01);
        const double area = spawnAreaM2(g);
        const bool flier = type->kind == AgentKind::Flier;
        // Hexagonal packing of discs on the ground, face-centred packing of balls in the air.
        const double height = std::max(double(g.altitudeM.y - g.altitudeM.x), 2.0 * r);
        const double fit = flier ? area * height * 0.74 / (4.18879 * r * r * r) : area / (3.4641 * r * r);
        if (double(g.count) <= kDenseGroupFactor * fit)
            continue;
        char m[200];
        std::snprintf(
            m, sizeof m,
            "%u agents of radius %g m would start packed %.0f times as tight as bodies fit in %s (room for about %.0f)",
            g.count, r, double(g.count) / std::max(fit, 1e-9), flier ? "its area and altitude range" : "its area", fit);
        f.error(located ? markOf(groups[i], {"count"}, root.Mark()) : root.Mark(),
                "groups[" + std::to_string(i) + "].count", m);
    }
}

void checkFlowStrokes(YamlFields& f, const YAML::Node& root, const Scene& scene)
{
    const YAML::Node strokes = section(root, "flow_strokes");
    double total = 0.0;
    for (std::size_t i = 0; i < scene.flowStrokes.size(); ++i) {
        const std::vector<glm::vec2>& p = scene.flowStrokes[i].points;
        for (std::size_t k = 1; k < p.size(); ++k)
            total += glm::distance(glm::dvec2(p[k - 1]), glm::dvec2(p[k]));
        if (total <= kMaxFlowStrokeLengthM)
            continue;
        const bool located = strokes.IsSequence() && strokes.size() == scene.flowStrokes.size();
        f.error(located ? markOf(strokes[i], {"points"}, root.Mark()) : root.Mark(),
                "flow_strokes[" + std::to_string(i) + "]",
                "the flow strokes would be " + withCommas(total) + " m long with this one, more than " +
                    withCommas(kMaxFlowStrokeLengthM) + " m (the sketched field takes a sample a metre)");
        return;
    }
}

// Exact repeats count once in the World; far points only stretch its grids. Both are
// almost always a paste gone wrong, so the user hears of them.
void checkStatics(YamlFields& f, const YAML::Node& root, const Scene& scene)
{
    const YAML::Node walls = section(root, "walls"), obstacles = section(root, "obstacles");
    const bool wallsLocated = walls.IsSequence() && walls.size() == scene.walls.size();
    const bool obstaclesLocated = obstacles.IsSequence() && obstacles.size() == scene.obstacles.size();
    using Key = std::array<float, 6>;
    std::vector<std::pair<Key, std::size_t>> seen;  // key, owner index
    for (std::size_t i = 0; i < scene.walls.size(); ++i) {
        const std::vector<glm::vec2>& p = scene.walls[i].points;
        for (std::size_t k = 1; k < p.size(); ++k) {
            glm::vec2 a = p[k - 1], b = p[k];
            if (std::tie(b.x, b.y) < std::tie(a.x, a.y))
                std::swap(a, b);
            seen.push_back({Key{a.x, a.y, b.x, b.y, 0.0f, 0.0f}, i});
        }
    }
    auto warnRepeats = [&](std::vector<std::pair<Key, std::size_t>>& keys, const char* section, const YAML::Node& list,
                           bool located, const char* what) {
        std::stable_sort(keys.begin(), keys.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
        std::size_t repeats = 0, first = SIZE_MAX;
        for (std::size_t k = 1; k < keys.size(); ++k)
            if (keys[k].first == keys[k - 1].first) {
                ++repeats;
                first = std::min(first, keys[k].second);
            }
        if (repeats == 0)
            return;
        const std::string key = std::string(section) + "[" + std::to_string(first) + "]";
        f.warning(located ? list[first].Mark() : root.Mark(), key,
                  withCommas(double(repeats)) + " " + what +
                      " repeat an earlier one exactly; the simulation counts each once");
    };
    warnRepeats(seen, "walls", walls, wallsLocated, "wall segments");
    seen.clear();
    for (std::size_t i = 0; i < scene.obstacles.size(); ++i) {
        const Obstacle& o = scene.obstacles[i];
        seen.push_back(
            {Key{float(int(o.shape)), o.center.x, o.center.y, o.shape == ObstacleShape::Circle ? o.radiusM : o.size.x,
                 o.shape == ObstacleShape::Circle ? 0.0f : o.size.y,
                 o.shape == ObstacleShape::Circle ? 0.0f : o.angleDeg},
             i});
    }
    warnRepeats(seen, "obstacles", obstacles, obstaclesLocated, "obstacles");

    // A shape this large swallows any set agents walk in (pushing everyone inside it out
    // to its rim, kilometres away); it is a typo, and the steps would crawl.
    for (std::size_t i = 0; i < scene.obstacles.size(); ++i) {
        const Obstacle& o = scene.obstacles[i];
        const float extent = o.shape == ObstacleShape::Circle ? o.radiusM : std::max(o.size.x, o.size.y);
        if (extent > kMaxObstacleM) {
            const char* name = o.shape == ObstacleShape::Circle ? "radius" : "size";
            char m[96];
            std::snprintf(m, sizeof m, "%s %.3g m is larger than %.0f km", name, double(extent),
                          double(kMaxObstacleM) / 1000.0);
            f.error(obstaclesLocated ? markOf(obstacles[i], {name}, root.Mark()) : root.Mark(),
                    "obstacles[" + std::to_string(i) + "]." + name, m);
        }
    }

    int farWarnings = 0;
    auto warnFar = [&](const YAML::Node& list, bool located, const std::string& key, std::size_t i, float outside) {
        if (outside <= kFarGeometryM || ++farWarnings > 3)
            return;
        char m[64];
        std::snprintf(m, sizeof m, "%.3g m", double(outside));
        f.warning(located ? list[i].Mark() : root.Mark(), key,
                  std::string("lies ") + m + " outside the scene bounds; no agent comes near it (a typo?)");
    };
    for (std::size_t i = 0; i < scene.walls.size(); ++i) {
        float far = 0.0f;
        for (glm::vec2 p : scene.walls[i].points)
            far = std::max(far, outsideM(p, scene.settings));
        warnFar(walls, wallsLocated, "walls[" + std::to_string(i) + "]", i, far);
    }
    for (std::size_t i = 0; i < scene.obstacles.size(); ++i)
        warnFar(obstacles, obstaclesLocated, "obstacles[" + std::to_string(i) + "]", i,
                outsideM(scene.obstacles[i].center, scene.settings));
}

}  // namespace

void checkSceneSizes(YamlFields& f, const YAML::Node& root, const Scene& scene)
{
    checkNavGrid(f, root, scene);
    checkAgents(f, root, scene);
    checkGroupDensity(f, root, scene);
    checkFlowStrokes(f, root, scene);
    checkStatics(f, root, scene);
}

}  // namespace throng::sim::detail
