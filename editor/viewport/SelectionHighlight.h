#pragma once
// Outlines the selected items in the selection colour: rings around agents, obstacles,
// goals and lights, bands along paths, walls and lanes, a hero's way and a group's area.
// Builds ShapeMesh triangles from plain scene data; never touches GL.

#include "editor/SceneItem.h"
#include "editor/viewport/ShapeMesh.h"

namespace throng::editor {

class SelectionHighlight {
public:
    static void add(const sim::Scene& scene, const Selection& selection, ShapeMesh& mesh);
};

}  // namespace throng::editor
