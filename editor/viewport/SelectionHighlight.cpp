#include "editor/viewport/SelectionHighlight.h"

#include "editor/tools/SelectionGeometry.h"
#include "editor/viewport/ViewportPalette.h"

#include <array>
#include <cmath>
#include <numbers>

namespace throng::editor {

namespace {
constexpr float kLineM = 0.14f;    // half width of the outline
constexpr float kMarginM = 0.25f;  // rings stand this far outside what they mark
}  // namespace

std::vector<SelectionHighlight::AgentRing> SelectionHighlight::agentRings(const sim::Scene& s, const Selection& selection)
{
    std::vector<AgentRing> rings;
    auto radiusOf = [&s](const std::string& type, float fallbackM) {
        const sim::AgentType* t = s.findAgentType(type);
        return (t ? t->radiusM : fallbackM) + kMarginM;
    };
    for (const SceneItem& item : selection) {
        if (item.kind == ItemKind::Agent && item.index < s.agents.size()) {
            const sim::Agent& a = s.agents[item.index];
            rings.push_back({item.index, a.id, {a.position.x, a.position.z}, radiusOf(a.type, 0.3f), 0.0f,
                             palette::kSelection});
        } else if (item.kind == ItemKind::Vehicle && item.index < s.vehicles.size()) {
            const sim::Vehicle& v = s.vehicles[item.index];
            if (const std::optional<glm::vec2> start = vehicleStart(s, v))
                rings.push_back({ShownAgents::kNone, v.id, *start, radiusOf(v.type, 1.0f), 0.0f, palette::kSelection});
        } else if (item.kind == ItemKind::LayoutOp && item.index < s.layout.ops.size()) {
            // The agents a layout operation names by id, where the shown frame draws them.
            for (const std::uint32_t id : s.layout.ops[item.index].agents.ids)
                rings.push_back({ShownAgents::kNone, id, {}, 0.0f, 0.0f, palette::kSelection});
        }
    }
    return rings;
}

SelectionHighlight::AgentRing SelectionHighlight::focusRing(sim::AgentId id)
{
    return {ShownAgents::kNone, id, {}, 0.0f, 0.0f, palette::kSelection};
}

SelectionHighlight::AgentRing SelectionHighlight::inspectedRing(sim::AgentId id)
{
    return {ShownAgents::kNone, id, {}, 0.0f, 3.0f * kLineM, kInspectedColour};
}

SelectionHighlight::AgentRing SelectionHighlight::clashRing(sim::AgentId id)
{
    return {ShownAgents::kNone, id, {}, 0.0f, 6.0f * kLineM, palette::kLayoutClash};
}

void SelectionHighlight::addAgentRings(std::span<const AgentRing> rings, const ShownAgents& shown, ShapeMesh& mesh)
{
    for (const AgentRing& r : rings) {
        const std::size_t i = shown.find(r.id, r.hint);
        if (i == ShownAgents::kNone) {
            // A frame made before the agent was added: it stands where the scene has it.
            if (r.radiusM > 0.0f)
                mesh.addRing(r.start, r.radiusM, kLineM, r.colour);
            continue;
        }
        if (!shown.drawn(i))
            continue;  // gone through an exit, or absent on this frame
        const float radius = r.radiusM > 0.0f ? r.radiusM : shown.radiusM(i) + kMarginM + r.extraM;
        mesh.addRing({shown.feet(i).x, shown.feet(i).z}, radius, kLineM, r.colour);
    }
}

void SelectionHighlight::addItems(const sim::Scene& s, const Selection& selection, ShapeMesh& mesh)
{
    const glm::vec4 c = palette::kSelection;
    for (const SceneItem& item : selection) {
        const std::size_t i = item.index;
        if (i >= itemCount(s, item.kind))
            continue;
        switch (item.kind) {
        case ItemKind::Obstacle: {
            const sim::Obstacle& o = s.obstacles[i];
            if (o.shape == sim::ObstacleShape::Circle) {
                mesh.addRing(o.center, o.radiusM + kMarginM, kLineM, c);
                break;
            }
            const float a = o.angleDeg * std::numbers::pi_v<float> / 180.0f, co = std::cos(a), si = std::sin(a);
            const glm::vec2 h = 0.5f * o.size + kMarginM;
            std::array<glm::vec2, 4> box{glm::vec2(-h.x, -h.y), glm::vec2(h.x, -h.y), h, glm::vec2(-h.x, h.y)};
            for (glm::vec2& p : box)
                p = o.center + glm::vec2(p.x * co + p.y * si, -p.x * si + p.y * co);
            mesh.addPolyline(box, true, kLineM, c);
            break;
        }
        case ItemKind::Goal: mesh.addRing(s.goals[i].position, s.goals[i].radiusM + kMarginM, kLineM, c); break;
        case ItemKind::ActionPoint:
            mesh.addRing(s.actionPoints[i].position, s.actionPoints[i].radiusM + kMarginM, kLineM, c);
            break;
        case ItemKind::Source: mesh.addPolyline(sourceOutline(s.sources[i]), false, 0.08f + kLineM, c); break;
        case ItemKind::Measurement:
            mesh.addPolyline(measurementOutline(s.measurements[i]), false, 0.06f + kLineM, c);
            break;
        case ItemKind::TrafficLight: mesh.addRing(s.trafficLights[i].position, 0.6f + kMarginM, kLineM, c); break;
        case ItemKind::Path: mesh.addPolyline(s.paths[i].points, s.paths[i].closed, kLineM, c); break;
        case ItemKind::Wall: mesh.addPolyline(s.walls[i].points, false, 0.12f + kLineM, c); break;
        case ItemKind::Lane: mesh.addPolyline(s.lanes[i].points, false, kLineM, c); break;
        case ItemKind::FlowStroke: mesh.addPolyline(s.flowStrokes[i].points, false, kLineM, c); break;
        case ItemKind::Hero: {
            std::vector<glm::vec2> way;
            for (const sim::Keyframe& k : s.heroes[i].keyframes)
                way.emplace_back(k.position.x, k.position.z);
            mesh.addPolyline(way, false, kLineM, c);
            break;
        }
        case ItemKind::Crosswalk: {
            // The band's outline: the centre line pushed out by half the width each side.
            const sim::Crosswalk& w = s.crosswalks[i];
            const glm::vec2 d = w.to - w.from;
            const float len = std::hypot(d.x, d.y);
            if (!(len > 0.0f))
                break;
            const glm::vec2 side = glm::vec2(-d.y, d.x) * ((0.5f * w.widthM + kMarginM) / len);
            const std::array<glm::vec2, 4> band{w.from + side, w.to + side, w.to - side, w.from - side};
            mesh.addPolyline(band, true, kLineM, c);
            break;
        }
        case ItemKind::Group: {
            const sim::SpawnGroup& g = s.groups[i];
            if (g.shape == sim::AreaShape::Circle) {
                mesh.addRing(g.center, g.radiusM, kLineM, c);
            } else if (g.shape == sim::AreaShape::Polygon) {
                mesh.addPolyline(g.points, true, kLineM, c);
            } else {
                const std::array<glm::vec2, 4> r{g.min, glm::vec2(g.max.x, g.min.y), g.max, glm::vec2(g.min.x, g.max.y)};
                mesh.addPolyline(r, true, kLineM, c);
            }
            break;
        }
        default: break;
        }
    }
}

}  // namespace throng::editor
