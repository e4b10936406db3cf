#pragma once
// Shared by the nav tests: random small grids, a brute-force shortest-path reference that
// knows nothing of A*, and exact geometry used to check rasterisation.

#include "simcore/nav/NavGrid.h"

#include <random>
#include <vector>

namespace throng::test {

// cols x rows cells of 1 m from (0, 0), each blocked with probability density.
sim::NavGrid randomGrid(std::mt19937& gen, int cols, int rows, float density);

// Dense O(V^2) Dijkstra from source over the 8-connected grid (diagonals only where both
// side cells are walkable), in cells; unreachable cells hold a negative value.
std::vector<double> bruteForceDistances(const sim::NavGrid& grid, sim::NavCell source);

// True when the cells form a legal 8-connected walk on walkable cells without corner cutting.
bool legalWalk(const sim::NavGrid& grid, const std::vector<sim::NavCell>& cells);

// Every point sampled every stepM along the polyline of cell centres lies in a walkable cell.
bool polylineStaysWalkable(const sim::NavGrid& grid, const std::vector<sim::NavCell>& corners, float stepM);

float pointSegmentDistance(glm::vec2 p, glm::vec2 a, glm::vec2 b);

// Angle between two directions, degrees in [0, 180]; 180 when either is zero.
float angleDeg(glm::vec2 a, glm::vec2 b);

// Three maps used by the field tests: open ground, a room with a door, a maze of walls.
sim::Scene fieldTestScene(int which);

}  // namespace throng::test
