#include "editor/tools/SelectionGeometry.h"

#include <glm/geometric.hpp>

#include <algorithm>

namespace throng::editor {

std::optional<glm::vec2> vehicleStart(const sim::Scene& scene, const sim::Vehicle& vehicle)
{
    const sim::Lane* lane = scene.findLane(vehicle.lane);
    if (!lane || lane->points.empty())
        return std::nullopt;
    float left = vehicle.atM;
    for (std::size_t k = 1; k < lane->points.size(); ++k) {
        const glm::vec2 a = lane->points[k - 1], b = lane->points[k];
        const float len = glm::length(b - a);
        if (left <= len)
            return len > 0.0f ? a + (b - a) * (left / len) : a;
        left -= len;
    }
    // Past the end: shown at the lane's end.
    return lane->points.back();
}

std::optional<glm::vec2> itemAnchor(const sim::Scene& s, SceneItem item)
{
    if (item.index >= itemCount(s, item.kind))
        return std::nullopt;
    switch (item.kind) {
    case ItemKind::Agent: return glm::vec2(s.agents[item.index].position.x, s.agents[item.index].position.z);
    case ItemKind::Obstacle: return s.obstacles[item.index].center;
    case ItemKind::Goal: return s.goals[item.index].position;
    case ItemKind::ActionPoint: return s.actionPoints[item.index].position;
    case ItemKind::TrafficLight: return s.trafficLights[item.index].position;
    case ItemKind::Crosswalk: return 0.5f * (s.crosswalks[item.index].from + s.crosswalks[item.index].to);
    case ItemKind::Source: {
        const sim::Source& src = s.sources[item.index];
        return src.shape == sim::SourceShape::Line ? 0.5f * (src.from + src.to) : 0.5f * (src.min + src.max);
    }
    case ItemKind::Vehicle: return vehicleStart(s, s.vehicles[item.index]);
    case ItemKind::Measurement: {
        const std::vector<glm::vec2>& points = s.measurements[item.index].points;
        glm::vec2 sum(0.0f);
        for (const glm::vec2& p : points)
            sum += p;
        return points.empty() ? std::nullopt : std::optional<glm::vec2>(sum / float(points.size()));
    }
    default: return std::nullopt;
    }
}

std::pair<sim::AgentId, sim::AgentId> groupMemberIds(const sim::Scene& s, std::size_t group)
{
    sim::AgentId first = sim::firstSpawnedId(s);
    for (std::size_t g = 0; g < group && g < s.groups.size(); ++g)
        first += s.groups[g].count;
    return {first, group < s.groups.size() ? first + s.groups[group].count : first};
}

std::optional<SceneItem> agentItem(const sim::Scene& s, sim::AgentId id)
{
    if (id == 0)
        return std::nullopt;
    for (std::size_t i = 0; i < s.agents.size(); ++i)
        if (s.agents[i].id == id)
            return SceneItem{ItemKind::Agent, i};
    for (std::size_t i = 0; i < s.vehicles.size(); ++i)
        if (s.vehicles[i].id == id)
            return SceneItem{ItemKind::Vehicle, i};
    for (std::size_t i = 0; i < s.heroes.size(); ++i)
        if (s.heroes[i].id == id)
            return SceneItem{ItemKind::Hero, i};
    const sim::AgentId first = groupMemberIds(s, 0).first;
    sim::AgentId end = first;
    for (std::size_t g = 0; g < s.groups.size(); ++g) {
        const sim::AgentId begin = end;
        end += s.groups[g].count;
        if (id >= begin && id < end)
            return SceneItem{ItemKind::Group, g};
    }
    return std::nullopt;
}

std::span<const glm::vec2> itemPolyline(const sim::Scene& s, SceneItem item)
{
    if (item.index >= itemCount(s, item.kind))
        return {};
    switch (item.kind) {
    case ItemKind::Path: return s.paths[item.index].points;
    case ItemKind::Wall: return s.walls[item.index].points;
    case ItemKind::Lane: return s.lanes[item.index].points;
    case ItemKind::FlowStroke: return s.flowStrokes[item.index].points;
    default: return {};
    }
}

std::vector<glm::vec2> sourceOutline(const sim::Source& source)
{
    if (source.shape == sim::SourceShape::Line)
        return {source.from, source.to};
    const glm::vec2 lo = source.min, hi = source.max;
    return {lo, {hi.x, lo.y}, hi, {lo.x, hi.y}, lo};
}

std::vector<glm::vec2> measurementOutline(const sim::Measurement& measurement)
{
    std::vector<glm::vec2> outline = measurement.points;
    if (measurement.shape == sim::MeasurementShape::Area && !outline.empty())
        outline.push_back(outline.front());
    return outline;
}

std::vector<EditHandle> editHandles(const sim::Scene& scene, const Selection& selection)
{
    std::vector<EditHandle> handles;
    if (selection.size() != 1)
        return handles;
    const SceneItem item = selection.front();
    const std::span<const glm::vec2> points = itemPolyline(scene, item);
    for (std::size_t i = 0; i < points.size(); ++i)
        handles.push_back({EditHandle::Kind::Point, item, i, points[i]});
    if (item.kind == ItemKind::Path && points.size() >= 2) {
        // On the band's edge, square to the first segment.
        const glm::vec2 d = points[1] - points[0];
        const float len = glm::length(d);
        if (len > 0.0f) {
            const glm::vec2 side(-d.y / len, d.x / len);
            const glm::vec2 mid = 0.5f * (points[0] + points[1]);
            handles.push_back({EditHandle::Kind::Radius, item, 0, mid + side * scene.paths[item.index].radiusM});
        }
    }
    return handles;
}

float polylineDistance(std::span<const glm::vec2> points, glm::vec2 p)
{
    float best = points.size() == 1 ? glm::length(p - points[0]) : 1e30f;
    for (std::size_t i = 1; i < points.size(); ++i) {
        const glm::vec2 a = points[i - 1], ab = points[i] - a;
        const float len2 = glm::dot(ab, ab);
        const float t = len2 > 0.0f ? std::clamp(glm::dot(p - a, ab) / len2, 0.0f, 1.0f) : 0.0f;
        best = std::min(best, glm::length(p - (a + t * ab)));
    }
    return best;
}

}  // namespace throng::editor
