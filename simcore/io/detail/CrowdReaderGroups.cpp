// Spawn groups (`groups`): their type and count, their area (a rectangle, a circle or a
// polygon), their route (a goal, a path or a leader) and the exits they may choose among
// instead (Scene.h, SpawnGroup); sources read their exits and rectangles here too.
#include "simcore/io/detail/CrowdReader.h"

#include "simcore/scene/GroundPolygon.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace throng::sim::detail {

namespace {

constexpr std::uint32_t kMaxSpawnCount = 10'000'000;
constexpr double kMinPolygonAreaM2 = 1e-6;  // a spawn polygon smaller than a square millimetre has none

}  // namespace

void CrowdReader::readGroups(const YAML::Node& node, Scene& scene)
{
    if (!m_f.expectSequence(node, "groups"))
        return;
    for (std::size_t i = 0; i < node.size(); ++i) {
        const std::string key = indexKey("groups", i);
        const YAML::Node item = node[i];
        if (!m_f.expectMap(item, key))
            continue;
        m_f.checkKeys(
            item, key,
            {"name", "type", "count", "rect", "circle", "shape", "points", "goal", "path", "leader", "altitude",
             "exits", "formation", "companions"});
        SpawnGroup g;
        if (m_f.readName(item, "name", key, g.name, true))
            m_names.claim(item, key, g.name, "group");
        if (m_f.readName(item, "type", key, g.type, true))
            m_names.checkKnown(item, "type", key, g.type, "agent type");
        if (m_f.readU32(item, "count", key, g.count, true) && g.count > kMaxSpawnCount)
            m_f.error(item["count"].Mark(), key + ".count", "at most 10,000,000 agents per group");
        readGroupArea(item, key, g);
        if (m_f.readName(item, "goal", key, g.goal, false) && !g.goal.empty())
            m_names.checkKnown(item, "goal", key, g.goal, "goal");
        if (m_f.readName(item, "path", key, g.path, false) && !g.path.empty())
            m_names.checkKnown(item, "path", key, g.path, "path");
        if (m_f.readU32(item, "leader", key, g.leader, false) && item["leader"].IsDefined())
            m_names.leads(item["leader"].Mark(), key + ".leader", g.leader);
        readExits(item, key, g.exits, !g.goal.empty() || !g.path.empty() || g.leader != 0, "goal, path or leader",
                  scene);
        if (!g.exits.empty() && scene.brainPicksGoals(g.type))
            m_f.warning(item["exits"].Mark(), key + ".exits",
                        "the brain of type '" + g.type + "' picks its agents' goals: they do not choose among exits");
        if (item["altitude"].IsDefined() &&
            m_f.readVec2(item, "altitude", key, g.altitudeM, false, Range::NonNegative)) {
            const AgentType* type = scene.findAgentType(g.type);
            if (g.altitudeM.x > g.altitudeM.y)
                m_f.error(item["altitude"].Mark(), key + ".altitude", "range [min, max] has min greater than max");
            else if (type && type->kind != AgentKind::Flier)
                m_f.warning(item["altitude"].Mark(), key + ".altitude",
                            "'altitude' only affects fliers and is ignored here");
        }
        readKeepingTogether(item, key, scene, g);
        scene.groups.push_back(std::move(g));
    }
}

