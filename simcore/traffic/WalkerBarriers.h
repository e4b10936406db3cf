#pragma once
// The walls walkers meet along a lane network: its kerbs (pedestrianBarriers), and both
// sides of each crosswalk's strip in full, the stretch over the pavement too, so a walker
// steps onto a crossing only over an end line, where the signal answers it, never
// sideways from the pavement beside it. The World steers and plans round them; the
// editor's field arrows lay out the same grid.

#include "simcore/traffic/LaneNetwork.h"

#include <vector>

namespace throng::sim {

std::vector<BarrierSegment> walkerBarriers(const LaneNetwork& net);

}  // namespace throng::sim
