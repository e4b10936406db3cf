#pragma once
// The unit shapes fliers are drawn with, one instance per bird: a body, a tail and two
// spread wings raised a little towards their tips, nose along +x. Radius 1 is half the
// wingspan, and y is in the same unit (the glyph shader's u_bird), so a bird keeps its
// proportions when it is widened to stay a few pixels wide far away. Flattened (y = 0)
// in the top view. Three levels of detail: a close-up, a coarse bird of four triangles
// and a far bird of two (as cheap as an impostor quad). CPU data only, no GL.

#include "editor/viewport/AgentGlyphMesh.h"

#include <vector>

namespace throng::editor {

class BirdGlyphMesh {
public:
    // Wing roots and the body's middle lie this high, wing tips kTipY; units of the radius.
    static constexpr float kRootY = 0.12f;
    static constexpr float kTipY = 0.32f;

    static std::vector<GlyphVertex> detailed();
    static std::vector<GlyphVertex> coarse();
    static std::vector<GlyphVertex> far();
};

}  // namespace throng::editor