// `formation: {shape, spacing, width}` or `companions: [min, max]` (Formations.h): walkers
// only, one of the two, and a group that walks to one place (no exits to choose among).
void CrowdReader::readKeepingTogether(const YAML::Node& item, const std::string& key, const Scene& scene,
                                      SpawnGroup& g)
{
    const YAML::Node formation = item["formation"], companions = item["companions"];
    if (!formation.IsDefined() && !companions.IsDefined())
        return;
    const AgentType* type = scene.findAgentType(g.type);
    const char* which = formation.IsDefined() ? "formation" : "companions";
    if (formation.IsDefined() && companions.IsDefined()) {
        m_f.error(companions.Mark(), key + ".companions", "give a formation or companions, not both");
        return;
    }
    // Walkers keep together either way; fliers fly in formation (a school's arrow).
    if (type && (type->kind == AgentKind::Vehicle ||
                 (companions.IsDefined() && type->kind != AgentKind::Pedestrian))) {
        const std::string what = companions.IsDefined() ? "only walkers walk as companions"
                                                        : "vehicles hold no formation";
        m_f.error(item[which].Mark(), key + "." + which,
                  what + "; '" + g.type + "' is a " + toString(type->kind) + " type");
        return;
    }
    if (!g.exits.empty()) {
        m_f.error(item[which].Mark(), key + "." + which,
                  "members that keep together walk to one place: give a goal or a path, not exits");
        return;
    }
    if (companions.IsDefined()) {
        glm::vec2 size(0.0f);
        if (!m_f.readVec2(item, "companions", key, size, false, Range::Positive))
            return;
        if (size.x != std::floor(size.x) || size.y != std::floor(size.y) || size.x > size.y || size.y < 2.0f ||
            size.y > 8.0f)
            m_f.error(companions.Mark(), key + ".companions",
                      "give [min, max] walkers per small group, whole numbers with 1 <= min <= max, 2 <= max <= 8");
        else {
            g.companions = glm::uvec2(size);
            if (g.leader != 0)
                m_f.warning(companions.Mark(), key + ".companions",
                            "companions walk with each other: they follow their leader only once their own have "
                            "arrived");
        }
        return;
    }
    if (!m_f.expectMap(formation, key + ".formation"))
        return;
    const std::string fk = key + ".formation";
    m_f.checkKeys(formation, fk, {"shape", "spacing", "width"});
    std::string shape;
    if (!m_f.readName(formation, "shape", fk, shape, true))
        return;
    if (shape == "line")
        g.formation.shape = FormationShape::Line;
    else if (shape == "column")
        g.formation.shape = FormationShape::Column;
    else if (shape == "wedge")
        g.formation.shape = FormationShape::Wedge;
    else {
        m_f.error(formation["shape"].Mark(), fk + ".shape", "must be 'line', 'column' or 'wedge'");
        return;
    }
    if (m_f.readFloat(formation, "spacing", fk, g.formation.spacingM, false, Range::Positive) && type &&
        g.formation.spacingM < 2.0f * type->radiusM) {
        char body[32];
        std::snprintf(body, sizeof body, "%.2f", double(2.0f * type->radiusM));
        m_f.error(formation["spacing"].Mark(), fk + ".spacing",
                  std::string("closer than two of its walkers' bodies (") + body +
                      " m): they could not stand in their slots");
    }
    if (formation["width"].IsDefined()) {
        if (m_f.readU32(formation, "width", fk, g.formation.width, false) && g.formation.width == 0)
            m_f.error(formation["width"].Mark(), fk + ".width", "at least 1 walker a row");
        if (g.formation.shape != FormationShape::Column)
            m_f.warning(formation["width"].Mark(), fk + ".width", "only a column has rows of a set width");
    }
    if (g.goal.empty() && g.path.empty() && g.leader == 0)
        m_f.warning(formation.Mark(), fk, "has no goal, path or leader: the formation forms where it stands");
}

void CrowdReader::readExits(const YAML::Node& item, const std::string& key, std::vector<std::string>& names,
                            bool routed, const char* route, const Scene& scene)
{
    if (!item["exits"].IsDefined() || !m_f.readStringList(item, "exits", key, names, false))
        return;
    const YAML::Node exits = item["exits"];
    if (names.size() < 2)
        m_f.error(exits.Mark(), key + ".exits", "list at least two exits to choose among");
    if (routed)
        m_f.error(exits.Mark(), key + ".exits", std::string("the agents choose their exit: give no ") + route + " too");
    for (std::size_t k = 0; k < names.size(); ++k) {
        const std::string ek = indexKey(key + ".exits", k);
        const Goal* goal = scene.findGoal(names[k]);
        if (!goal)
            m_f.error(exits[k].Mark(), ek, "no goal named '" + names[k] + "'");
        else if (!goal->exit)
            m_f.error(exits[k].Mark(), ek, "goal '" + names[k] + "' is not an exit (exit: true)");
        for (std::size_t j = 0; j < k; ++j)
            if (names[j] == names[k])
                m_f.error(exits[k].Mark(), ek, "'" + names[k] + "' is listed twice");
    }
}

