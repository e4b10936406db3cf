#pragma once
// Scenes rich in state for the checkpoint tests: the crossroads demo (traffic, a hero, A*
// errands, paths) with a brain holding memory, timer, smoothing and action state on its
// pedestrians, and a reduced evacuation (flow fields, exits).

#include "simcore/scene/Scene.h"
#include "simcore/world/FrameCache.h"
#include "simcore/world/World.h"

#include <cstddef>

namespace throng::test::state {

sim::Scene crossroads();
sim::Scene crossroadsWithBrains();
sim::Scene smallEvacuation();
// Records the world's current state and `steps` more frames.
sim::FrameCache record(sim::World& world, std::size_t steps);
// Largest distance between the same agent's positions in two frames, m.
float largestMove(const sim::FrameCache& a, std::size_t fa, const sim::FrameCache& b, std::size_t fb);

}  // namespace throng::test::state
