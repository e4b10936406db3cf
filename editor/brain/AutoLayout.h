#pragma once
// Layered layout for brain graphs read without editor positions: each node goes one
// column right of the furthest node feeding it (links into memory nodes are loop backs
// and do not count), rows ordered by their inputs' rows. Changes positions only.

#include "simcore/scene/BrainGraph.h"

namespace throng::editor {

// True when no two nodes have distinct positions (a graph written by hand or a tool).
bool needsLayout(const sim::BrainGraph& graph);
void autoLayout(sim::BrainGraph& graph);

}  // namespace throng::editor
