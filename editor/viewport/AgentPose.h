#pragma once
// Which character pose one shown agent wears, beside its AgentGlyph: plain data the
// viewport fills from the agent's look and recorded clip and phase.

namespace throng::editor {

struct AgentPose {
    int character = -1;       // index into the renderer's pose tables, -1 = no character (a glyph)
    int pose = 0;             // PoseTable pose index
    float heightScale = 1.0f; // uniform scale of the character, > 0
};

}  // namespace throng::editor
