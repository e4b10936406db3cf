#pragma once
// The unit shapes vehicles are drawn with, one instance per car: a top-view rectangle
// with windscreen, rear window and headlights, and a perspective body with a cabin.
// Front along +x; lengths in units of the agent radius (a 1.1 m radius gives a 4.4 m by
// 1.8 m car), y in [0, 1] of the agent's height. CPU data only, no GL.

#include "editor/viewport/AgentGlyphMesh.h"

#include <vector>

namespace throng::editor {

class CarGlyphMesh {
public:
    static constexpr float kHalfLength = 2.0f;
    static constexpr float kHalfWidth = 0.82f;

    static std::vector<GlyphVertex> flat();
    static std::vector<GlyphVertex> solid();
};

}  // namespace throng::editor
