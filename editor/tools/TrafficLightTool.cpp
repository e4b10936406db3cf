#include "editor/tools/TrafficLightTool.h"
#include "editor/SegmentDistance.h"

#include "editor/SceneDocument.h"
#include "editor/commands/AddSceneItemCommand.h"
#include "editor/commands/ChangeValueCommand.h"
#include "editor/viewport/Viewport.h"
#include "editor/tools/UniqueName.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace throng::editor {

namespace {

// Distance along the lane's polyline to the point nearest `p`, and how far `p` is from it.
std::pair<float, float> projectOnLane(const sim::Lane& lane, glm::vec2 p)
{
    float along = 0.0f, bestAlong = 0.0f, bestDist = 1e30f;
    for (std::size_t i = 1; i < lane.points.size(); ++i) {
        const glm::vec2 a = lane.points[i - 1], ab = lane.points[i] - a;
        const float len = glm::length(ab);
        const float t = len > 0.0f ? std::clamp(glm::dot(p - a, ab) / (len * len), 0.0f, 1.0f) : 0.0f;
        const float d = glm::length(p - (a + t * ab));
        if (d < bestDist) {
            bestDist = d;
            bestAlong = along + t * len;
        }
        along += len;
    }
    return {bestAlong, bestDist};
}

// A lane or crosswalk obeys one signal only.
bool controlledBy(const sim::Scene& scene, const std::string& lane, const std::string& crosswalk)
{
    for (const sim::TrafficLight& other : scene.trafficLights)
        for (const sim::StopLine& s : other.stopLines)
            if ((!lane.empty() && s.lane == lane) || (!crosswalk.empty() && s.crosswalk == crosswalk))
                return true;
    return false;
}

}  // namespace

void TrafficLightTool::mouseReleased(const ToolMouse& mouse)
{
    const sim::Scene& scene = document().scene();
    const Selection& selection = document().selection();
    const bool oneLight = selection.size() == 1 && selection.front().kind == ItemKind::TrafficLight &&
                          selection.front().index < scene.trafficLights.size();
    if ((mouse.modifiers & Qt::ControlModifier) && oneLight && mouse.ground) {
        toggleStopLine(selection.front().index, {mouse.ground->x, mouse.ground->z});
        emit overlayChanged();
        return;
    }
    for (std::size_t i = 0; i < scene.trafficLights.size(); ++i) {
        const glm::vec2 p = scene.trafficLights[i].position;
        const QPointF at = viewport().worldToPixel({p.x, 0.0f, p.y});
        if (std::hypot(at.x() - mouse.pixel.x(), at.y() - mouse.pixel.y()) <= kPickPx) {
            document().setSelection({{ItemKind::TrafficLight, i}});
            m_status = tr("%1 selected: Ctrl+click a lane or crosswalk to attach or detach a stop line")
                           .arg(QString::fromStdString(scene.trafficLights[i].name));
            emit overlayChanged();
            return;
        }
    }
    if (mouse.ground)
        placeLight({mouse.ground->x, mouse.ground->z});
}

void TrafficLightTool::placeLight(glm::vec2 at)
{
    const sim::Scene& scene = document().scene();
    sim::TrafficLight light;
    light.name = uniqueName(scene.trafficLights, "light");
    light.position = at;
    for (const sim::Crosswalk& c : scene.crosswalks)
        if (glm::length(0.5f * (c.from + c.to) - light.position) <= kReachM && !controlledBy(scene, "", c.name))
            light.stopLines.push_back({"", 0.0f, c.name});
    for (const sim::Lane& lane : scene.lanes) {
        const auto [along, dist] = projectOnLane(lane, light.position);
        if (dist <= kReachM && !controlledBy(scene, lane.name, ""))
            light.stopLines.push_back({lane.name, std::max(0.0f, along - kReachM), ""});
    }
    const QString name = QString::fromStdString(light.name);
    addAndSelect(document(), &sim::Scene::trafficLights, std::move(light), tr("Add traffic light %1").arg(name));
    m_status = tr("%1 placed and selected: Ctrl+click a lane or crosswalk to attach or detach a stop line").arg(name);
}

void TrafficLightTool::toggleStopLine(std::size_t light, glm::vec2 at)
{
    const sim::Scene& scene = document().scene();
    // The crosswalk or lane under the click, nearest centre line first.
    sim::StopLine hit;
    float best = 1e30f;
    for (const sim::Crosswalk& c : scene.crosswalks) {
        const float d = segmentDistance(at, c.from, c.to);
        if (d <= 0.5f * c.widthM && d < best) {
            best = d;
            hit = {"", 0.0f, c.name};
        }
    }
    for (const sim::Lane& lane : scene.lanes) {
        const auto [along, d] = projectOnLane(lane, at);
        if (d <= 0.5f * lane.widthM && d < best) {
            best = d;
            hit = {lane.name, along, ""};
        }
    }
    const sim::TrafficLight& target = scene.trafficLights[light];
    if (hit.lane.empty() && hit.crosswalk.empty()) {
        m_status = tr("No lane or crosswalk under the click");
        return;
    }
    std::vector<sim::StopLine> lines = target.stopLines;
    auto same = [&hit](const sim::StopLine& s) {
        return (!hit.lane.empty() && s.lane == hit.lane) || (!hit.crosswalk.empty() && s.crosswalk == hit.crosswalk);
    };
    const QString what = QString::fromStdString(hit.lane.empty() ? hit.crosswalk : hit.lane);
    QString text;
    if (std::any_of(lines.begin(), lines.end(), same)) {
        std::erase_if(lines, same);
        text = tr("Detach %1 from %2").arg(what, QString::fromStdString(target.name));
    } else {
        for (std::size_t i = 0; i < scene.trafficLights.size(); ++i)
            if (i != light && std::any_of(scene.trafficLights[i].stopLines.begin(),
                                          scene.trafficLights[i].stopLines.end(), same)) {
                m_status = tr("%1 already obeys %2").arg(what, QString::fromStdString(scene.trafficLights[i].name));
                return;
            }
        lines.push_back(hit);
        text = tr("Attach %1 to %2").arg(what, QString::fromStdString(target.name));
    }
    m_status = text;
    const QString key = QStringLiteral("stopLines/%1/%2").arg(light).arg(document().undoStack()->index());
    document().undoStack()->push(new ChangeValueCommand<std::vector<sim::StopLine>>(
        document(), key, [light](sim::Scene& s) -> std::vector<sim::StopLine>& { return s.trafficLights[light].stopLines; },
        std::move(lines), text, SceneChange::of({ItemKind::TrafficLight, light}, SceneField::Route)));
}

}  // namespace throng::editor
