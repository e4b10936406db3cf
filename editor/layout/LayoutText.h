#pragma once
// How the editor words a layout operation (sim::LayoutOp): which agents it edits, on which
// frames, and what it does to them, for the Layout panel's rows and the properties panel.
// Reads the operation only; no scene, no recording.

#include "simcore/layout/LayoutLayer.h"

#include <QString>

namespace throng::editor {

// "agents 1, 2, 5; group crowd; type walker; a lasso on frame 40" ("nobody" when empty).
QString selectorText(const sim::AgentSelector& agents);
// "every frame", "frames 10 to 40", "from frame 10 on".
QString framesText(const sim::LayoutOp& op);
// "by (2.00, 0.00) m", "by 90.0°", "15 frames later, holding the first pose", ...
QString effectText(const sim::LayoutOp& op);
// The three together: "agents 1, 2 · by (2.00, 0.00) m · every frame".
QString layoutSummary(const sim::LayoutOp& op);

}  // namespace throng::editor
