// The set's geometry and traffic: paths, walls, obstacles, goals, terrain, flow strokes,
// lanes, crosswalks, traffic lights, vehicles and heroes.
#include "simcore/io/detail/SceneReader.h"

#include <cmath>
#include <fstream>
#include <sstream>

namespace throng::sim::detail {

void SceneReader::readGoals(const YAML::Node& node, Scene& scene)
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
            claimName(item, key, g.name, "goal");
        m_f.readVec2(item, "position", key, g.position, true);
        m_f.readFloat(item, "radius", key, g.radiusM, false, Range::Positive);
        m_f.readBool(item, "exit", key, g.exit, false);
        scene.goals.push_back(std::move(g));
    }
}

void SceneReader::readPaths(const YAML::Node& node, Scene& scene)
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
            claimName(item, key, p.name, "path");
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

void SceneReader::readWalls(const YAML::Node& node, Scene& scene)
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

void SceneReader::readObstacles(const YAML::Node& node, Scene& scene)
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

void SceneReader::readTerrain(const YAML::Node& node, Terrain& t)
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

void SceneReader::readFlowStrokes(const YAML::Node& node, Scene& scene)
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

void SceneReader::readCarFollowing(const YAML::Node& item, const std::string& key, CarFollowing& out, bool inherit)
{
    std::string name;
    if (!m_f.readString(item, "car_following", key, name, false) || !item["car_following"].IsDefined())
        return;
    for (const CarFollowing m : {CarFollowing::Inherit, CarFollowing::Idm, CarFollowing::GapTime, CarFollowing::Fuzzy})
        if (name == toString(m) && (inherit || m != CarFollowing::Inherit)) {
            out = m;
            return;
        }
    m_f.error(item["car_following"].Mark(), key + ".car_following",
              std::string("must be ") + (inherit ? "inherit, " : "") + "idm, gap_time or fuzzy, got '" + name + "'");
}

void SceneReader::readTraffic(const YAML::Node& node, TrafficSettings& t)
{
    const std::string key = "traffic";
    if (!m_f.expectMap(node, key))
        return;
    m_f.checkKeys(node, key, {"car_following", "driver_start_delay", "walker_start_delay", "crossing_margin",
                              "walker_clearance", "waiting_speed", "yield_horizon"});
    readCarFollowing(node, key, t.carFollowing, false);
    for (auto [name, range] : {std::pair{"driver_start_delay", &t.driverStartDelayS},
                               std::pair{"walker_start_delay", &t.walkerStartDelayS}})
        if (m_f.readVec2(node, name, key, *range, false, Range::NonNegative) && range->x > range->y)
            m_f.error(node[name].Mark(), key + "." + name, "the minimum (first) must not exceed the maximum");
    m_f.readFloat(node, "crossing_margin", key, t.crossingMarginM, false, Range::NonNegative);
    m_f.readFloat(node, "walker_clearance", key, t.walkerClearanceM, false, Range::NonNegative);
    m_f.readFloat(node, "waiting_speed", key, t.waitingSpeed, false, Range::NonNegative);
    m_f.readFloat(node, "yield_horizon", key, t.yieldHorizonS, false, Range::Positive);
}

void SceneReader::readLanes(const YAML::Node& node, Scene& scene)
{
    if (!m_f.expectSequence(node, "lanes"))
        return;
    for (std::size_t i = 0; i < node.size(); ++i) {
        const std::string key = indexKey("lanes", i);
        const YAML::Node item = node[i];
        if (!m_f.expectMap(item, key))
            continue;
        m_f.checkKeys(item, key, {"name", "points", "width", "speed_limit", "loop", "car_following"});
        Lane l;
        if (m_f.readName(item, "name", key, l.name, true))
            claimName(item, key, l.name, "lane");
        m_f.readPolyline(item, "points", key, l.points, true, 2);
        m_f.readFloat(item, "width", key, l.widthM, false, Range::Positive);
        m_f.readFloat(item, "speed_limit", key, l.speedLimit, false, Range::Positive);
        m_f.readBool(item, "loop", key, l.loop, false);
        readCarFollowing(item, key, l.carFollowing, true);
        scene.lanes.push_back(std::move(l));
    }
}

