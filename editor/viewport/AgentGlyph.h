#pragma once
// One agent as the renderer draws it: plain data, uploaded as is (two vec4 per instance);
// and one kind of them with the characters they wear.

#include "editor/viewport/AgentPose.h"

#include <glm/vec3.hpp>

#include <span>

namespace throng::editor {

// 32 bytes per instance.
struct AgentGlyph {
    glm::vec3 position{0.0f};  // m
    float headingRad = 0.0f;   // 0 = +x, counter-clockwise seen from above
    float radiusM = 0.3f;      // > 0
    glm::vec3 colour{1.0f};    // RGB in 0..1
};

// One kind of agent to draw: its glyphs and, empty or one per glyph, the characters they
// wear (see AgentRenderer::setCharacters).
struct AgentBatch {
    std::span<const AgentGlyph> glyphs;
    std::span<const AgentPose> poses;
};

}  // namespace throng::editor
