#include "editor/tools/TrafficLightTool.h"

#include "editor/commands/AddSceneItemCommand.h"
#include "editor/tools/UniqueName.h"

#include <glm/geometric.hpp>

#include <algorithm>

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

}  // namespace

void TrafficLightTool::mouseReleased(const ToolMouse& mouse)
{
    if (!mouse.ground)
        return;
    const sim::Scene& scene = document().scene();
    sim::TrafficLight light;
    light.name = uniqueName(scene.trafficLights, "light");
    light.position = {mouse.ground->x, mouse.ground->z};
    // A lane or crosswalk obeys one signal only: skip those another light controls.
    auto controlled = [&scene](const std::string& lane, const std::string& crosswalk) {
        for (const sim::TrafficLight& other : scene.trafficLights)
            for (const sim::StopLine& s : other.stopLines)
                if ((!lane.empty() && s.lane == lane) || (!crosswalk.empty() && s.crosswalk == crosswalk))
                    return true;
        return false;
    };
    for (const sim::Crosswalk& c : scene.crosswalks)
        if (glm::length(0.5f * (c.from + c.to) - light.position) <= kReachM && !controlled("", c.name))
            light.stopLines.push_back({"", 0.0f, c.name});
    for (const sim::Lane& lane : scene.lanes) {
        const auto [along, dist] = projectOnLane(lane, light.position);
        if (dist <= kReachM && !controlled(lane.name, ""))
            light.stopLines.push_back({lane.name, std::max(0.0f, along - kReachM), ""});
    }
    const QString text = tr("Add traffic light %1").arg(QString::fromStdString(light.name));
    document().undoStack()->push(new AddSceneItemCommand<sim::TrafficLight>(document(), &sim::Scene::trafficLights,
                                                                            std::move(light), text));
}

}  // namespace throng::editor
