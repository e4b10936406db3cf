#include "editor/viewport/TrailBuilder.h"

#include "editor/viewport/ViewportPalette.h"

#include <algorithm>
#include <vector>

namespace throng::editor {

void TrailBuilder::add(const sim::FrameCache& cache, std::size_t frame, std::span<const std::size_t> agents,
                       std::size_t lengthFrames, ShapeMesh& mesh)
{
    if (frame >= cache.frameCount() || lengthFrames == 0)
        return;
    constexpr float kHalfWidthM = 0.05f;
    const std::size_t first = frame >= lengthFrames ? frame - lengthFrames + 1 : 0;
    std::vector<glm::vec2> piece;
    for (std::size_t k = 0; k < agents.size() && k < kMaxTrails; ++k) {
        const std::size_t agent = agents[k];
        if (agent >= cache.agentCount())
            continue;
        // Piece by piece from the oldest frame; each piece shares its last point with the
        // next, so the trail has no gaps, and is more opaque the newer it is.
        for (std::size_t start = first; start < frame; start += kFramesPerPiece) {
            const std::size_t end = std::min(frame, start + kFramesPerPiece);
            const float age = float(frame - end) / float(lengthFrames);
            const glm::vec4 colour(palette::kTrail.r, palette::kTrail.g, palette::kTrail.b,
                                   palette::kTrail.a * (1.0f - age));
            piece.clear();
            auto flush = [&] {
                if (piece.size() >= 2)
                    mesh.addPolyline(piece, false, kHalfWidthM, colour);
                piece.clear();
            };
            for (std::size_t f = start; f <= end; ++f) {
                const sim::AgentFrame& a = cache.at(f, agent);
                if (!a.present || a.out) {
                    flush();
                    continue;
                }
                piece.emplace_back(a.position.x, a.position.z);
            }
            flush();
        }
    }
}

}  // namespace throng::editor
