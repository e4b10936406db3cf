#pragma once
// Plane geometry of a simple polygon on the ground (corners (x, z) in order, closed from
// the last back to the first): its area, whether it crosses itself, containment, the
// nearest point of its outline and a triangulation. Pure functions; they never keep or
// change the corners.

#include <glm/vec2.hpp>

#include <array>
#include <cstddef>
#include <optional>
#include <span>
#include <utility>
#include <vector>

namespace throng::sim {

// Shoelace area in m², > 0 when the corners run counter-clockwise in (x, z).
double signedPolygonArea(std::span<const glm::vec2> corners);
double polygonArea(std::span<const glm::vec2> corners);

// The first pair of edges (i, j), i < j, that cross or touch though they are not
// neighbours, or neighbours that fold back over each other; edge i runs from corner i
// to corner i + 1 (the last edge back to corner 0). Empty when the polygon is simple.
// A zero-length edge (a corner repeated) touches its neighbours and counts as a crossing.
std::optional<std::pair<std::size_t, std::size_t>> polygonSelfCrossing(std::span<const glm::vec2> corners);

// Even-odd rule; a point exactly on the outline may fall either way.
bool polygonContains(std::span<const glm::vec2> corners, glm::vec2 p);

// The nearest point to p on the outline.
glm::vec2 nearestOnPolygonOutline(std::span<const glm::vec2> corners, glm::vec2 p);

// Ear clipping (Eberly, "Triangulation by Ear Clipping"): corners.size() - 2 triangles
// covering a simple polygon, counter-clockwise. O(n²) corners; a polygon that crosses
// itself gets as many triangles as could be clipped.
using GroundTriangle = std::array<glm::vec2, 3>;
std::vector<GroundTriangle> triangulatePolygon(std::span<const glm::vec2> corners);

}  // namespace throng::sim
