#include "editor/panels/PropertyFields.h"

#include <QCoreApplication>

namespace throng::editor {

namespace {

QString tr(const char* text)
{
    return QCoreApplication::translate("PropertyFields", text);
}

// Refuses a coordinate of a crosswalk's end (`to` or from, axis 0 = x, 1 = z) that would
// put both ends on one point, which the scene check rejects.
std::function<QString(const sim::Scene&, std::size_t, float)> crosswalkEnd(bool to, int axis)
{
    return [to, axis](const sim::Scene& s, std::size_t i, float value) {
        const sim::Crosswalk& c = s.crosswalks[i];
        glm::vec2 moved = to ? c.to : c.from;
        moved[axis] = value;
        if (moved != (to ? c.from : c.to))
            return QString();
        return tr("The ends of crosswalk %1 cannot be the same point: it stays as it is.")
            .arg(itemLabel(s, {ItemKind::Crosswalk, i}));
    };
}

using Refusal = std::function<QString(const sim::Scene&, std::size_t, float)>;
using RangeOf = std::function<glm::vec2(const sim::Scene&, std::size_t)>;

// Refuses the lower end of a [min, max] pair (`lower`) above its upper end, or the upper
// end below the lower one: the scene check rejects both.
Refusal rangeEnd(ItemKind kind, RangeOf range, bool lower)
{
    return [kind, range, lower](const sim::Scene& s, std::size_t i, float value) {
        const glm::vec2 r = range(s, i);
        if (lower ? value <= r.y : value >= r.x)
            return QString();
        const QString item = itemLabel(s, {kind, i});
        return lower ? tr("%1: a minimum cannot exceed its maximum (%2); it stays as it is.").arg(item).arg(double(r.y))
                     : tr("%1: a maximum cannot be below its minimum (%2); it stays as it is.").arg(item).arg(double(r.x));
    };
}

// A group's rectangle along one axis (0 = x, 1 = z), its altitude range, a type's ranges.
Refusal cornerEnd(int axis, bool lower)
{
    return rangeEnd(ItemKind::Group, [axis](const sim::Scene& s, std::size_t i) {
        return glm::vec2(s.groups[i].min[axis], s.groups[i].max[axis]);
    }, lower);
}

Refusal altitudeEnd(bool lower)
{
    return rangeEnd(ItemKind::Group, [](const sim::Scene& s, std::size_t i) { return s.groups[i].altitudeM; }, lower);
}

Refusal variationEnd(glm::vec2 sim::Variation::*range, bool lower)
{
    return rangeEnd(ItemKind::AgentType, [range](const sim::Scene& s, std::size_t i) {
        return s.agentTypes[i].variation.*range;
    }, lower);
}

Refusal trafficRangeEnd(glm::vec2 sim::TrafficSettings::*range, bool lower)
{
    return rangeEnd(ItemKind::Settings, [range](const sim::Scene& s, std::size_t) { return s.traffic.*range; }, lower);
}

// A source's corners along one axis (0 = x, 1 = z).
Refusal sourceCornerEnd(int axis, bool lower)
{
    return rangeEnd(ItemKind::Source, [axis](const sim::Scene& s, std::size_t i) {
        return glm::vec2(s.sources[i].min[axis], s.sources[i].max[axis]);
    }, lower);
}

// Refuses a source's rate of 0 or less, and one that lets in more than the scene check
// allows over the run when the source has no cap.
Refusal sourceRateRefusal()
{
    return [](const sim::Scene& s, std::size_t i, float value) {
        const QString item = itemLabel(s, {ItemKind::Source, i});
        if (!(value > 0.0f))
            return tr("%1: the rate must be above 0 agents a second; it stays as it is.").arg(item);
        if (s.sources[i].cap == 0 && double(value) * double(s.settings.durationS) > 1e7)
            return tr("%1: that rate lets in more than 10,000,000 agents over the run; set a cap first. It stays "
                      "as it is.").arg(item);
        return QString();
    };
}

// Refuses a formation's spacing closer than two of its walkers' bodies (the file refuses it).
Refusal formationSpacingRefusal()
{
    return [](const sim::Scene& s, std::size_t i, float value) {
        const sim::AgentType* type = s.findAgentType(s.groups[i].type);
        if (type && value < 2.0f * type->radiusM)
            return tr("%1: slots closer than two of its walkers' bodies (%2 m) could not hold them; the spacing stays "
                      "as it is.")
                .arg(itemLabel(s, {ItemKind::Group, i}))
                .arg(double(2.0f * type->radiusM));
        return QString();
    };
}

// Refuses a coordinate of a mirror's axis point `end` (axis 0 = x, 1 = z) that would put
// both points of the line on one place: a line needs two.
Refusal mirrorAxisEnd(int end, int axis)
{
    return [end, axis](const sim::Scene& s, std::size_t i, float value) {
        const sim::LayoutOp& op = s.layout.ops[std::size_t(i)];
        glm::vec2 moved = op.axis[end];
        moved[axis] = value;
        if (moved != op.axis[1 - end])
            return QString();
        return tr("%1: the mirror's line needs two different points; it stays as it is.")
            .arg(itemLabel(s, {ItemKind::LayoutOp, i}));
    };
}

bool isFlier(const sim::Scene& s, std::size_t i)
{
    return s.agentTypes[i].kind == sim::AgentKind::Flier;
}

bool isWalker(const sim::Scene& s, std::size_t i)
{
    return s.agentTypes[i].kind == sim::AgentKind::Pedestrian;
}

#define THRONG_TRAFFIC(member) [](sim::Scene& s, std::size_t) -> float& { return s.traffic.member; }
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
                {"navCell", tr("Navigation cell (m)"), 0.05, 10, 0.05, 2, THRONG_SETTING(navCellM)},
                // The crossroads' knobs (sim::TrafficSettings).
                {"walkerDelayMin", tr("Walker delay min (s)"), 0, 60, 0.1, 2, THRONG_TRAFFIC(walkerStartDelayS.x),
                 trafficRangeEnd(&sim::TrafficSettings::walkerStartDelayS, true)},
                {"walkerDelayMax", tr("Walker delay max (s)"), 0, 60, 0.1, 2, THRONG_TRAFFIC(walkerStartDelayS.y),
                 trafficRangeEnd(&sim::TrafficSettings::walkerStartDelayS, false)},
                {"driverDelayMin", tr("Driver delay min (s)"), 0, 60, 0.1, 2, THRONG_TRAFFIC(driverStartDelayS.x),
                 trafficRangeEnd(&sim::TrafficSettings::driverStartDelayS, true)},
                {"driverDelayMax", tr("Driver delay max (s)"), 0, 60, 0.1, 2, THRONG_TRAFFIC(driverStartDelayS.y),
                 trafficRangeEnd(&sim::TrafficSettings::driverStartDelayS, false)},
                {"crossingMargin", tr("Crossing margin (m)"), 0, 50, 0.1, 2, THRONG_TRAFFIC(crossingMarginM)},
                {"walkerClearance", tr("Walker clearance (m)"), 0, 20, 0.1, 2, THRONG_TRAFFIC(walkerClearanceM)},
                {"waitingSpeed", tr("Waiting speed (m/s)"), 0, 5, 0.01, 3, THRONG_TRAFFIC(waitingSpeed)},
                {"yieldHorizon", tr("Yield horizon (s)"), 0.1, 60, 0.5, 1, THRONG_TRAFFIC(yieldHorizonS)}};
    case ItemKind::AgentType:
        return {{"radius", tr("Radius (m)"), 0.05, 20, 0.05, 2, THRONG_FIELD(agentTypes, radiusM)},
                {"maxSpeed", tr("Max speed (m/s)"), 0, 100, 0.1, 2, THRONG_FIELD(agentTypes, maxSpeed),
                 rangeEnd(ItemKind::AgentType, [](const sim::Scene& s, std::size_t i) {
                     return glm::vec2(s.agentTypes[i].minSpeed, s.agentTypes[i].maxSpeed);
                 }, false)},
                {"maxForce", tr("Max force (N)"), 0, 1e6, 0.5, 1, THRONG_FIELD(agentTypes, maxForce)},
                {"mass", tr("Mass (kg)"), 0.01, 1e5, 1, 2, THRONG_FIELD(agentTypes, mass)},
                {"perception", tr("Perception (m)"), 0.1, 200, 0.5, 1, THRONG_FIELD(agentTypes, perceptionM)},
                {"viewAngle", tr("View angle (deg)"), 1, 360, 5, 0, THRONG_FIELD(agentTypes, viewAngleDeg)},
                {"minSpeed", tr("Min speed (m/s)"), 0, 100, 0.1, 2, THRONG_FIELD(agentTypes, minSpeed),
                 rangeEnd(ItemKind::AgentType, [](const sim::Scene& s, std::size_t i) {
                     return glm::vec2(s.agentTypes[i].minSpeed, s.agentTypes[i].maxSpeed);
                 }, true), isFlier},
                {"banking", tr("Banking (s^2/m)"), 0, 10, 0.01, 3, THRONG_FIELD(agentTypes, banking), {}, isFlier},
                {"priority", tr("Priority"), -1e6, 1e6, 1, 1, THRONG_FIELD(agentTypes, priority)},
                {"actionBlend", tr("Action blend (s; -1 = each action's own)"), -1, 10, 0.05, 2,
                 THRONG_FIELD(agentTypes, actionBlendS)},
                {"timeGap", tr("Time gap (s; 0 = none)"), 0, 10, 0.05, 2, THRONG_FIELD(agentTypes, timeGapS), {},
                 isWalker},
                {"heightMin", tr("Height scale min"), 0.01, 10, 0.05, 2, THRONG_FIELD(agentTypes, variation.heightScale.x),
                 variationEnd(&sim::Variation::heightScale, true)},
                {"heightMax", tr("Height scale max"), 0.01, 10, 0.05, 2, THRONG_FIELD(agentTypes, variation.heightScale.y),
                 variationEnd(&sim::Variation::heightScale, false)},
                {"speedFactorMin", tr("Speed factor min"), 0.01, 10, 0.05, 2, THRONG_FIELD(agentTypes, variation.speedFactor.x),
                 variationEnd(&sim::Variation::speedFactor, true)},
                {"speedFactorMax", tr("Speed factor max"), 0.01, 10, 0.05, 2, THRONG_FIELD(agentTypes, variation.speedFactor.y),
                 variationEnd(&sim::Variation::speedFactor, false)},
                {"phaseMin", tr("Phase offset min"), 0, 1, 0.05, 2, THRONG_FIELD(agentTypes, variation.phaseOffset.x),
                 variationEnd(&sim::Variation::phaseOffset, true)},
                {"phaseMax", tr("Phase offset max"), 0, 1, 0.05, 2, THRONG_FIELD(agentTypes, variation.phaseOffset.y),
                 variationEnd(&sim::Variation::phaseOffset, false)},
                {"reactionMin", tr("Reaction time min (s)"), 0, 1e5, 1, 1, THRONG_FIELD(agentTypes, variation.reactionS.x),
                 variationEnd(&sim::Variation::reactionS, true), isWalker},
                {"reactionMax", tr("Reaction time max (s)"), 0, 1e5, 1, 1, THRONG_FIELD(agentTypes, variation.reactionS.y),
                 variationEnd(&sim::Variation::reactionS, false), isWalker}};
    case ItemKind::Agent:
        return {{"x", tr("X (m)"), -1e5, 1e5, 0.1, 2, THRONG_FIELD(agents, position.x)},
                {"z", tr("Z (m)"), -1e5, 1e5, 0.1, 2, THRONG_FIELD(agents, position.z)},
                {"heading", tr("Heading (deg)"), -360, 360, 5, 1, THRONG_FIELD(agents, headingDeg)}};
    case ItemKind::Path:
        return {{"radius", tr("Radius (m)"), 0.05, 100, 0.1, 2, THRONG_FIELD(paths, radiusM)},
                {"clearance", tr("Plan clearance (m)"), 0.05, 50, 0.1, 2, THRONG_FIELD(paths, clearanceM)}};
    case ItemKind::Obstacle: {
        const auto box = [](const sim::Scene& s, std::size_t i) { return s.obstacles[i].shape == sim::ObstacleShape::Box; };
        const auto circle = [box](const sim::Scene& s, std::size_t i) { return !box(s, i); };
        return {{"x", tr("Centre X (m)"), -1e5, 1e5, 0.1, 2, THRONG_FIELD(obstacles, center.x)},
                {"z", tr("Centre Z (m)"), -1e5, 1e5, 0.1, 2, THRONG_FIELD(obstacles, center.y)},
                {"radius", tr("Radius (m)"), 0.05, 100, 0.1, 2, THRONG_FIELD(obstacles, radiusM), {}, circle},
                {"width", tr("Width (m)"), 0.05, 1000, 0.1, 2, THRONG_FIELD(obstacles, size.x), {}, box},
                {"depth", tr("Depth (m)"), 0.05, 1000, 0.1, 2, THRONG_FIELD(obstacles, size.y), {}, box},
                {"angle", tr("Angle (deg)"), -360, 360, 5, 1, THRONG_FIELD(obstacles, angleDeg), {}, box}};
    }
    case ItemKind::Goal:
        return {{"x", tr("X (m)"), -1e5, 1e5, 0.1, 2, THRONG_FIELD(goals, position.x)},
                {"z", tr("Z (m)"), -1e5, 1e5, 0.1, 2, THRONG_FIELD(goals, position.y)},
                {"radius", tr("Radius (m)"), 0.05, 100, 0.1, 2, THRONG_FIELD(goals, radiusM)}};
    case ItemKind::ActionPoint: {
        const auto faces = [](const sim::Scene& s, std::size_t i) { return s.actionPoints[i].faces; };
        return {{"x", tr("X (m)"), -1e5, 1e5, 0.1, 2, THRONG_FIELD(actionPoints, position.x)},
                {"z", tr("Z (m)"), -1e5, 1e5, 0.1, 2, THRONG_FIELD(actionPoints, position.y)},
                {"radius", tr("Radius (m)"), 0.05, 100, 0.1, 2, THRONG_FIELD(actionPoints, radiusM)},
                {"duration", tr("Duration (s)"), 0.05, 36000, 0.5, 2, THRONG_FIELD(actionPoints, durationS)},
                {"facing", tr("Facing (deg)"), -360, 360, 5, 1, THRONG_FIELD(actionPoints, facingDeg), {}, faces},
                {"chance", tr("Chance (0 to 1)"), 0, 1, 0.05, 2, THRONG_FIELD(actionPoints, chance)}};
    }
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
    case ItemKind::Group: {
        const auto circle = [](const sim::Scene& s, std::size_t i) { return s.groups[i].shape == sim::AreaShape::Circle; };
        const auto rect = [](const sim::Scene& s, std::size_t i) { return s.groups[i].shape == sim::AreaShape::Rect; };
        const auto flier = [](const sim::Scene& s, std::size_t i) {
            const sim::AgentType* type = s.findAgentType(s.groups[i].type);
            return type && type->kind == sim::AgentKind::Flier;
        };
        const auto formed = [](const sim::Scene& s, std::size_t i) {
            return s.groups[i].formation.shape != sim::FormationShape::None;
        };
        return {{"minX", tr("Min X (m)"), -1e5, 1e5, 0.5, 2, THRONG_FIELD(groups, min.x), cornerEnd(0, true), rect},
                {"minZ", tr("Min Z (m)"), -1e5, 1e5, 0.5, 2, THRONG_FIELD(groups, min.y), cornerEnd(1, true), rect},
                {"maxX", tr("Max X (m)"), -1e5, 1e5, 0.5, 2, THRONG_FIELD(groups, max.x), cornerEnd(0, false), rect},
                {"maxZ", tr("Max Z (m)"), -1e5, 1e5, 0.5, 2, THRONG_FIELD(groups, max.y), cornerEnd(1, false), rect},
                {"centreX", tr("Centre X (m)"), -1e5, 1e5, 0.5, 2, THRONG_FIELD(groups, center.x), {}, circle},
                {"centreZ", tr("Centre Z (m)"), -1e5, 1e5, 0.5, 2, THRONG_FIELD(groups, center.y), {}, circle},
                {"radius", tr("Radius (m)"), 0.05, 1e4, 0.5, 2, THRONG_FIELD(groups, radiusM), {}, circle},
                {"altitudeMin", tr("Altitude min (m)"), 0, 1e4, 0.5, 2, THRONG_FIELD(groups, altitudeM.x),
                 altitudeEnd(true), flier},
                {"altitudeMax", tr("Altitude max (m)"), 0, 1e4, 0.5, 2, THRONG_FIELD(groups, altitudeM.y),
                 altitudeEnd(false), flier},
                {"formationSpacing", tr("Formation spacing (m)"), 0.1, 100, 0.1, 2,
                 THRONG_FIELD(groups, formation.spacingM), formationSpacingRefusal(), formed}};
    }
    case ItemKind::Crosswalk:
        return {{"fromX", tr("From X (m)"), -1e5, 1e5, 0.1, 2, THRONG_FIELD(crosswalks, from.x), crosswalkEnd(false, 0)},
                {"fromZ", tr("From Z (m)"), -1e5, 1e5, 0.1, 2, THRONG_FIELD(crosswalks, from.y), crosswalkEnd(false, 1)},
                {"toX", tr("To X (m)"), -1e5, 1e5, 0.1, 2, THRONG_FIELD(crosswalks, to.x), crosswalkEnd(true, 0)},
                {"toZ", tr("To Z (m)"), -1e5, 1e5, 0.1, 2, THRONG_FIELD(crosswalks, to.y), crosswalkEnd(true, 1)},
                {"width", tr("Width (m)"), 0.1, 50, 0.1, 2, THRONG_FIELD(crosswalks, widthM)}};
    case ItemKind::Source: {
        using Shape = sim::SourceShape;
        const auto line = [](const sim::Scene& s, std::size_t i) { return s.sources[i].shape == Shape::Line; };
        const auto rect = [](const sim::Scene& s, std::size_t i) { return s.sources[i].shape == Shape::Rect; };
        const auto headed = [](const sim::Scene& s, std::size_t i) { return s.sources[i].headed; };
        return {{"fromX", tr("From X (m)"), -1e5, 1e5, 0.1, 2, THRONG_FIELD(sources, from.x), {}, line},
                {"fromZ", tr("From Z (m)"), -1e5, 1e5, 0.1, 2, THRONG_FIELD(sources, from.y), {}, line},
                {"toX", tr("To X (m)"), -1e5, 1e5, 0.1, 2, THRONG_FIELD(sources, to.x), {}, line},
                {"toZ", tr("To Z (m)"), -1e5, 1e5, 0.1, 2, THRONG_FIELD(sources, to.y), {}, line},
                {"minX", tr("Min X (m)"), -1e5, 1e5, 0.5, 2, THRONG_FIELD(sources, min.x),
                 sourceCornerEnd(0, true), rect},
                {"minZ", tr("Min Z (m)"), -1e5, 1e5, 0.5, 2, THRONG_FIELD(sources, min.y),
                 sourceCornerEnd(1, true), rect},
                {"maxX", tr("Max X (m)"), -1e5, 1e5, 0.5, 2, THRONG_FIELD(sources, max.x),
                 sourceCornerEnd(0, false), rect},
                {"maxZ", tr("Max Z (m)"), -1e5, 1e5, 0.5, 2, THRONG_FIELD(sources, max.y),
                 sourceCornerEnd(1, false), rect},
                {"rate", tr("Rate (agents/s)"), 0, 1e5, 0.1, 3, THRONG_FIELD(sources, rate), sourceRateRefusal()},
                {"heading", tr("Heading (deg)"), -360, 360, 5, 1, THRONG_FIELD(sources, headingDeg), {}, headed}};
    }
    case ItemKind::LayoutOp: {
        using K = sim::LayoutKind;
        const auto is = [](sim::LayoutKind kind) {
            return [kind](const sim::Scene& s, std::size_t i) { return s.layout.ops[i].kind == kind; };
        };
        const auto moves = [](const sim::Scene& s, std::size_t i) {
            return s.layout.ops[i].kind == K::Translate || s.layout.ops[i].kind == K::Duplicate;
        };
        return {{"offsetX", tr("Offset X (m)"), -1e5, 1e5, 0.1, 2, THRONG_FIELD(layout.ops, offset.x), {}, moves},
                {"offsetZ", tr("Offset Z (m)"), -1e5, 1e5, 0.1, 2, THRONG_FIELD(layout.ops, offset.y), {}, moves},
                {"angle", tr("Angle (deg)"), -3600, 3600, 5, 1, THRONG_FIELD(layout.ops, angleDeg), {}, is(K::Rotate)},
                {"factor", tr("Factor"), 0.01, 100, 0.1, 2, THRONG_FIELD(layout.ops, factor), {}, is(K::Expand)},
                {"axisFromX", tr("Axis from X (m)"), -1e5, 1e5, 0.5, 2, THRONG_FIELD(layout.ops, axis[0].x),
                 mirrorAxisEnd(0, 0), is(K::Mirror)},
                {"axisFromZ", tr("Axis from Z (m)"), -1e5, 1e5, 0.5, 2, THRONG_FIELD(layout.ops, axis[0].y),
                 mirrorAxisEnd(0, 1), is(K::Mirror)},
                {"axisToX", tr("Axis to X (m)"), -1e5, 1e5, 0.5, 2, THRONG_FIELD(layout.ops, axis[1].x),
                 mirrorAxisEnd(1, 0), is(K::Mirror)},
                {"axisToZ", tr("Axis to Z (m)"), -1e5, 1e5, 0.5, 2, THRONG_FIELD(layout.ops, axis[1].y),
                 mirrorAxisEnd(1, 1), is(K::Mirror)}};
    }
    case ItemKind::Vehicle:
        return {{"at", tr("Start distance (m)"), 0, 1e5, 0.5, 2, THRONG_FIELD(vehicles, atM)},
                {"speed", tr("Initial speed (m/s)"), 0, 100, 0.5, 2, THRONG_FIELD(vehicles, speed)}};
    default:
        return {};
    }
}

#undef THRONG_FIELD
#undef THRONG_SETTING
#undef THRONG_TRAFFIC

}  // namespace

const std::vector<PropertyField>& propertyFields(ItemKind kind)
{
    static const std::vector<std::vector<PropertyField>> all = [] {
        std::vector<std::vector<PropertyField>> v;
        for (int k = 0; k < kItemKindCount; ++k)
            v.push_back(make(ItemKind(k)));
        return v;
    }();
    return all[std::size_t(kind)];
}

}  // namespace throng::editor
