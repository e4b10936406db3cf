#pragma once
// The order a World with fliers steps its agents in is its neighbour grid's: rows of cells
// along z, the cells of a row along x, each cell from the ground up. Agents stored in
// another order are read and written all over memory at every step; stored in the grid's
// order, a million birds step 1.2 times as fast. No result depends on the order
// (worldstate.TestStorageOrder): every agent keeps its id, and with it everything it does.

#include "simcore/scene/Scene.h"

#include <cstddef>

namespace throng::sim {

// From this many placed agents, the order is worth the sort.
inline constexpr std::size_t kGridOrderFrom = 65'536;

// Puts a scene's placed agents in the order its World's grid steps them in, when the scene
// has fliers (without them the World steps agents in the stored order) and at least `from`
// placed agents; true when it reordered them. Each agent
// keeps everything it has, id included. For a scene run headless (throng-cli run and
// bench): the editor's outliner, checkpoints and resume read placed agents by their place
// in the scene, so the document's own scene is never reordered.
bool orderPlacedForGrid(Scene& scene, std::size_t from = kGridOrderFrom);

}  // namespace throng::sim
