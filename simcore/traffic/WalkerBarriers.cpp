#include "simcore/traffic/WalkerBarriers.h"

namespace throng::sim {

std::vector<BarrierSegment> walkerBarriers(const LaneNetwork& net)
{
    std::vector<BarrierSegment> walls = net.pedestrianBarriers();
    for (std::size_t c = 0; c < net.crosswalkCount(); ++c) {
        const CrosswalkStrip& s = net.crosswalk(int(c));
        const glm::vec2 side = glm::vec2(-s.dir.y, s.dir.x) * s.halfWidthM;
        walls.push_back({s.a + side, s.b + side});
        walls.push_back({s.a - side, s.b - side});
    }
    return walls;
}

}  // namespace throng::sim
