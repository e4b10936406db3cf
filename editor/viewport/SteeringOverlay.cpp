#include "editor/viewport/SteeringOverlay.h"

#include "editor/viewport/ViewportPalette.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

namespace throng::editor {

namespace {
constexpr float kArrowLineM = 0.035f;
constexpr float kArrowM = 0.05f;
constexpr float kTinyForceN = 1e-3f;
constexpr float kFieldArrowM = 0.35f;  // the length of a field sample's arrow

glm::vec2 xz(glm::vec3 v) { return {v.x, v.z}; }

void addArrow(ShapeMesh& mesh, glm::vec2 from, glm::vec2 vector, float halfWidthM, glm::vec4 colour)
{
    const float length = glm::length(vector);
    if (!(length > 1e-4f))
        return;
    const glm::vec2 dir = vector / length, side(-dir.y, dir.x);
    const glm::vec2 tip = from + vector;
    const float head = std::min(0.3f, 0.35f * length);
    mesh.addLine(from, tip, halfWidthM, colour);
    mesh.addLine(tip, tip - dir * head + side * (0.5f * head), halfWidthM, colour);
    mesh.addLine(tip, tip - dir * head - side * (0.5f * head), halfWidthM, colour);
}

void addViewCone(ShapeMesh& mesh, const sim::AgentDebug& a)
{
    if (!(a.rangeM > 0.0f) || !(a.viewAngleRad > 0.0f))
        return;
    const glm::vec2 c = xz(a.position);
    const glm::vec2 f = glm::length(xz(a.forward)) > 0.0f ? glm::normalize(xz(a.forward)) : glm::vec2(1.0f, 0.0f);
    const float heading = std::atan2(f.y, f.x);
    const float half = 0.5f * std::min(a.viewAngleRad, 6.2831853f);
    constexpr int kSlices = 24;
    std::vector<glm::vec2> arc;
    for (int k = 0; k <= kSlices; ++k) {
        const float angle = heading - half + 2.0f * half * float(k) / float(kSlices);
        arc.push_back(c + a.rangeM * glm::vec2(std::cos(angle), std::sin(angle)));
    }
    // Convex slices: a cone wider than half a turn is not convex as a whole.
    for (int k = 0; k < kSlices; ++k) {
        const std::array<glm::vec2, 3> slice{c, arc[std::size_t(k)], arc[std::size_t(k) + 1]};
        mesh.addConvexPolygon(slice, palette::kViewCone);
    }
    const bool whole = a.viewAngleRad >= 6.28f;
    if (!whole) {
        arc.insert(arc.begin(), c);
        arc.push_back(c);
    }
    mesh.addPolyline(arc, whole, 0.02f, palette::kViewConeEdge);
}
}  // namespace

glm::vec4 SteeringOverlay::behaviourColour(sim::Behaviour behaviour)
{
    return glm::vec4(AgentColours::categoryColour(int(behaviour)), 1.0f);
}

void SteeringOverlay::add(std::span<const sim::AgentDebug> agents, ShapeMesh& mesh)
{
    for (const sim::AgentDebug& a : agents) {
        const glm::vec2 p = xz(a.position);
        addViewCone(mesh, a);
        for (const sim::AgentDebug::Seen& n : a.neighbours) {
            mesh.addLine(p, xz(n.position), kArrowLineM * 0.7f, palette::kNeighbourLink);
            mesh.addRing(xz(n.position), 0.35f, 0.025f, palette::kNeighbourLink);
        }
        if (a.path.size() >= 2) {
            std::vector<glm::vec2> way;
            for (const glm::vec3& q : a.path)
                way.push_back(xz(q));
            mesh.addDashedPolyline(way, kArrowLineM, 0.4f, 0.25f, palette::kPlannedPath);
        }
        if (a.hasTarget) {
            mesh.addRing(xz(a.target), 0.3f, 0.04f, palette::kSteerTarget);
            mesh.addLine(p, xz(a.target), 0.015f, glm::vec4(glm::vec3(palette::kSteerTarget), 0.5f));
        }
        for (const sim::AgentDebug::Feeler& feeler : a.feelers)
            mesh.addLine(xz(feeler.from), xz(feeler.to), kArrowLineM, palette::kFeeler);
        // The field it follows: a short arrow from each sample along its direction (none
        // where it has none).
        for (const sim::AgentDebug::FieldSample& f : a.field)
            addArrow(mesh, xz(f.at), xz(f.direction) * kFieldArrowM, kArrowM * 0.6f, palette::kFlowArrow);
        for (const sim::AgentDebug::Force& f : a.forces) {
            const glm::vec3 weighted = f.force * f.weight;
            if (glm::length(weighted) > kTinyForceN)
                addArrow(mesh, p, xz(weighted) * kMetresPerNewton, kArrowM, behaviourColour(f.behaviour));
        }
        addArrow(mesh, p, xz(a.velocity) * kMetresPerMps, kArrowM, palette::kVelocity);
        addArrow(mesh, p, xz(a.steering) * kMetresPerNewton, kArrowM * 1.6f, palette::kSteeringForce);
    }
}

ColourLegend SteeringOverlay::describe(const sim::AgentDebug& a)
{
    ColourLegend legend;
    char text[160];
    std::snprintf(text, sizeof text, "Agent %u: %.2f m/s, %zu neighbours, steering %.2f N", unsigned(a.id),
                  double(glm::length(a.velocity)), a.neighbours.size(), double(glm::length(a.steering)));
    legend.title = text;
    std::vector<const sim::AgentDebug::Force*> forces;
    for (const sim::AgentDebug::Force& f : a.forces)
        forces.push_back(&f);
    std::stable_sort(forces.begin(), forces.end(), [](const auto* x, const auto* y) {
        return glm::length(x->force * x->weight) > glm::length(y->force * y->weight);
    });
    for (const sim::AgentDebug::Force* f : forces) {
        std::snprintf(text, sizeof text, "%s %.2f N", sim::behaviourName(f->behaviour),
                      double(glm::length(f->force * f->weight)));
        legend.entries.push_back({text, glm::vec3(behaviourColour(f->behaviour))});
    }
    return legend;
}

}  // namespace throng::editor
