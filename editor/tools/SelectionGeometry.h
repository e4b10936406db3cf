#pragma once
// Where selectable things lie on the ground, for the select tool: an item's anchor
// point, the polylines of paths, walls and lanes, and the edit handles of a selected
// polyline (its points, and a path's radius). Plain functions over scene data.

#include "editor/SceneItem.h"

#include <glm/vec2.hpp>

#include <optional>
#include <span>
#include <vector>

namespace throng::editor {

// Where a vehicle starts: `atM` along its lane (clamped to the lane's end); empty when
// the lane is unknown.
std::optional<glm::vec2> vehicleStart(const sim::Scene& scene, const sim::Vehicle& vehicle);
// The point an agent, obstacle, goal, light, vehicle (its start) or crosswalk (its middle)
// stands on; empty for other kinds and for a vehicle on an unknown lane.
std::optional<glm::vec2> itemAnchor(const sim::Scene& scene, SceneItem item);
// The polyline of a path, wall or lane; empty for other kinds.
std::span<const glm::vec2> itemPolyline(const sim::Scene& scene, SceneItem item);

struct EditHandle {
    enum class Kind { Point, Radius };
    Kind kind = Kind::Point;
    SceneItem item;
    std::size_t point = 0;  // Point: index into the polyline
    glm::vec2 ground{0.0f};
};

// The handles shown when exactly one path, wall or lane is selected.
std::vector<EditHandle> editHandles(const sim::Scene& scene, const Selection& selection);

// Distance from `p` to a polyline, m.
float polylineDistance(std::span<const glm::vec2> points, glm::vec2 p);

}  // namespace throng::editor
