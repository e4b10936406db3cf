#pragma once
// Trails behind the followed agents: where each stood over the recorded frames before the
// shown one, as polylines fading with age and broken where the agent was absent or gone.
// Reads the frame cache; plain geometry for ShapeMesh, no GL.

#include "editor/viewport/ShapeMesh.h"
#include "simcore/world/FrameCache.h"

#include <cstddef>
#include <span>

namespace throng::editor {

class TrailBuilder {
public:
    // Most trails drawn at once (the first ones of `agents`).
    static constexpr std::size_t kMaxTrails = 256;
    // Points of one trail at most: a longer trail takes every second, third, ... frame
    // (an agent walks a few decimetres between them), so its cost does not grow with the
    // frame rate or the length asked for.
    static constexpr std::size_t kMaxPoints = 32;
    // Points of one trail drawn with the same opacity.
    static constexpr std::size_t kPointsPerPiece = 6;

    // Trails of cache agents `agents` over frames (frame - lengthFrames, frame] of `cache`.
    static void add(const sim::FrameCache& cache, std::size_t frame, std::span<const std::size_t> agents,
                    std::size_t lengthFrames, ShapeMesh& mesh);
};

}  // namespace throng::editor
