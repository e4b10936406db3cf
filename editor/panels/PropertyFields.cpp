#include "editor/panels/PropertyFields.h"

#include <QCoreApplication>

namespace throng::editor {

namespace {

QString tr(const char* text)
{
    return QCoreApplication::translate("PropertyFields", text);
}

#define THRONG_SETTING(member) [](sim::Scene& s, std::size_t) -> float& { return s.settings.member; }
#define THRONG_FIELD(list, member) [](sim::Scene& s, std::size_t i) -> float& { return s.list[i].member; }

std::vector<PropertyField> make(ItemKind kind)
{
    switch (kind) {
    case ItemKind::Settings:
        return {{"fps", tr("Frames per second"), 1, 240, 1, 0, [](sim::Scene& s, std::size_t) -> float& { return s.settings.fps; }},
                {"duration", tr("Duration (s)"), 0.1, 36000, 1, 1,
                 [](sim::Scene& s, std::size_t) -> float& { return s.settings.durationS; }},
                {"boundsMinX", tr("Bounds min X (m)"), -1e5, 1e5, 1, 1, THRONG_SETTING(boundsMin.x)},
                {"boundsMinZ", tr("Bounds min Z (m)"), -1e5, 1e5, 1, 1, THRONG_SETTING(boundsMin.y)},
                {"boundsMaxX", tr("Bounds max X (m)"), -1e5, 1e5, 1, 1, THRONG_SETTING(boundsMax.x)},
                {"boundsMaxZ", tr("Bounds max Z (m)"), -1e5, 1e5, 1, 1, THRONG_SETTING(boundsMax.y)},
                {"navCell", tr("Navigation cell (m)"), 0.05, 10, 0.05, 2, THRONG_SETTING(navCellM)}};
    case ItemKind::AgentType:
        return {{"radius", tr("Radius (m)"), 0.05, 20, 0.05, 2, THRONG_FIELD(agentTypes, radiusM)},
                {"maxSpeed", tr("Max speed (m/s)"), 0, 100, 0.1, 2, THRONG_FIELD(agentTypes, maxSpeed)},
                {"maxForce", tr("Max force (N)"), 0, 1e6, 0.5, 1, THRONG_FIELD(agentTypes, maxForce)},
                {"mass", tr("Mass (kg)"), 0.01, 1e5, 1, 2, THRONG_FIELD(agentTypes, mass)},
                {"perception", tr("Perception (m)"), 0.1, 200, 0.5, 1, THRONG_FIELD(agentTypes, perceptionM)},
                {"viewAngle", tr("View angle (deg)"), 1, 360, 5, 0, THRONG_FIELD(agentTypes, viewAngleDeg)},
                {"minSpeed", tr("Min speed (m/s)"), 0, 100, 0.1, 2, THRONG_FIELD(agentTypes, minSpeed)},
                {"priority", tr("Priority"), -1e6, 1e6, 1, 1, THRONG_FIELD(agentTypes, priority)}};
    case ItemKind::Agent:
        return {{"x", tr("X (m)"), -1e5, 1e5, 0.1, 2, THRONG_FIELD(agents, position.x)},
                {"z", tr("Z (m)"), -1e5, 1e5, 0.1, 2, THRONG_FIELD(agents, position.z)},
                {"heading", tr("Heading (deg)"), -360, 360, 5, 1, THRONG_FIELD(agents, headingDeg)}};
    case ItemKind::Path:
        return {{"radius", tr("Radius (m)"), 0.05, 100, 0.1, 2, THRONG_FIELD(paths, radiusM)},
                {"clearance", tr("Plan clearance (m)"), 0.05, 50, 0.1, 2, THRONG_FIELD(paths, clearanceM)}};
    case ItemKind::Obstacle:
        return {{"x", tr("Centre X (m)"), -1e5, 1e5, 0.1, 2, THRONG_FIELD(obstacles, center.x)},
                {"z", tr("Centre Z (m)"), -1e5, 1e5, 0.1, 2, THRONG_FIELD(obstacles, center.y)},
                {"radius", tr("Radius (m)"), 0.05, 100, 0.1, 2, THRONG_FIELD(obstacles, radiusM)},
                {"angle", tr("Angle (deg)"), -360, 360, 5, 1, THRONG_FIELD(obstacles, angleDeg)}};
    case ItemKind::Goal:
        return {{"x", tr("X (m)"), -1e5, 1e5, 0.1, 2, THRONG_FIELD(goals, position.x)},
                {"z", tr("Z (m)"), -1e5, 1e5, 0.1, 2, THRONG_FIELD(goals, position.y)},
                {"radius", tr("Radius (m)"), 0.05, 100, 0.1, 2, THRONG_FIELD(goals, radiusM)}};
    case ItemKind::TrafficLight:
        return {{"green", tr("Green (s)"), 0, 600, 1, 1, THRONG_FIELD(trafficLights, greenS)},
                {"yellow", tr("Yellow (s)"), 0, 600, 1, 1, THRONG_FIELD(trafficLights, yellowS)},
                {"red", tr("Red (s)"), 0, 600, 1, 1, THRONG_FIELD(trafficLights, redS)},
                {"offset", tr("Offset (s)"), -600, 600, 1, 1, THRONG_FIELD(trafficLights, offsetS)}};
    case ItemKind::Lane:
        return {{"width", tr("Width (m)"), 0.5, 50, 0.1, 2, THRONG_FIELD(lanes, widthM)},
                {"speedLimit", tr("Speed limit (m/s)"), 0.1, 100, 0.5, 1, THRONG_FIELD(lanes, speedLimit)}};
    case ItemKind::FlowStroke:
        return {{"width", tr("Width (m)"), 0.1, 100, 0.5, 2, THRONG_FIELD(flowStrokes, widthM)}};
    case ItemKind::Hero:
        return {{"clearance", tr("Clearance (m)"), 0, 50, 0.1, 2, THRONG_FIELD(heroes, clearanceM)}};
    case ItemKind::Group:
        return {{"radius", tr("Circle radius (m)"), 0, 1e4, 0.5, 2, THRONG_FIELD(groups, radiusM)}};
    default:
        return {};
    }
}

#undef THRONG_FIELD
#undef THRONG_SETTING

}  // namespace

const std::vector<PropertyField>& propertyFields(ItemKind kind)
{
    static const std::vector<std::vector<PropertyField>> all = [] {
        std::vector<std::vector<PropertyField>> v;
        for (int k = 0; k <= int(ItemKind::Brain); ++k)
            v.push_back(make(ItemKind(k)));
        return v;
    }();
    return all[std::size_t(kind)];
}

}  // namespace throng::editor
