// The set's geometry: goals, paths, walls, obstacles, terrain and flow strokes.
#include "simcore/io/detail/SetReader.h"

#include <cmath>

namespace throng::sim::detail {

void SetReader::readGoals(const YAML::Node& node, Scene& scene)
{
    if (!m_f.expectSequence(node, "goals"))
        return;
    for (std::size_t i = 0; i < node.size(); ++i) {
        const std::string key = indexKey("goals", i);
        const YAML::Node item = node[i];
        if (!m_f.expectMap(item, key))
            continue;
        m_f.checkKeys(item, key, {"name", "position", "radius", "exit"});
        Goal g;
        if (m_f.readName(item, "name", key, g.name, true))
            m_names.claim(item, key, g.name, "goal");
        m_f.readVec2(item, "position", key, g.position, true);
        m_f.readFloat(item, "radius", key, g.radiusM, false, Range::Positive);
        m_f.readBool(item, "exit", key, g.exit, false);
        scene.goals.push_back(std::move(g));
    }
}

void SetReader::readPaths(const YAML::Node& node, Scene& scene)
{
    if (!m_f.expectSequence(node, "paths"))
        return;
    for (std::size_t i = 0; i < node.size(); ++i) {
        const std::string key = indexKey("paths", i);
        const YAML::Node item = node[i];
        if (!m_f.expectMap(item, key))
            continue;
        m_f.checkKeys(item, key, {"name", "points", "radius", "closed", "plan", "clearance", "exit"});
        Path p;
        if (m_f.readName(item, "name", key, p.name, true))
            m_names.claim(item, key, p.name, "path");
        m_f.readPolyline(item, "points", key, p.points, true, 2);
        m_f.readFloat(item, "radius", key, p.radiusM, false, Range::Positive);
        m_f.readBool(item, "closed", key, p.closed, false);
        std::string plan = "none";
        if (m_f.readString(item, "plan", key, plan, false)) {
            if (plan == "astar")
                p.planned = true;
            else if (plan != "none")
                m_f.error(item["plan"].Mark(), key + ".plan", "must be none or astar, got '" + plan + "'");
        }
        m_f.readFloat(item, "clearance", key, p.clearanceM, false, Range::Positive);
        if (m_f.readBool(item, "exit", key, p.exit, false) && p.exit && p.closed)
            m_f.error(item["exit"].Mark(), key + ".exit", "a closed path has no end to leave by");
        scene.paths.push_back(std::move(p));
    }
}

void SetReader::readWalls(const YAML::Node& node, Scene& scene)
{
    if (!m_f.expectSequence(node, "walls"))
        return;
    for (std::size_t i = 0; i < node.size(); ++i) {
        const std::string key = indexKey("walls", i);
        const YAML::Node item = node[i];
        if (!m_f.expectMap(item, key))
            continue;
        m_f.checkKeys(item, key, {"name", "points", "height"});
        Wall w;
        m_f.readName(item, "name", key, w.name, false);
        m_f.readPolyline(item, "points", key, w.points, true, 2);
        m_f.readFloat(item, "height", key, w.heightM, false, Range::Positive);
        scene.walls.push_back(std::move(w));
    }
}

void SetReader::readObstacles(const YAML::Node& node, Scene& scene)
{
    if (!m_f.expectSequence(node, "obstacles"))
        return;
    for (std::size_t i = 0; i < node.size(); ++i) {
        const std::string key = indexKey("obstacles", i);
        const YAML::Node item = node[i];
        if (!m_f.expectMap(item, key))
            continue;
        m_f.checkKeys(item, key, {"name", "shape", "center", "radius", "size", "angle"});
        Obstacle o;
        m_f.readName(item, "name", key, o.name, false);
        std::string shape = "circle";
        if (m_f.readString(item, "shape", key, shape, false)) {
            if (shape == "circle") o.shape = ObstacleShape::Circle;
            else if (shape == "box") o.shape = ObstacleShape::Box;
            else m_f.error(item["shape"].Mark(), key + ".shape", "must be circle or box, got '" + shape + "'");
        }
        m_f.readVec2(item, "center", key, o.center, true);
        // Keys of the other shape would be silently ignored; say so.
        static const std::vector<const char*> kBoxOnly{"size", "angle"}, kCircleOnly{"radius"};
        for (const char* other : o.shape == ObstacleShape::Circle ? kBoxOnly : kCircleOnly)
            if (item[other].IsDefined())
                m_f.warning(item[other].Mark(), key + "." + other,
                            std::string("'") + other + "' is ignored for a " + shape + " obstacle");
        if (o.shape == ObstacleShape::Circle) {
            m_f.readFloat(item, "radius", key, o.radiusM, true, Range::Positive);
        } else {
            m_f.readVec2(item, "size", key, o.size, true, Range::Positive);
            m_f.readFloat(item, "angle", key, o.angleDeg, false);
        }
        scene.obstacles.push_back(std::move(o));
    }
}

void SetReader::readTerrain(const YAML::Node& node, Terrain& t)
{
    const std::string key = "terrain";
    if (!m_f.expectMap(node, key))
        return;
    m_f.checkKeys(node, key, {"origin", "cell", "cols", "rows", "heights"});
    m_f.readVec2(node, "origin", key, t.origin, false);
    m_f.readFloat(node, "cell", key, t.cellM, false, Range::Positive);
    const bool dims = m_f.readU32(node, "cols", key, t.cols, true) & m_f.readU32(node, "rows", key, t.rows, true);
    if (!m_f.readFloatList(node, "heights", key, t.heights, true) || !dims)
        return;
    if (t.cols < 2 || t.rows < 2)
        m_f.error(node.Mark(), key, "needs at least 2 columns and 2 rows of height samples");
    else if (std::uint64_t(t.cols) * t.rows != t.heights.size())
        m_f.error(node["heights"].Mark(), key + ".heights",
                  "has " + std::to_string(t.heights.size()) + " samples but cols x rows = " +
                      std::to_string(std::uint64_t(t.cols) * t.rows));
}

void SetReader::readFlowStrokes(const YAML::Node& node, Scene& scene)
{
    if (!m_f.expectSequence(node, "flow_strokes"))
        return;
    for (std::size_t i = 0; i < node.size(); ++i) {
        const std::string key = indexKey("flow_strokes", i);
        const YAML::Node item = node[i];
        if (!m_f.expectMap(item, key))
            continue;
        m_f.checkKeys(item, key, {"points", "width"});
        FlowStroke s;
        m_f.readPolyline(item, "points", key, s.points, true, 2);
        m_f.readFloat(item, "width", key, s.widthM, false, Range::Positive);
        scene.flowStrokes.push_back(std::move(s));
    }
}

}  // namespace throng::sim::detail
