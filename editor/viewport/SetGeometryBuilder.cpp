#include "editor/viewport/SetGeometryBuilder.h"

#include "simcore/traffic/LightPhase.h"
#include "editor/viewport/ViewportPalette.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

namespace throng::editor {

namespace {

constexpr float kWallHalfWidthM = 0.12f;
constexpr float kThinHalfWidthM = 0.05f;

// Rotation about +y, counter-clockwise seen from above (the scene's heading convention).
glm::vec2 rotate(glm::vec2 v, float angleRad)
{
    const float c = std::cos(angleRad), s = std::sin(angleRad);
    return {v.x * c + v.y * s, -v.x * s + v.y * c};
}

std::vector<glm::vec2> circlePoints(glm::vec2 centre, float radiusM)
{
    const int n = std::clamp(int(radiusM * 8.0f), 24, 128);
    std::vector<glm::vec2> points;
    points.reserve(std::size_t(n) + 1);
    for (int i = 0; i <= n; ++i) {
        const float a = 2.0f * std::numbers::pi_v<float> * float(i) / float(n);
        points.push_back(centre + radiusM * glm::vec2(std::cos(a), std::sin(a)));
    }
    return points;
}

// The point `atM` metres along a polyline and the direction of travel there.
std::pair<glm::vec2, glm::vec2> pointAlong(std::span<const glm::vec2> points, float atM)
{
    for (std::size_t i = 0; i + 1 < points.size(); ++i) {
        const glm::vec2 d = points[i + 1] - points[i];
        const float len = glm::length(d);
        if (!(len > 0.0f))
            continue;
        if (atM <= len || i + 2 == points.size())
            return {points[i] + d * (std::min(atM, len) / len), d / len};
        atM -= len;
    }
    return {points.empty() ? glm::vec2(0.0f) : points.front(), glm::vec2(1.0f, 0.0f)};
}

glm::vec4 phaseColour(std::optional<double> timeS, const sim::TrafficLight& light)
{
    if (!timeS)
        return palette::kLightUnknown;
    switch (sim::lightPhaseAt(light, *timeS)) {
    case sim::LightPhase::Green: return palette::kLightGreen;
    case sim::LightPhase::Yellow: return palette::kLightYellow;
    case sim::LightPhase::Red: return palette::kLightRed;
    }
    return palette::kLightUnknown;
}

}  // namespace

void SetGeometryBuilder::addSet(const sim::Scene& scene, ShapeMesh& mesh)
{
    addBounds(scene.settings, mesh);
    addLanes(scene.lanes, mesh);
    addCrosswalks(scene.crosswalks, mesh);
    addFlowField(scene, mesh);
    addFlowStrokes(scene.flowStrokes, mesh);
    addPaths(scene.paths, mesh);
    addHeroes(scene.heroes, mesh);
    addSpawnAreas(scene.groups, mesh);
    addGoals(scene.goals, mesh);
    addActionPoints(scene.actionPoints, mesh);
    addSources(scene, mesh);
    addMeasurements(scene.measurements, mesh);
    addObstacles(scene.obstacles, mesh);
    addWalls(scene.walls, mesh);
}

void SetGeometryBuilder::addBounds(const sim::Settings& settings, ShapeMesh& mesh)
{
    const glm::vec2 lo = settings.boundsMin, hi = settings.boundsMax;
    const std::array<glm::vec2, 4> corners{lo, {hi.x, lo.y}, hi, {lo.x, hi.y}};
    mesh.addPolyline(corners, true, 0.0f, palette::kBounds);
}

void SetGeometryBuilder::addLanes(std::span<const sim::Lane> lanes, ShapeMesh& mesh)
{
    for (const sim::Lane& lane : lanes)
        mesh.addPolyline(lane.points, false, 0.5f * lane.widthM, palette::kLane);
    for (const sim::Lane& lane : lanes) {
        mesh.addDashedPolyline(lane.points, 0.06f, 1.5f, 1.5f, palette::kLaneCentre);
        addChevrons(lane.points, false, std::min(0.35f * lane.widthM, 1.0f), palette::kLaneEdge, mesh);
    }
}

void SetGeometryBuilder::addCrosswalks(std::span<const sim::Crosswalk> crosswalks, ShapeMesh& mesh)
{
    // Zebra bars run along the walking direction, laid side by side across the width.
    constexpr float kBarM = 0.5f;
    for (const sim::Crosswalk& c : crosswalks) {
        const glm::vec2 d = c.to - c.from;
        const float len = glm::length(d);
        if (!(len > 0.0f))
            continue;
        const glm::vec2 along = d / len, across{-along.y, along.x};
        const int bars = std::max(1, int(std::floor(c.widthM / (2.0f * kBarM))));
        const float first = -0.5f * float(2 * bars - 1) * kBarM;
        for (int i = 0; i < bars; ++i) {
            const float o0 = first + float(2 * i) * kBarM, o1 = o0 + kBarM;
            const std::array<glm::vec2, 4> bar{c.from + across * o0, c.to + across * o0, c.to + across * o1,
                                               c.from + across * o1};
            mesh.addConvexPolygon(bar, palette::kCrosswalkStripe);
        }
    }
}

void SetGeometryBuilder::addSpawnAreas(std::span<const sim::SpawnGroup> groups, ShapeMesh& mesh)
{
    for (const sim::SpawnGroup& g : groups) {
        if (g.shape == sim::AreaShape::Rect) {
            const std::array<glm::vec2, 5> r{g.min, glm::vec2(g.max.x, g.min.y), g.max, glm::vec2(g.min.x, g.max.y),
                                             g.min};
            mesh.addDashedPolyline(r, 0.04f, 0.6f, 0.4f, palette::kSpawnArea);
        } else if (g.shape == sim::AreaShape::Polygon) {
            std::vector<glm::vec2> outline = g.points;
            if (!outline.empty())
                outline.push_back(outline.front());
            mesh.addDashedPolyline(outline, 0.04f, 0.6f, 0.4f, palette::kSpawnArea);
        } else {
            mesh.addDashedPolyline(circlePoints(g.center, g.radiusM), 0.04f, 0.6f, 0.4f, palette::kSpawnArea);
        }
    }
}

void SetGeometryBuilder::addFlowStrokes(std::span<const sim::FlowStroke> strokes, ShapeMesh& mesh)
{
    for (const sim::FlowStroke& s : strokes) {
        mesh.addPolyline(s.points, false, kThinHalfWidthM, palette::kFlowStroke);
        addChevrons(s.points, false, std::min(0.25f * s.widthM, 0.6f), palette::kFlowStroke, mesh);
    }
}

void SetGeometryBuilder::addFlowField(const sim::Scene& scene, ShapeMesh& mesh)
{
    constexpr float kCellM = 2.0f, kArrowM = 0.6f;
    if (scene.flowStrokes.empty())
        return;
    const glm::vec2 lo = scene.settings.boundsMin, hi = scene.settings.boundsMax;
    for (float z = lo.y + 0.5f * kCellM; z < hi.y; z += kCellM)
        for (float x = lo.x + 0.5f * kCellM; x < hi.x; x += kCellM) {
            const glm::vec2 p(x, z);
            float best = INFINITY;
            glm::vec2 dir(0.0f);
            for (const sim::FlowStroke& s : scene.flowStrokes)
                for (std::size_t i = 1; i < s.points.size(); ++i) {
                    const glm::vec2 a = s.points[i - 1], ab = s.points[i] - a;
                    const float len2 = glm::dot(ab, ab);
                    if (!(len2 > 0.0f))
                        continue;
                    const float t = std::clamp(glm::dot(p - a, ab) / len2, 0.0f, 1.0f);
                    const float d = glm::length(p - (a + t * ab));
                    if (d <= 0.5f * s.widthM && d < best) {
                        best = d;
                        dir = ab / std::sqrt(len2);
                    }
                }
            if (dir == glm::vec2(0.0f))
                continue;
            const glm::vec2 side(-dir.y, dir.x), tip = p + dir * (0.5f * kArrowM);
            const glm::vec4 c = palette::kFlowArrow;
            mesh.addLine(p - dir * (0.5f * kArrowM), tip, 0.03f, c);
            mesh.addLine(tip - dir * (0.4f * kArrowM) + side * (0.25f * kArrowM), tip, 0.03f, c);
            mesh.addLine(tip - dir * (0.4f * kArrowM) - side * (0.25f * kArrowM), tip, 0.03f, c);
        }
}

void SetGeometryBuilder::addHeroes(std::span<const sim::Hero> heroes, ShapeMesh& mesh)
{
    for (const sim::Hero& h : heroes) {
        std::vector<glm::vec2> way;
        for (const sim::Keyframe& k : h.keyframes)
            way.emplace_back(k.position.x, k.position.z);
        mesh.addDashedPolyline(way, 0.06f, 0.8f, 0.4f, palette::kHeroWay);
        for (glm::vec2 p : way)
            mesh.addDisc(p, 0.18f, palette::kHeroWay);
    }
}

void SetGeometryBuilder::addPaths(std::span<const sim::Path> paths, ShapeMesh& mesh)
{
    // All bands first, so one path's band never hides another path's centre line.
    for (const sim::Path& p : paths)
        mesh.addPolyline(p.points, p.closed, p.radiusM, palette::kPathBand);
    for (const sim::Path& p : paths) {
        mesh.addPolyline(p.points, p.closed, kThinHalfWidthM, palette::kPathLine);
        addChevrons(p.points, p.closed, std::min(0.5f * p.radiusM, 0.6f), palette::kPathLine, mesh);
    }
}

void SetGeometryBuilder::addGoals(std::span<const sim::Goal> goals, ShapeMesh& mesh)
{
    for (const sim::Goal& g : goals) {
        mesh.addRing(g.position, g.radiusM, kThinHalfWidthM, palette::kGoal);
        const float arm = std::min(0.3f, 0.5f * g.radiusM);
        mesh.addLine(g.position - glm::vec2(arm, 0.0f), g.position + glm::vec2(arm, 0.0f), kThinHalfWidthM,
                     palette::kGoal);
        mesh.addLine(g.position - glm::vec2(0.0f, arm), g.position + glm::vec2(0.0f, arm), kThinHalfWidthM,
                     palette::kGoal);
    }
}

void SetGeometryBuilder::addActionPoints(std::span<const sim::ActionPoint> points, ShapeMesh& mesh)
{
    for (const sim::ActionPoint& p : points) {
        mesh.addRing(p.position, p.radiusM, kThinHalfWidthM, palette::kActionPoint);
        mesh.addRing(p.position, std::min(0.12f, 0.3f * p.radiusM), kThinHalfWidthM, palette::kActionPoint);
        if (!p.faces)
            continue;
        const float a = p.facingDeg * std::numbers::pi_v<float> / 180.0f;
        const glm::vec2 dir(std::cos(a), -std::sin(a)), side(-dir.y, dir.x);
        const glm::vec2 tip = p.position + 0.9f * p.radiusM * dir;
        const float head = std::min(0.4f, 0.35f * p.radiusM);
        mesh.addLine(p.position, tip, kThinHalfWidthM, palette::kActionPoint);
        mesh.addLine(tip - head * (dir - side), tip, kThinHalfWidthM, palette::kActionPoint);
        mesh.addLine(tip - head * (dir + side), tip, kThinHalfWidthM, palette::kActionPoint);
    }
}

void SetGeometryBuilder::addSources(const sim::Scene& scene, ShapeMesh& mesh)
{
    constexpr float kLineHalfWidthM = 0.08f, kArrowM = 1.2f;
    for (const sim::Source& src : scene.sources) {
        glm::vec2 middle(0.0f), across(1.0f, 0.0f);
        if (src.shape == sim::SourceShape::Line) {
            mesh.addLine(src.from, src.to, kLineHalfWidthM, palette::kSource);
            for (glm::vec2 end : {src.from, src.to})
                mesh.addRing(end, 0.15f, kThinHalfWidthM, palette::kSource);
            middle = 0.5f * (src.from + src.to);
            const glm::vec2 d = src.to - src.from;
            if (glm::length(d) > 0.0f)
                across = glm::normalize(glm::vec2(d.y, -d.x));
        } else {
            const std::array<glm::vec2, 4> box{src.min, glm::vec2(src.max.x, src.min.y), src.max,
                                               glm::vec2(src.min.x, src.max.y)};
            mesh.addPolyline(box, true, kLineHalfWidthM, palette::kSource);
            middle = 0.5f * (src.min + src.max);
        }
        // Which way the arrow points: where the arrivals face, or where they walk.
        glm::vec2 dir = across;
        const sim::Goal* goal = scene.findGoal(src.goal);
        const sim::Path* path = scene.findPath(src.path);
        if (src.headed) {
            const float a = src.headingDeg * std::numbers::pi_v<float> / 180.0f;
            dir = glm::vec2(std::cos(a), -std::sin(a));
        } else if (goal && glm::length(goal->position - middle) > 0.0f) {
            dir = glm::normalize(goal->position - middle);
        } else if (path && !path->points.empty() && glm::length(path->points.front() - middle) > 0.0f) {
            dir = glm::normalize(path->points.front() - middle);
        }
        const glm::vec2 side(-dir.y, dir.x), tip = middle + kArrowM * dir;
        mesh.addLine(middle, tip, kThinHalfWidthM, palette::kSource);
        mesh.addLine(tip - 0.4f * (dir - side), tip, kThinHalfWidthM, palette::kSource);
        mesh.addLine(tip - 0.4f * (dir + side), tip, kThinHalfWidthM, palette::kSource);
    }
}

void SetGeometryBuilder::addMeasurements(std::span<const sim::Measurement> measurements, ShapeMesh& mesh)
{
    constexpr float kLineHalfWidthM = 0.06f, kDashM = 0.6f;
    for (const sim::Measurement& m : measurements) {
        if (m.shape == sim::MeasurementShape::Line && m.points.size() == 2) {
            const glm::vec2 a = m.points[0], b = m.points[1], d = b - a;
            mesh.addLine(a, b, kLineHalfWidthM, palette::kMeasurement);
            if (glm::length(d) <= 0.0f)
                continue;
            const glm::vec2 dir = glm::normalize(glm::vec2(d.y, -d.x)), side(-dir.y, dir.x);
            const glm::vec2 middle = 0.5f * (a + b), tip = middle + 0.8f * dir;
            mesh.addLine(middle, tip, kThinHalfWidthM, palette::kMeasurement);
            mesh.addLine(tip - 0.3f * (dir - side), tip, kThinHalfWidthM, palette::kMeasurement);
            mesh.addLine(tip - 0.3f * (dir + side), tip, kThinHalfWidthM, palette::kMeasurement);
            continue;
        }
        // An area: its outline in dashes, so it reads as a region to measure, not a wall.
        for (std::size_t k = 0; k < m.points.size(); ++k) {
            const glm::vec2 a = m.points[k], b = m.points[(k + 1) % m.points.size()];
            const float length = glm::length(b - a);
            for (float t = 0.0f; t < length; t += 2.0f * kDashM)
                mesh.addLine(a + (b - a) * (t / length), a + (b - a) * (std::min(t + kDashM, length) / length),
                             kThinHalfWidthM, palette::kMeasurement);
        }
    }
}

void SetGeometryBuilder::addObstacles(std::span<const sim::Obstacle> obstacles, ShapeMesh& mesh)
{
    for (const sim::Obstacle& o : obstacles) {
        if (o.shape == sim::ObstacleShape::Circle) {
            mesh.addDisc(o.center, o.radiusM, palette::kObstacleFill);
            mesh.addRing(o.center, o.radiusM, kThinHalfWidthM, palette::kObstacleEdge);
            continue;
        }
        const float a = o.angleDeg * std::numbers::pi_v<float> / 180.0f;
        const glm::vec2 h = 0.5f * o.size;
        const std::array<glm::vec2, 4> box{o.center + rotate({-h.x, -h.y}, a), o.center + rotate({h.x, -h.y}, a),
                                           o.center + rotate({h.x, h.y}, a), o.center + rotate({-h.x, h.y}, a)};
        mesh.addConvexPolygon(box, palette::kObstacleFill);
        mesh.addPolyline(box, true, kThinHalfWidthM, palette::kObstacleEdge);
    }
}

void SetGeometryBuilder::addWalls(std::span<const sim::Wall> walls, ShapeMesh& mesh)
{
    for (const sim::Wall& w : walls)
        mesh.addPolyline(w.points, false, kWallHalfWidthM, palette::kWall);
}

void SetGeometryBuilder::addChevrons(std::span<const glm::vec2> points, bool closed, float sizeM, glm::vec4 colour,
                                     ShapeMesh& mesh)
{
    // One arrow head at the middle of every segment long enough to hold it: the direction of travel.
    const std::size_t n = points.size();
    for (std::size_t i = 0; i + 1 < n + (closed ? 1 : 0); ++i) {
        const glm::vec2 a = points[i], b = points[(i + 1) % n];
        const float len = glm::length(b - a);
        if (!(len > 4.0f * sizeM) || !(sizeM > 0.0f))
            continue;
        const glm::vec2 dir = (b - a) / len, side{-dir.y, dir.x};
        const glm::vec2 tip = 0.5f * (a + b) + dir * (0.5f * sizeM);
        mesh.addLine(tip - dir * sizeM + side * sizeM, tip, 0.5f * kThinHalfWidthM + 0.02f, colour);
        mesh.addLine(tip - dir * sizeM - side * sizeM, tip, 0.5f * kThinHalfWidthM + 0.02f, colour);
    }
}

void SetGeometryBuilder::addLights(const sim::Scene& scene, std::optional<double> timeS, ShapeMesh& mesh)
{
    for (const sim::TrafficLight& light : scene.trafficLights) {
        const glm::vec4 colour = phaseColour(timeS, light);
        for (const sim::StopLine& s : light.stopLines) {
            if (const sim::Lane* lane = scene.findLane(s.lane)) {
                const auto [p, dir] = pointAlong(lane->points, s.atM);
                const glm::vec2 side = 0.5f * lane->widthM * glm::vec2(-dir.y, dir.x);
                mesh.addLine(p - side, p + side, 0.15f, colour);
            } else if (const sim::Crosswalk* c = scene.findCrosswalk(s.crosswalk)) {
                const glm::vec2 d = glm::normalize(c->to - c->from);
                const glm::vec2 side = 0.5f * c->widthM * glm::vec2(-d.y, d.x);
                for (glm::vec2 end : {c->from - d * 0.3f, c->to + d * 0.3f})
                    mesh.addLine(end - side, end + side, 0.1f, colour);
            }
        }
        mesh.addDisc(light.position, 0.6f, palette::kLightHousing);
        mesh.addDisc(light.position, 0.42f, colour);
    }
}

}  // namespace throng::editor
