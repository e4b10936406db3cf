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
    const std::size_t span = frame - first;  // frames between the oldest point and the newest
    const std::size_t step = std::max<std::size_t>(1, (span + kMaxPoints - 2) / (kMaxPoints - 1));
    // The frames a trail passes through: the shown one, then back by `step`.
    std::vector<std::size_t> frames;
    for (std::size_t f = frame;; f -= step) {
        frames.push_back(f);
        if (f < first + step)
            break;
    }
    std::reverse(frames.begin(), frames.end());
    std::vector<glm::vec2> piece;
    for (std::size_t k = 0; k < agents.size() && k < kMaxTrails; ++k) {
        const std::size_t agent = agents[k];
        if (agent >= cache.agentCount())
            continue;
        // Piece by piece from the oldest point; each piece shares its last point with the
        // next, so the trail has no gaps, and is more opaque the newer it is.
        for (std::size_t start = 0; start + 1 < frames.size(); start += kPointsPerPiece) {
            const std::size_t end = std::min(frames.size() - 1, start + kPointsPerPiece);
            const float age = float(frame - frames[end]) / float(lengthFrames);
            const glm::vec4 colour(palette::kTrail.r, palette::kTrail.g, palette::kTrail.b,
                                   palette::kTrail.a * (1.0f - age));
            piece.clear();
            auto flush = [&] {
                if (piece.size() >= 2)
                    mesh.addPolyline(piece, false, kHalfWidthM, colour);
                piece.clear();
            };
            for (std::size_t p = start; p <= end; ++p) {
                const sim::AgentFrame& a = cache.at(frames[p], agent);
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
