#pragma once
// Narrow passages kept open on a walking grid. The grid walkers plan on is the set inflated
// by their body radius and a clearance (NavDefaults.h), so that plans keep off the walls;
// but where a passage is narrower than twice that, the clearance closes it although the
// body fits, and a flow field or plan then finds no way through: walkers stood in front of
// a 0.8 m passage for good. This reopens the cells that lie between shapes on opposite
// sides, each farther than the body's own reach (NavGrid's rule for the body alone) from
// every shape; cells near a single wall keep their clearance. Never moves agents.

#include "simcore/nav/NavGrid.h"
#include "simcore/nav/NavShapes.h"

namespace throng::sim {

// Reopens the blocked cells of `grid` (built with the shapes inflated by inflateM) that a
// body of bodyRadiusM fits in and that lie in a passage: within inflateM of one shape and
// within inflateM and a cell of another on the opposite side of the cell's centre (more than
// 120 degrees round from the first). Returns
// how many it reopened.
std::size_t openNarrowPassages(NavGrid& grid, const NavShapes& shapes, float bodyRadiusM, float inflateM);

}  // namespace throng::sim
