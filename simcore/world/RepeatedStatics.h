#pragma once
// Drops exact repeats of static geometry (wall segments either way round, identical
// obstacles) so that a pasted set does not multiply the work of every wall query.
// Keeps the first of each and the order of the rest; never moves or merges near-repeats.

#include "simcore/scene/Scene.h"
#include "simcore/base/SegmentGrid.h"

#include <vector>

namespace throng::sim {

// Metres round the bounds that the wall and obstacle grids cover (agents stay inside the
// bounds; geometry beyond lands in the border cells).
constexpr float kStaticGridMarginM = 100.0f;

void removeRepeatedSegments(std::vector<Segment>& segments);
std::vector<Obstacle> uniqueObstacles(const std::vector<Obstacle>& obstacles);

}  // namespace throng::sim
