#pragma once
// Where selectable things lie on the ground, for the select tool: an item's anchor
// point, the polylines of paths, walls and lanes, the edit handles of a selected
// polyline (its points, and a path's radius), and which item a World agent belongs to.
// Plain functions over scene data.

#include "editor/SceneItem.h"
#include "simcore/world/FrameCache.h"

#include <glm/vec2.hpp>

#include <optional>
#include <span>
#include <utility>
#include <vector>

namespace throng::editor {

// Where a vehicle starts: `atM` along its lane (clamped to the lane's end); empty when
// the lane is unknown.
std::optional<glm::vec2> vehicleStart(const sim::Scene& scene, const sim::Vehicle& vehicle);
// The point an agent, obstacle, goal, light, vehicle (its start), crosswalk, source (its
// middle) or measurement (the mean of its points) stands on; empty for other kinds and for
// a vehicle on an unknown lane.
std::optional<glm::vec2> itemAnchor(const sim::Scene& scene, SceneItem item);
// The ids the World gives group `group`'s members: [first, second). Spawned agents take
// ids after every id the scene uses, group after group (World::buildAgents).
std::pair<sim::AgentId, sim::AgentId> groupMemberIds(const sim::Scene& scene, std::size_t group);
// The item World agent `id` stands for: a placed agent, the spawn group it is a member
// of, a vehicle or a hero; empty for an id the scene does not know.
std::optional<SceneItem> agentItem(const sim::Scene& scene, sim::AgentId id);
// The polyline of a path, wall or lane; empty for other kinds.
std::span<const glm::vec2> itemPolyline(const sim::Scene& scene, SceneItem item);
// Where a source lets agents in, as a polyline: its line's two ends, or its rectangle's
// corners closed (five points).
std::vector<glm::vec2> sourceOutline(const sim::Source& source);
// A measurement as a polyline: a line's two ends, or an area's corners closed.
std::vector<glm::vec2> measurementOutline(const sim::Measurement& measurement);

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
