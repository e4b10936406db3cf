#include "editor/viewport/FieldArrows.h"

#include "simcore/nav/NavDefaults.h"
#include "simcore/nav/NavPassages.h"
#include "simcore/nav/NavShapes.h"
#include "simcore/traffic/WalkerBarriers.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace throng::editor {

namespace {

constexpr float kArrowFraction = 0.8f;  // of the spacing: neighbouring arrows never touch

// The radius the World inflates its grid by: the largest body (plus clearance) of the
// pedestrians placed or spawned whose type navigates by A* or a flow field.
float inflateRadiusM(const sim::Scene& scene)
{
    float inflate = 0.0f;
    auto consider = [&](const std::string& typeName) {
        const sim::AgentType* t = scene.findAgentType(typeName);
        if (t && t->kind == sim::AgentKind::Pedestrian && t->navigation != sim::Navigation::Direct)
            inflate = std::max(inflate, t->radiusM + sim::kNavClearanceM);
    };
    for (const sim::Agent& a : scene.agents)
        consider(a.type);
    for (const sim::SpawnGroup& g : scene.groups)
        if (g.count > 0)
            consider(g.type);
    return inflate > 0.0f ? inflate : sim::kNavDefaultRadiusM + sim::kNavClearanceM;
}

// The walls walkers meet, as World::buildNav gathers them: walls, obstacles, and with a
// lane network its kerbs and crosswalk sides (sim::walkerBarriers).
sim::NavShapes walkerShapes(const sim::Scene& parts)
{
    sim::NavShapes shapes = sim::navShapes(parts);
    if (parts.lanes.empty())
        return shapes;
    for (const sim::BarrierSegment& b : sim::walkerBarriers(sim::LaneNetwork(parts)))
        shapes.walls.push_back({b.a, b.b});
    return shapes;
}

}  // namespace

sim::Scene FieldArrows::partsOf(const sim::Scene& scene)
{
    sim::Scene parts;
    parts.settings = scene.settings;
    parts.agentTypes = scene.agentTypes;
    parts.groups = scene.groups;
    for (const sim::Agent& a : scene.agents)
        if (std::none_of(parts.agents.begin(), parts.agents.end(), [&](const sim::Agent& b) { return b.type == a.type; }))
            parts.agents.push_back(a);
    parts.walls = scene.walls;
    parts.obstacles = scene.obstacles;
    parts.lanes = scene.lanes;
    parts.crosswalks = scene.crosswalks;
    parts.flowStrokes = scene.flowStrokes;
    parts.goals = scene.goals;
    return parts;
}

bool FieldArrows::setScene(const sim::Scene& scene)
{
    sim::Scene parts;
    parts.settings = scene.settings;
    parts.walls = scene.walls;
    parts.obstacles = scene.obstacles;
    parts.lanes = scene.lanes;
    parts.crosswalks = scene.crosswalks;
    parts.flowStrokes = scene.flowStrokes;
    parts.goals = scene.goals;
    const float inflate = inflateRadiusM(scene);
    if (m_built && parts == m_parts && inflate == m_inflateM)
        return false;
    m_parts = std::move(parts);
    m_inflateM = inflate;
    m_built = true;

    const sim::NavShapes shapes = walkerShapes(m_parts);
    m_grid.build(shapes, m_parts.settings.boundsMin, m_parts.settings.boundsMax,
                 sim::NavGridParams{m_parts.settings.navCellM, m_inflateM});
    sim::openNarrowPassages(m_grid, shapes, m_inflateM - sim::kNavClearanceM, m_inflateM);
    m_sketch.reset();
    m_sketchError.clear();
    if (!m_parts.flowStrokes.empty()) {
        sim::SketchField sketch;
        if (sketch.build(m_parts, m_grid))
            m_sketch = std::move(sketch);
        else
            m_sketchError = sketch.error();
    }
    m_goalFields.clear();
    m_goalFields.resize(m_parts.goals.size());
    return true;
}

std::vector<FieldArrow> FieldArrows::sketchArrows(float spacingM) const
{
    if (!m_sketch)
        return {};
    const sim::SketchField& field = *m_sketch;
    return arrowsAt(spacingM, [&](glm::vec2 p, sim::NavCell c) {
        const float strength = field.strength(c);
        const glm::vec2 d = strength >= sim::kSketchMinStrength ? field.sample(p) : glm::vec2(0.0f);
        return std::pair{d, std::min(strength, 1.0f)};
    });
}

