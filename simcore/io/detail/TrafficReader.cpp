// The traffic: its settings, lanes, crosswalks, traffic lights and vehicles.
#include "simcore/io/detail/TrafficReader.h"

#include <cmath>

namespace throng::sim::detail {

void readCarFollowing(YamlFields& f, const YAML::Node& item, const std::string& key, CarFollowing& out, bool inherit)
{
    std::string name;
    if (!f.readString(item, "car_following", key, name, false) || !item["car_following"].IsDefined())
        return;
    for (const CarFollowing m : {CarFollowing::Inherit, CarFollowing::Idm, CarFollowing::GapTime, CarFollowing::Fuzzy})
        if (name == toString(m) && (inherit || m != CarFollowing::Inherit)) {
            out = m;
            return;
        }
    f.error(item["car_following"].Mark(), key + ".car_following",
              std::string("must be ") + (inherit ? "inherit, " : "") + "idm, gap_time or fuzzy, got '" + name + "'");
}

void TrafficReader::readTraffic(const YAML::Node& node, TrafficSettings& t)
{
    const std::string key = "traffic";
    if (!m_f.expectMap(node, key))
        return;
    m_f.checkKeys(node, key, {"car_following", "driver_start_delay", "walker_start_delay", "crossing_margin",
                              "walker_clearance", "waiting_speed", "yield_horizon"});
    readCarFollowing(m_f, node, key, t.carFollowing, false);
    for (auto [name, range] : {std::pair{"driver_start_delay", &t.driverStartDelayS},
                               std::pair{"walker_start_delay", &t.walkerStartDelayS}})
        if (m_f.readVec2(node, name, key, *range, false, Range::NonNegative) && range->x > range->y)
            m_f.error(node[name].Mark(), key + "." + name, "the minimum (first) must not exceed the maximum");
    m_f.readFloat(node, "crossing_margin", key, t.crossingMarginM, false, Range::NonNegative);
    m_f.readFloat(node, "walker_clearance", key, t.walkerClearanceM, false, Range::NonNegative);
    m_f.readFloat(node, "waiting_speed", key, t.waitingSpeed, false, Range::NonNegative);
    m_f.readFloat(node, "yield_horizon", key, t.yieldHorizonS, false, Range::Positive);
}

void TrafficReader::readLanes(const YAML::Node& node, Scene& scene)
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
            m_names.claim(item, key, l.name, "lane");
        m_f.readPolyline(item, "points", key, l.points, true, 2);
        m_f.readFloat(item, "width", key, l.widthM, false, Range::Positive);
        m_f.readFloat(item, "speed_limit", key, l.speedLimit, false, Range::Positive);
        m_f.readBool(item, "loop", key, l.loop, false);
        readCarFollowing(m_f, item, key, l.carFollowing, true);
        scene.lanes.push_back(std::move(l));
    }
}

void TrafficReader::readCrosswalks(const YAML::Node& node, Scene& scene)
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
            m_names.claim(item, key, c.name, "crosswalk");
        const bool ends = m_f.readVec2(item, "from", key, c.from, true) & m_f.readVec2(item, "to", key, c.to, true);
        m_f.readFloat(item, "width", key, c.widthM, false, Range::Positive);
        if (ends && c.from == c.to)
            m_f.error(item.Mark(), key, "'from' and 'to' are the same point");
        scene.crosswalks.push_back(std::move(c));
    }
}

void TrafficReader::readTrafficLights(const YAML::Node& node, Scene& scene)
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
            m_names.claim(item, key, t.name, "traffic light");
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
                    m_names.checkRef(line, "lane", lk, s.lane, scene.findLane(s.lane) != nullptr, "lane");
                    m_f.readFloat(line, "at", lk, s.atM, true, Range::NonNegative);
                } else {
                    m_names.checkRef(line, "crosswalk", lk, s.crosswalk, scene.findCrosswalk(s.crosswalk) != nullptr,
                             "crosswalk");
                }
                t.stopLines.push_back(std::move(s));
            }
        }
        scene.trafficLights.push_back(std::move(t));
    }
}

void TrafficReader::readVehicles(const YAML::Node& node, Scene& scene)
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
            m_names.claimId(id, key + ".id", v.id);
        if (m_f.readName(item, "type", key, v.type, true)) {
            const AgentType* type = scene.findAgentType(v.type);
            if (m_names.checkRef(item, "type", key, v.type, type != nullptr, "agent type") &&
                type->kind != AgentKind::Vehicle)
                m_f.error(item["type"].Mark(), key + ".type", "agent type '" + v.type + "' is not of kind vehicle");
        }
        if (m_f.readName(item, "lane", key, v.lane, true))
            m_names.checkRef(item, "lane", key, v.lane, scene.findLane(v.lane) != nullptr, "lane");
        m_f.readFloat(item, "at", key, v.atM, false, Range::NonNegative);
        m_f.readFloat(item, "speed", key, v.speed, false, Range::NonNegative);
        scene.vehicles.push_back(std::move(v));
    }
}

}  // namespace throng::sim::detail