void SceneReader::readCrosswalks(const YAML::Node& node, Scene& scene)
{
    if (!m_f.expectSequence(node, "crosswalks"))
        return;
    for (std::size_t i = 0; i < node.size(); ++i) {
        const std::string key = indexKey("crosswalks", i);
        const YAML::Node item = node[i];
        if (!m_f.expectMap(item, key))
            continue;
        m_f.checkKeys(item, key, {"name", "from", "to", "width"});
        Crosswalk c;
        if (m_f.readName(item, "name", key, c.name, true))
            claimName(item, key, c.name, "crosswalk");
        const bool ends = m_f.readVec2(item, "from", key, c.from, true) & m_f.readVec2(item, "to", key, c.to, true);
        m_f.readFloat(item, "width", key, c.widthM, false, Range::Positive);
        if (ends && c.from == c.to)
            m_f.error(item.Mark(), key, "'from' and 'to' are the same point");
        scene.crosswalks.push_back(std::move(c));
    }
}

void SceneReader::readTrafficLights(const YAML::Node& node, Scene& scene)
{
    if (!m_f.expectSequence(node, "traffic_lights"))
        return;
    for (std::size_t i = 0; i < node.size(); ++i) {
        const std::string key = indexKey("traffic_lights", i);
        const YAML::Node item = node[i];
        if (!m_f.expectMap(item, key))
            continue;
        m_f.checkKeys(item, key, {"name", "green", "yellow", "red", "offset", "position", "stop_lines"});
        TrafficLight t;
        if (m_f.readName(item, "name", key, t.name, true))
            claimName(item, key, t.name, "traffic light");
        m_f.readFloat(item, "green", key, t.greenS, false, Range::NonNegative);
        m_f.readFloat(item, "yellow", key, t.yellowS, false, Range::NonNegative);
        m_f.readFloat(item, "red", key, t.redS, false, Range::NonNegative);
        m_f.readFloat(item, "offset", key, t.offsetS, false);
        m_f.readVec2(item, "position", key, t.position, false);
        if (t.greenS + t.yellowS + t.redS <= 0.0f)
            m_f.error(item.Mark(), key, "the phases green + yellow + red must last longer than 0 s");
        if (YAML::Node lines = item["stop_lines"];
            lines.IsDefined() && m_f.expectSequence(lines, key + ".stop_lines")) {
            for (std::size_t j = 0; j < lines.size(); ++j) {
                const std::string lk = indexKey(key + ".stop_lines", j);
                const YAML::Node line = lines[j];
                if (!m_f.expectMap(line, lk))
                    continue;
                m_f.checkKeys(line, lk, {"lane", "at", "crosswalk"});
                StopLine s;
                if (!m_f.readName(line, "lane", lk, s.lane, false) ||
                    !m_f.readName(line, "crosswalk", lk, s.crosswalk, false))
                    continue;
                if (s.lane.empty() == s.crosswalk.empty()) {
                    m_f.error(line.Mark(), lk, "a stop line names exactly one of 'lane' or 'crosswalk'");
                    continue;
                }
                if (!s.crosswalk.empty() && line["at"].IsDefined())
                    m_f.warning(line["at"].Mark(), lk + ".at", "'at' is ignored for a crosswalk stop line");
                if (!s.lane.empty()) {
                    checkRef(line, "lane", lk, s.lane, scene.findLane(s.lane) != nullptr, "lane");
                    m_f.readFloat(line, "at", lk, s.atM, true, Range::NonNegative);
                } else {
                    checkRef(line, "crosswalk", lk, s.crosswalk, scene.findCrosswalk(s.crosswalk) != nullptr,
                             "crosswalk");
                }
                t.stopLines.push_back(std::move(s));
            }
        }
        scene.trafficLights.push_back(std::move(t));
    }
}

void SceneReader::readVehicles(const YAML::Node& node, Scene& scene)
{
    if (!m_f.expectSequence(node, "vehicles"))
        return;
    for (std::size_t i = 0; i < node.size(); ++i) {
        const std::string key = indexKey("vehicles", i);
        const YAML::Node item = node[i];
        if (!m_f.expectMap(item, key))
            continue;
        m_f.checkKeys(item, key, {"id", "type", "lane", "at", "speed"});
        Vehicle v;
        if (YAML::Node id = item["id"]; id.IsDefined() && m_f.readU32(item, "id", key, v.id, false))
            claimId(id, key + ".id", v.id);
        if (m_f.readName(item, "type", key, v.type, true)) {
            const AgentType* type = scene.findAgentType(v.type);
            if (checkRef(item, "type", key, v.type, type != nullptr, "agent type") && type->kind != AgentKind::Vehicle)
                m_f.error(item["type"].Mark(), key + ".type", "agent type '" + v.type + "' is not of kind vehicle");
        }
        if (m_f.readName(item, "lane", key, v.lane, true))
            checkRef(item, "lane", key, v.lane, scene.findLane(v.lane) != nullptr, "lane");
        m_f.readFloat(item, "at", key, v.atM, false, Range::NonNegative);
        m_f.readFloat(item, "speed", key, v.speed, false, Range::NonNegative);
        scene.vehicles.push_back(std::move(v));
    }
}

