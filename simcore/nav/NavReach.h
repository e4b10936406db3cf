#pragma once
// Which places a body of one radius can walk between: the connected regions of a grid of
// the set inflated by that radius (less a cell's width, so a door the body fits through is
// never closed by rounding). Answers "can an agent here get into that disk at all"; never
// plans a way and never moves agents.

#include "simcore/nav/NavGrid.h"
#include "simcore/nav/NavShapes.h"

#include <glm/vec2.hpp>

#include <cstdint>
#include <vector>

namespace throng::sim {

class NavReach {
public:
    // The cells cover the bounds; cellM > 0 (finer cells judge narrow doors better).
    void build(const NavShapes& shapes, glm::vec2 boundsMin, glm::vec2 boundsMax, float bodyRadiusM, float cellM);
    bool built() const { return !m_region.empty(); }
    float bodyRadiusM() const { return m_bodyRadiusM; }

    // The region of the walkable cell nearest p, if one lies within a body radius and a
    // cell of it (a body brushing a wall stands in the inflated margin); -1 when none does.
    std::int32_t regionAt(glm::vec2 p) const;
    // Whether some place within radiusM of centre (an exit's or goal's disk) is walkable
    // for the body: else nobody of this radius can get into it.
    bool enterable(glm::vec2 centre, float radiusM) const;
    // Whether a body at `from` can walk into the disk (centre, radiusM).
    bool reaches(glm::vec2 from, glm::vec2 centre, float radiusM) const;

    // A cell edge that keeps a grid over these bounds to about 4 million cells at most.
    static float cellFor(glm::vec2 boundsMin, glm::vec2 boundsMax, float finestM);

private:
    NavGrid m_grid;
    std::vector<std::int32_t> m_region;  // per cell: connected region of walkable cells, -1 blocked
    float m_bodyRadiusM = 0.0f;
};

}  // namespace throng::sim
