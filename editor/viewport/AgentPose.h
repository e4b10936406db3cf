#pragma once
// Which character pose one shown agent wears, beside its AgentGlyph: plain data the
// viewport fills from the agent's look and recorded clip and phase.

#include <cstdint>

namespace throng::editor {

struct AgentPose {
    int character = -1;       // the character (AgentCharacters' index), -1 = no character (a glyph)
    int pose = 0;             // PoseTable pose index
    float heightScale = 1.0f; // uniform scale of the character, > 0
    // Per material slot s from skin (1) to bag (8), its palette colour in bits 3(s-1)..;
    // bit 24 + s - 7: the accessory of slot s (hat 7, bag 8) is worn.
    std::uint32_t lookBits = 0;
};

}  // namespace throng::editor
