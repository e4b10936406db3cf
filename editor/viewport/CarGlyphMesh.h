#pragma once
// The unit shapes vehicles are drawn with, one instance per car: a top-view rectangle
// with windscreen, rear window and headlights, and a perspective body with a cabin.
// Front along +x; lengths in units of the agent radius, in the proportions of export's
// car (a 1.1 m radius gives its 4.2 m by 1.76 m, which fits the 4.2 m between the centres
// of cars queueing at a light), y in [0, 1] of the agent's height. CPU data only, no GL.

#include "editor/viewport/AgentGlyphMesh.h"

#include <vector>

namespace throng::editor {

class CarGlyphMesh {
public:
    static constexpr float kHalfLength = 1.9f;
    static constexpr float kHalfWidth = 0.8f;

    static std::vector<GlyphVertex> flat();
    static std::vector<GlyphVertex> solid();
};

}  // namespace throng::editor
