#include "simcore/scene/TerrainHeight.h"

#include <algorithm>

namespace throng::sim {

float terrainHeight(const Terrain& t, float x, float z)
{
    if (t.heights.size() < std::size_t(t.cols) * t.rows || t.cols < 2 || t.rows < 2 || !(t.cellM > 0.0f))
        return 0.0f;
    const float fx = std::clamp((x - t.origin.x) / t.cellM, 0.0f, float(t.cols - 1));
    const float fz = std::clamp((z - t.origin.y) / t.cellM, 0.0f, float(t.rows - 1));
    const auto x0 = std::min(std::uint32_t(fx), t.cols - 2), z0 = std::min(std::uint32_t(fz), t.rows - 2);
    const float u = fx - float(x0), v = fz - float(z0);
    auto h = [&](std::uint32_t cx, std::uint32_t cz) { return t.heights[std::size_t(cz) * t.cols + cx]; };
    return (h(x0, z0) * (1 - u) + h(x0 + 1, z0) * u) * (1 - v) + (h(x0, z0 + 1) * (1 - u) + h(x0 + 1, z0 + 1) * u) * v;
}

}  // namespace throng::sim