void CrowdReader::readRect(const YAML::Node& rect, const std::string& key, glm::vec2& min, glm::vec2& max)
{
    m_f.checkKeys(rect, key, {"min", "max"});
    if (m_f.readVec2(rect, "min", key, min, true) && m_f.readVec2(rect, "max", key, max, true) &&
        (min.x > max.x || min.y > max.y))
        m_f.error(rect.Mark(), key, "min must not exceed max");
}

void CrowdReader::readGroupArea(const YAML::Node& item, const std::string& key, SpawnGroup& g)
{
    const YAML::Node rect = item["rect"], circle = item["circle"], shape = item["shape"], points = item["points"];
    const bool polygon = shape.IsDefined() || points.IsDefined();
    if (int(rect.IsDefined()) + int(circle.IsDefined()) + int(polygon) != 1) {
        m_f.error(item.Mark(), key, "give exactly one spawn area: 'rect', 'circle' or 'shape: polygon' with 'points'");
    } else if (rect.IsDefined() && m_f.expectMap(rect, key + ".rect")) {
        g.shape = AreaShape::Rect;
        readRect(rect, key + ".rect", g.min, g.max);
    } else if (circle.IsDefined() && m_f.expectMap(circle, key + ".circle")) {
        g.shape = AreaShape::Circle;
        m_f.checkKeys(circle, key + ".circle", {"center", "radius"});
        m_f.readVec2(circle, "center", key + ".circle", g.center, true);
        m_f.readFloat(circle, "radius", key + ".circle", g.radiusM, true, Range::Positive);
    } else if (polygon) {
        readGroupPolygon(item, key, g);
    }
}

// A polygon is given by a shape key (not a map like rect and circle) so that its corners
// read as every other list of points in the file does.
void CrowdReader::readGroupPolygon(const YAML::Node& item, const std::string& key, SpawnGroup& g)
{
    std::string shape;
    if (!m_f.readString(item, "shape", key, shape, true))
        return;
    if (shape != "polygon") {
        m_f.error(item["shape"].Mark(), key + ".shape",
                  "unknown shape '" + shape + "': 'polygon' (a rectangle or circle is a 'rect' or 'circle' map)");
        return;
    }
    g.shape = AreaShape::Polygon;
    if (!m_f.readPolyline(item, "points", key, g.points, true, 3))
        return;
    const YAML::Mark at = item["points"].Mark();
    // Corners all on one line fold back over themselves; say what is wrong with that
    // rather than where the fold is.
    const double area = polygonArea(g.points);
    const bool flat = area < kMinPolygonAreaM2 && std::all_of(g.points.begin(), g.points.end(), [&](glm::vec2 p) {
        const glm::dvec2 a(g.points.front()), b(g.points[g.points.size() / 2]), q(p);
        return std::abs((b.x - a.x) * (q.y - a.y) - (b.y - a.y) * (q.x - a.x)) <= kMinPolygonAreaM2;
    });
    if (flat) {
        m_f.error(at, key + ".points", "the polygon has no area: its corners lie on one line");
    } else if (const auto crossing = polygonSelfCrossing(g.points)) {
        const std::size_t n = g.points.size(), i = crossing->first, j = crossing->second;
        auto edge = [n](std::size_t e) {
            return "points[" + std::to_string(e) + "]-points[" + std::to_string((e + 1) % n) + "]";
        };
        m_f.error(at, key + ".points", "the polygon crosses itself: edge " + edge(i) + " meets edge " + edge(j));
    } else if (area < kMinPolygonAreaM2) {
        m_f.error(at, key + ".points", "the polygon has no area (under a square millimetre)");
    }
}

}  // namespace throng::sim::detail