std::vector<FieldArrow> FieldArrows::goalArrows(std::size_t goalIndex, float spacingM) const
{
    if (goalIndex >= m_goalFields.size())
        return {};
    std::unique_ptr<sim::FlowField>& field = m_goalFields[goalIndex];
    if (!field) {
        const sim::Goal& g = m_parts.goals[goalIndex];
        const sim::FlowGoal goal{g.position, g.radiusM};
        field = std::make_unique<sim::FlowField>();
        field->build(m_grid, std::span<const sim::FlowGoal>(&goal, 1));
    }
    return arrowsAt(spacingM, [&](glm::vec2 p, sim::NavCell) { return std::pair{field->sample(p), 1.0f}; });
}

template <typename DirectionAt>
std::vector<FieldArrow> FieldArrows::arrowsAt(float spacingM, DirectionAt&& directionAt) const
{
    std::vector<FieldArrow> arrows;
    const glm::vec2 lo = m_parts.settings.boundsMin, hi = m_parts.settings.boundsMax;
    const float spacing = spacingFor(lo, hi, spacingM);
    // The count also turns away bounds that are not finite (spacingFor leaves those be).
    const std::size_t points = gridPointCount(lo, hi, spacing);
    if (!m_built || !std::isfinite(spacing) || points == 0 || points > kMaxArrows)
        return arrows;
    // Counted as gridPointCount counts them.
    const auto cols = int(std::floor(double(hi.x - lo.x) / double(spacing)));
    const auto rows = int(std::floor(double(hi.y - lo.y) / double(spacing)));
    for (int z = 0; z < rows; ++z)
        for (int x = 0; x < cols; ++x) {
            const glm::vec2 p = lo + (glm::vec2(float(x), float(z)) + 0.5f) * spacing;
            const sim::NavCell c = m_grid.cellOf(p);
            if (!m_grid.walkable(c))
                continue;
            const auto [d, strength] = directionAt(p, c);
            const float len = glm::length(d);
            if (!(len > 1e-6f) || !(strength > 0.0f))
                continue;
            arrows.push_back({p, d / len, kArrowFraction * spacing * strength});
        }
    return arrows;
}

void FieldArrows::addSketchArrows(ShapeMesh& mesh, float spacingM) const
{
    addArrows(sketchArrows(spacingM), kSketchColour, mesh);
}

void FieldArrows::addGoalArrows(std::size_t goalIndex, ShapeMesh& mesh, float spacingM) const
{
    addArrows(goalArrows(goalIndex, spacingM), kGoalColour, mesh);
}

void FieldArrows::addArrows(const std::vector<FieldArrow>& arrows, glm::vec4 colour, ShapeMesh& mesh)
{
    // Filled shapes, not lines with round caps: a tenth of the vertices for thousands of arrows.
    for (const FieldArrow& a : arrows) {
        const glm::vec2 d = a.direction, side(-d.y, d.x);
        const glm::vec2 tail = a.centre - d * (0.5f * a.lengthM), tip = a.centre + d * (0.5f * a.lengthM);
        const glm::vec2 neck = tip - d * (0.4f * a.lengthM);
        const float shaft = 0.06f * a.lengthM, head = 0.22f * a.lengthM;
        const std::array<glm::vec2, 4> quad{tail - side * shaft, neck - side * shaft, neck + side * shaft,
                                            tail + side * shaft};
        const std::array<glm::vec2, 3> triangle{neck - side * head, tip, neck + side * head};
        mesh.addConvexPolygon(quad, colour);
        mesh.addConvexPolygon(triangle, colour);
    }
}

std::size_t FieldArrows::gridPointCount(glm::vec2 boundsMin, glm::vec2 boundsMax, float spacingM)
{
    if (!(spacingM > 0.0f))
        return 0;
    const double cols = std::floor(double(boundsMax.x - boundsMin.x) / double(spacingM));
    const double rows = std::floor(double(boundsMax.y - boundsMin.y) / double(spacingM));
    if (!(cols > 0.0) || !(rows > 0.0))
        return 0;
    const double n = cols * rows;
    return n < 1e18 ? std::size_t(n) : std::size_t(1e18);
}

float FieldArrows::spacingFor(glm::vec2 boundsMin, glm::vec2 boundsMax, float wantedM, std::size_t maxArrows)
{
    const glm::vec2 extent = boundsMax - boundsMin;
    const double area = double(extent.x) * double(extent.y);
    if (!(extent.x > 0.0f) || !(extent.y > 0.0f) || !std::isfinite(area))
        return wantedM;
    maxArrows = std::max<std::size_t>(maxArrows, 1);
    // cols * rows <= (w / s) * (h / s) = maxArrows at this spacing; the loop only absorbs rounding.
    float spacing = std::max(wantedM, float(std::sqrt(area / double(maxArrows))));
    while (gridPointCount(boundsMin, boundsMax, spacing) > maxArrows)
        spacing *= 1.001f;
    return spacing;
}

}  // namespace throng::editor