void SceneReader::readHeroes(const YAML::Node& node, Scene& scene)
{
    if (!m_f.expectSequence(node, "heroes"))
        return;
    for (std::size_t i = 0; i < node.size(); ++i) {
        const std::string key = indexKey("heroes", i);
        const YAML::Node item = node[i];
        if (!m_f.expectMap(item, key))
            continue;
        m_f.checkKeys(item, key, {"id", "name", "type", "clearance", "keyframes", "keyframes_file"});
        Hero h;
        if (YAML::Node id = item["id"]; id.IsDefined() && m_f.readU32(item, "id", key, h.id, false))
            claimId(id, key + ".id", h.id);
        if (m_f.readName(item, "name", key, h.name, true))
            claimName(item, key, h.name, "hero");
        if (m_f.readName(item, "type", key, h.type, true))
            checkRef(item, "type", key, h.type, scene.findAgentType(h.type) != nullptr, "agent type");
        m_f.readFloat(item, "clearance", key, h.clearanceM, false, Range::NonNegative);
        const YAML::Node keys = item["keyframes"];
        const YAML::Node file = item["keyframes_file"];
        if (keys.IsDefined() == file.IsDefined()) {
            m_f.error(item.Mark(), key, "give exactly one of 'keyframes' or 'keyframes_file'");
        } else if (file.IsDefined()) {
            if (m_f.readString(item, "keyframes_file", key, h.keyframesFile, true))
                readHeroKeyframesFile(file, key + ".keyframes_file", scene.settings.fps, h);
        } else if (m_f.expectSequence(keys, key + ".keyframes")) {
            for (std::size_t j = 0; j < keys.size(); ++j) {
                const std::string kk = indexKey(key + ".keyframes", j);
                const YAML::Node k = keys[j];
                if (!m_f.expectMap(k, kk))
                    continue;
                m_f.checkKeys(k, kk, {"time", "position"});
                Keyframe kf;
                if (!m_f.readFloat(k, "time", kk, kf.timeS, true, Range::NonNegative) ||
                    !m_f.readPoint3(k, "position", kk, kf.position, true))
                    continue;
                if (!h.keyframes.empty() && kf.timeS <= h.keyframes.back().timeS)
                    m_f.error(k["time"].Mark(), kk + ".time", "keyframe times must increase");
                h.keyframes.push_back(kf);
            }
            if (h.keyframes.empty())
                m_f.error(keys.Mark(), key + ".keyframes", "a hero needs at least one keyframe");
        }
        scene.heroes.push_back(std::move(h));
    }
}

void SceneReader::readHeroKeyframesFile(const YAML::Node& at, const std::string& key, float fps, Hero& hero)
{
    // One "x y z" line per frame, as Maya writes it: frame n is at time n / fps.
    const std::string full = resolvePath(m_baseDir, hero.keyframesFile);
    std::ifstream in(full);
    if (!in) {
        m_f.error(at.Mark(), key, "cannot open keyframes file '" + full + "'");
        return;
    }
    std::string line;
    int lineNo = 0;
    while (std::getline(in, line)) {
        ++lineNo;
        if (line.find_first_not_of(" \t\r") == std::string::npos || line[line.find_first_not_of(" \t")] == '#')
            continue;
        std::istringstream ss(line);
        std::string tok[3], extra;
        ss >> tok[0] >> tok[1] >> tok[2];
        glm::vec3 p;
        std::string why;
        bool ok = !tok[2].empty() && !(ss >> extra);
        for (int c = 0; ok && c < 3; ++c)
            ok = parseFiniteFloat(tok[c], p[c], why);
        if (!ok) {
            std::vector<Diagnostic> sub;
            sub.push_back({Severity::Error, full, lineNo, 1, "", why.empty() ? "expected 'x y z'" : why});
            m_f.error(at.Mark(), key, "in keyframes file: " + sub[0].format());
            return;
        }
        hero.keyframes.push_back({float(double(hero.keyframes.size()) / fps), p});
    }
    if (hero.keyframes.empty())
        m_f.error(at.Mark(), key, "keyframes file '" + full + "' has no keyframes");
}

}  // namespace throng::sim::detail
