#pragma once
// The unit shapes every agent is drawn with, one instance per agent: a flat disc with a
// darker rim and a nose wedge pointing along +x (top view), and an upright prism with
// the same cap (perspective). Radius 1, height 1; CPU data only, no GL.

#include <glm/vec3.hpp>

#include <vector>

namespace throng::editor {

enum class GlyphPart { Body = 0, Rim = 1, Nose = 2 };

struct GlyphVertex {
    glm::vec3 position{0.0f};  // unit radius in x/z, y in [0, 1] of the agent's height
    glm::vec3 normal{0.0f, 1.0f, 0.0f};
    float part = 0.0f;         // a GlyphPart, as the shader reads it
};

class AgentGlyphMesh {
public:
    // Fraction of the radius where the rim starts; the nose spans kNoseFrom..kNoseTo along +x.
    static constexpr float kRimFrom = 0.84f;
    static constexpr float kNoseFrom = 0.30f;
    static constexpr float kNoseTo = 0.96f;

    // Segments around the circle: kDetailed for close-ups, kCoarse (no rim) for crowds
    // of many small glyphs, where vertex work dominates the frame.
    static constexpr int kDetailed = 28;
    static constexpr int kCoarse = 6;

    static std::vector<GlyphVertex> flat(int segments = kDetailed);
    static std::vector<GlyphVertex> prism(int segments = kDetailed);

private:
    static void addCap(std::vector<GlyphVertex>& out, float y, float noseLiftY, int segments);
};

}  // namespace throng::editor
