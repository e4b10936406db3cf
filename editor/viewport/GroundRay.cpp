#include "editor/viewport/GroundRay.h"

#include "editor/tools/TerrainHeight.h"

#include <glm/matrix.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <cmath>

namespace throng::editor {

std::optional<glm::vec3> castToGround(const glm::mat4& viewProjection, QSize sizePx, QPointF pixel,
                                      const sim::Terrain& terrain)
{
    const glm::mat4 inverse = glm::inverse(viewProjection);
    const float ndcX = float(2.0 * pixel.x() / std::max(1, sizePx.width()) - 1.0);
    const float ndcY = float(1.0 - 2.0 * pixel.y() / std::max(1, sizePx.height()));
    const glm::vec4 nearH = inverse * glm::vec4(ndcX, ndcY, -1.0f, 1.0f);
    const glm::vec4 farH = inverse * glm::vec4(ndcX, ndcY, 1.0f, 1.0f);
    const glm::vec3 from = glm::vec3(nearH) / nearH.w, to = glm::vec3(farH) / farH.w;
    const glm::vec3 dir = to - from;
    if (terrain.heights.empty()) {
        if (std::abs(dir.y) < 1e-9f)
            return std::nullopt;
        const float t = -from.y / dir.y;
        if (t < 0.0f || t > 1.0f)
            return std::nullopt;
        return from + t * dir;
    }
    // March the ray in short steps until it passes under the terrain, then bisect.
    constexpr int kSteps = 512, kBisections = 24;
    auto above = [&](float t) {
        const glm::vec3 p = from + t * dir;
        return p.y - terrainHeight(terrain, p.x, p.z);
    };
    float previous = 0.0f;
    if (above(previous) < 0.0f)
        return std::nullopt;
    for (int i = 1; i <= kSteps; ++i) {
        const float t = float(i) / float(kSteps);
        if (above(t) >= 0.0f) {
            previous = t;
            continue;
        }
        float lo = previous, hi = t;
        for (int k = 0; k < kBisections; ++k) {
            const float mid = 0.5f * (lo + hi);
            (above(mid) >= 0.0f ? lo : hi) = mid;
        }
        const glm::vec3 p = from + hi * dir;
        return glm::vec3(p.x, terrainHeight(terrain, p.x, p.z), p.z);
    }
    return std::nullopt;
}

}  // namespace throng::editor
