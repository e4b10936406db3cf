#pragma once
// Arrows on a regular ground grid for the navigation fields a World builds from a scene:
// the flow strokes' sketched field (Jin et al. 2008) and one goal's flow field. Builds them
// through simcore's own calls (never solves a field itself), caches them per scene, and
// draws into a ShapeMesh; owns no GL and never writes to the scene.

#include "editor/viewport/ShapeMesh.h"
#include "simcore/nav/FlowField.h"
#include "simcore/nav/NavGrid.h"
#include "simcore/nav/SketchField.h"
#include "simcore/scene/Scene.h"

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace throng::editor {

// One arrow, centred on its grid point.
struct FieldArrow {
    glm::vec2 centre{0.0f};     // (x, z), m
    glm::vec2 direction{0.0f};  // unit
    float lengthM = 0.0f;       // > 0, at most 0.8 * spacing
};

class FieldArrows {
public:
    static constexpr std::size_t kMaxArrows = 6000;
    static constexpr glm::vec4 kSketchColour{0.780f, 0.560f, 1.000f, 0.85f};  // violet, like the strokes
    static constexpr glm::vec4 kGoalColour{0.250f, 0.820f, 0.950f, 0.85f};    // cyan

    // Takes the parts of the scene the fields depend on (settings, walls, obstacles, lanes
    // and crosswalks as kerbs, flow strokes, goals, the navigating walkers' radii) and, when
    // they differ from the last call's, builds the grid and the sketched field again and
    // forgets the goal fields. True when it rebuilt. Slow on big scenes (a sketch solve).
    bool setScene(const sim::Scene& scene);
    // What setScene reads of a scene, small enough to keep: the set, the goals, the types,
    // the groups and one placed agent per type placed (for the walkers' inflation), the
    // rest empty. setScene(partsOf(scene)) builds what setScene(scene) does.
    static sim::Scene partsOf(const sim::Scene& scene);

    // The grid the fields lie on, inflated as WorldNav.cpp inflates it.
    const sim::NavGrid& grid() const { return m_grid; }
    bool hasSketch() const { return m_sketch.has_value(); }
    // Why the scene's flow strokes gave no sketched field; empty when they did or there are none.
    const std::string& sketchError() const { return m_sketchError; }
    std::size_t goalCount() const { return m_parts.goals.size(); }

    // Arrows at the points of a grid `spacingM` apart over the scene bounds, raised as far
    // as spacingFor() needs to stay within kMaxArrows. Only in walkable cells where the
    // field gives a direction; the sketch's only where it is as strong as the World needs
    // to follow it, and shorter where it is weaker.
    std::vector<FieldArrow> sketchArrows(float spacingM) const;
    // Builds goal goalIndex's field the first time it is asked for (not thread-safe).
    // Nothing for an index past goalCount().
    std::vector<FieldArrow> goalArrows(std::size_t goalIndex, float spacingM) const;

    void addSketchArrows(ShapeMesh& mesh, float spacingM) const;
    void addGoalArrows(std::size_t goalIndex, ShapeMesh& mesh, float spacingM) const;
    // Each arrow as two filled shapes: a shaft quad and a head triangle (9 vertices).
    static void addArrows(const std::vector<FieldArrow>& arrows, glm::vec4 colour, ShapeMesh& mesh);

    // The smallest spacing >= wantedM (m) whose grid over the bounds has at most maxArrows
    // points; wantedM itself when the bounds are empty.
    static float spacingFor(glm::vec2 boundsMin, glm::vec2 boundsMax, float wantedM, std::size_t maxArrows = kMaxArrows);
    // Points of the arrow grid `spacingM` apart over the bounds (before any is left out).
    static std::size_t gridPointCount(glm::vec2 boundsMin, glm::vec2 boundsMax, float spacingM);

private:
    template <typename DirectionAt>
    std::vector<FieldArrow> arrowsAt(float spacingM, DirectionAt&& directionAt) const;

    sim::Scene m_parts;  // only the parts setScene() reads; the rest stays empty
    float m_inflateM = 0.0f;
    bool m_built = false;
    sim::NavGrid m_grid;
    std::optional<sim::SketchField> m_sketch;
    std::string m_sketchError;
    mutable std::vector<std::unique_ptr<sim::FlowField>> m_goalFields;  // per goal, built on first use
};

}  // namespace throng::editor
