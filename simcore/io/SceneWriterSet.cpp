// Writes the set (goals, paths, walls, obstacles, terrain, flow strokes) and the traffic
// (lanes, crosswalks, lights, vehicles, heroes) sections of a scene file.
#include "simcore/io/detail/YamlWriter.h"
#include "simcore/scene/Scene.h"

namespace throng::sim::detail {

void writeSceneSet(YamlWriter& w, const Scene& s)
{
    YAML::Emitter& o = w.out;
    if (!s.goals.empty()) {
        w.key("goals");
        o << YAML::BeginSeq;
        for (const Goal& g : s.goals) {
            o << YAML::Flow << YAML::BeginMap;
            w.kv("name", g.name);
            w.key("position");
            w.vec2(g.position);
            w.kvf("radius", g.radiusM);
            if (g.exit)
                w.kv("exit", "true");
            o << YAML::EndMap;
        }
        o << YAML::EndSeq;
    }
    if (!s.paths.empty()) {
        w.key("paths");
        o << YAML::BeginSeq;
        for (const Path& p : s.paths) {
            o << YAML::BeginMap;
            w.kv("name", p.name);
            w.kvf("radius", p.radiusM);
            w.kv("closed", p.closed ? "true" : "false");
            if (p.exit)
                w.kv("exit", "true");
            if (p.planned) {
                w.kv("plan", "astar");
                w.kvf("clearance", p.clearanceM);
            }
            w.key("points");
            w.polyline(p.points);
            o << YAML::EndMap;
        }
        o << YAML::EndSeq;
    }
    if (!s.walls.empty()) {
        w.key("walls");
        o << YAML::BeginSeq;
        for (const Wall& wall : s.walls) {
            o << YAML::Flow << YAML::BeginMap;
            w.kvOpt("name", wall.name);
            if (wall.heightM != Wall{}.heightM)
                w.kvf("height", wall.heightM);
            w.key("points");
            w.polyline(wall.points);
            o << YAML::EndMap;
        }
        o << YAML::EndSeq;
    }
    if (!s.obstacles.empty()) {
        w.key("obstacles");
        o << YAML::BeginSeq;
        for (const Obstacle& ob : s.obstacles) {
            o << YAML::Flow << YAML::BeginMap;
            w.kvOpt("name", ob.name);
            w.kv("shape", toString(ob.shape));
            w.key("center");
            w.vec2(ob.center);
            if (ob.shape == ObstacleShape::Circle) {
                w.kvf("radius", ob.radiusM);
            } else {
                w.key("size");
                w.vec2(ob.size);
                w.kvf("angle", ob.angleDeg);
            }
            o << YAML::EndMap;
        }
        o << YAML::EndSeq;
    }
    if (!s.terrain.heights.empty()) {
        w.key("terrain");
        o << YAML::BeginMap;
        w.key("origin");
        w.vec2(s.terrain.origin);
        w.kvf("cell", s.terrain.cellM);
        w.kv("cols", std::to_string(s.terrain.cols));
        w.kv("rows", std::to_string(s.terrain.rows));
        w.key("heights");
        o << YAML::Flow << YAML::BeginSeq;
        for (float h : s.terrain.heights)
            o << num(h);
        o << YAML::EndSeq << YAML::EndMap;
    }
    if (!s.flowStrokes.empty()) {
        w.key("flow_strokes");
        o << YAML::BeginSeq;
        for (const FlowStroke& f : s.flowStrokes) {
            o << YAML::Flow << YAML::BeginMap;
            w.kvf("width", f.widthM);
            w.key("points");
            w.polyline(f.points);
            o << YAML::EndMap;
        }
        o << YAML::EndSeq;
    }
    if (!s.groups.empty()) {
        w.key("groups");
        o << YAML::BeginSeq;
        for (const SpawnGroup& g : s.groups) {
            o << YAML::BeginMap;
            w.kv("name", g.name);
            w.kv("type", g.type);
            w.kv("count", std::to_string(g.count));
            if (g.shape == AreaShape::Polygon) {
                w.kv("shape", "polygon");
                w.key("points");
                w.polyline(g.points);
            } else if (g.shape == AreaShape::Rect) {
                w.key("rect");
                o << YAML::Flow << YAML::BeginMap;
                w.key("min");
                w.vec2(g.min);
                w.key("max");
                w.vec2(g.max);
                o << YAML::EndMap;
            } else {
                w.key("circle");
                o << YAML::Flow << YAML::BeginMap;
                w.key("center");
                w.vec2(g.center);
                w.kvf("radius", g.radiusM);
                o << YAML::EndMap;
            }
            w.kvOpt("goal", g.goal);
            w.kvOpt("path", g.path);
            if (!g.exits.empty()) {
                w.key("exits");
                o << YAML::Flow << g.exits;
            }
            if (g.leader != 0)
                w.kv("leader", std::to_string(g.leader));
            if (g.altitudeM != glm::vec2(0.0f)) {
                w.key("altitude");
                w.vec2(g.altitudeM);
            }
            if (g.formation.shape != FormationShape::None) {
                w.key("formation");
                o << YAML::Flow << YAML::BeginMap;
                w.kv("shape", toString(g.formation.shape));
                w.kvf("spacing", g.formation.spacingM);
                if (g.formation.shape == FormationShape::Column)
                    w.kv("width", std::to_string(g.formation.width));
                o << YAML::EndMap;
            }
            if (g.companions != glm::uvec2(0u)) {
                w.key("companions");
                o << YAML::Flow << YAML::BeginSeq << g.companions.x << g.companions.y << YAML::EndSeq;
            }
            o << YAML::EndMap;
        }
        o << YAML::EndSeq;
    }
}

void writeSceneTraffic(YamlWriter& w, const Scene& s)
{
    YAML::Emitter& o = w.out;
    const TrafficSettings& t = s.traffic;
    const TrafficSettings defaults{};
    if (t != defaults) {  // only the keys a user changed
        w.key("traffic");
        o << YAML::BeginMap;
        if (t.carFollowing != defaults.carFollowing)
            w.kv("car_following", toString(t.carFollowing));
        if (t.driverStartDelayS != defaults.driverStartDelayS) {
            w.key("driver_start_delay");
            w.vec2(t.driverStartDelayS);
        }
        if (t.walkerStartDelayS != defaults.walkerStartDelayS) {
            w.key("walker_start_delay");
            w.vec2(t.walkerStartDelayS);
        }
        if (t.crossingMarginM != defaults.crossingMarginM)
            w.kvf("crossing_margin", t.crossingMarginM);
        if (t.walkerClearanceM != defaults.walkerClearanceM)
            w.kvf("walker_clearance", t.walkerClearanceM);
        if (t.waitingSpeed != defaults.waitingSpeed)
            w.kvf("waiting_speed", t.waitingSpeed);
        if (t.yieldHorizonS != defaults.yieldHorizonS)
            w.kvf("yield_horizon", t.yieldHorizonS);
        o << YAML::EndMap;
    }
    if (!s.lanes.empty()) {
        w.key("lanes");
        o << YAML::BeginSeq;
        for (const Lane& l : s.lanes) {
            o << YAML::Flow << YAML::BeginMap;
            w.kv("name", l.name);
            w.kvf("width", l.widthM);
            w.kvf("speed_limit", l.speedLimit);
            w.kv("loop", l.loop ? "true" : "false");
            if (l.carFollowing != CarFollowing::Inherit)
                w.kv("car_following", toString(l.carFollowing));
            w.key("points");
            w.polyline(l.points);
            o << YAML::EndMap;
        }
        o << YAML::EndSeq;
    }
    if (!s.crosswalks.empty()) {
        w.key("crosswalks");
        o << YAML::BeginSeq;
        for (const Crosswalk& c : s.crosswalks) {
            o << YAML::Flow << YAML::BeginMap;
            w.kv("name", c.name);
            w.key("from");
            w.vec2(c.from);
            w.key("to");
            w.vec2(c.to);
            w.kvf("width", c.widthM);
            o << YAML::EndMap;
        }
        o << YAML::EndSeq;
    }
    if (!s.trafficLights.empty()) {
        w.key("traffic_lights");
        o << YAML::BeginSeq;
        for (const TrafficLight& t : s.trafficLights) {
            o << YAML::BeginMap;
            w.kv("name", t.name);
            w.kvf("green", t.greenS);
            w.kvf("yellow", t.yellowS);
            w.kvf("red", t.redS);
            w.kvf("offset", t.offsetS);
            w.key("position");
            w.vec2(t.position);
            w.key("stop_lines");
            o << YAML::BeginSeq;
            for (const StopLine& l : t.stopLines) {
                o << YAML::Flow << YAML::BeginMap;
                if (!l.lane.empty()) {
                    w.kv("lane", l.lane);
                    w.kvf("at", l.atM);
                } else {
                    w.kv("crosswalk", l.crosswalk);
                }
                o << YAML::EndMap;
            }
            o << YAML::EndSeq << YAML::EndMap;
        }
        o << YAML::EndSeq;
    }
    if (!s.vehicles.empty()) {
        w.key("vehicles");
        o << YAML::BeginSeq;
        for (const Vehicle& v : s.vehicles) {
            o << YAML::Flow << YAML::BeginMap;
            w.kv("id", std::to_string(v.id));
            w.kv("type", v.type);
            w.kv("lane", v.lane);
            w.kvf("at", v.atM);
            w.kvf("speed", v.speed);
            o << YAML::EndMap;
        }
        o << YAML::EndSeq;
    }
    if (!s.heroes.empty()) {
        w.key("heroes");
        o << YAML::BeginSeq;
        for (const Hero& h : s.heroes) {
            o << YAML::BeginMap;
            w.kv("id", std::to_string(h.id));
            w.kv("name", h.name);
            w.kv("type", h.type);
            w.kvf("clearance", h.clearanceM);
            if (!h.keyframesFile.empty()) {
                w.kv("keyframes_file", h.keyframesFile);
            } else {
                w.key("keyframes");
                o << YAML::BeginSeq;
                for (const Keyframe& k : h.keyframes) {
                    o << YAML::Flow << YAML::BeginMap;
                    w.kvf("time", k.timeS);
                    w.key("position");
                    w.vec3(k.position);
                    o << YAML::EndMap;
                }
                o << YAML::EndSeq;
            }
            o << YAML::EndMap;
        }
        o << YAML::EndSeq;
    }
}

}  // namespace throng::sim::detail
