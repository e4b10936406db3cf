#include "simcore/world/RepeatedStatics.h"

#include <algorithm>
#include <array>
#include <numeric>
#include <tuple>

namespace throng::sim {

namespace {

// Indices of the items to keep: the first of each run of equal keys, in input order.
template <typename Key>
std::vector<std::size_t> firstOfEach(const std::vector<Key>& keys)
{
    std::vector<std::size_t> order(keys.size());
    std::iota(order.begin(), order.end(), std::size_t(0));
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return keys[a] < keys[b]; });
    std::vector<std::size_t> keep;
    for (std::size_t k = 0; k < order.size(); ++k)
        if (k == 0 || keys[order[k]] != keys[order[k - 1]])
            keep.push_back(order[k]);
    std::sort(keep.begin(), keep.end());
    return keep;
}

}  // namespace

void removeRepeatedSegments(std::vector<Segment>& segments)
{
    using Key = std::array<float, 4>;
    std::vector<Key> keys;
    keys.reserve(segments.size());
    for (const Segment& s : segments) {
        glm::vec2 a = s.a, b = s.b;
        if (std::tie(b.x, b.y) < std::tie(a.x, a.y))
            std::swap(a, b);
        keys.push_back({a.x, a.y, b.x, b.y});
    }
    const std::vector<std::size_t> keep = firstOfEach(keys);
    if (keep.size() == segments.size())
        return;
    std::vector<Segment> out;
    out.reserve(keep.size());
    for (std::size_t k : keep)
        out.push_back(segments[k]);
    segments = std::move(out);
}

std::vector<Obstacle> uniqueObstacles(const std::vector<Obstacle>& obstacles)
{
    using Key = std::array<float, 7>;
    std::vector<Key> keys;
    keys.reserve(obstacles.size());
    for (const Obstacle& o : obstacles) {
        const bool circle = o.shape == ObstacleShape::Circle;
        keys.push_back({circle ? 0.0f : 1.0f, o.center.x, o.center.y, circle ? o.radiusM : 0.0f,
                        circle ? 0.0f : o.size.x, circle ? 0.0f : o.size.y, circle ? 0.0f : o.angleDeg});
    }
    std::vector<Obstacle> out;
    for (std::size_t k : firstOfEach(keys))
        out.push_back(obstacles[k]);
    return out;
}

}  // namespace throng::sim
