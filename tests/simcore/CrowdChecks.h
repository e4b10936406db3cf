#pragma once
// What the crowd tests measure, computed from the World's public state only: geometry
// against the scene's walls and paths, overlaps, finiteness. Test-only; never steers.

#include "simcore/io/SceneIO.h"
#include "simcore/world/World.h"

#include <glm/geometric.hpp>

#include <QtGlobal>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace throng::test::crowd {

// One thread: these tests are about behaviour, and a shared 2-core machine runs them
// faster without OpenMP's spinning threads. Thread independence has its own test.
inline const sim::WorldOptions kSerial{0, false, 1};

struct WallSegment2 {
    glm::vec2 a, b;
};

inline sim::Scene parse(const std::string& yaml)
{
    const sim::LoadResult r = sim::parseScene(yaml, "test.yaml", "");
    if (!r.ok())
        qFatal("%s", r.diagnostics[0].format().c_str());
    return r.scene;
}

inline glm::vec2 xz(glm::vec3 v) { return {v.x, v.z}; }

inline float cross2(glm::vec2 a, glm::vec2 b) { return a.x * b.y - a.y * b.x; }

// True when the move p0 -> p1 ends strictly on the other side of segment a-b and passes
// between its ends (a move that starts or ends on the line does not count).
inline bool crosses(glm::vec2 p0, glm::vec2 p1, glm::vec2 a, glm::vec2 b)
{
    const double s0 = cross2(b - a, p0 - a), s1 = cross2(b - a, p1 - a);
    const double t0 = cross2(p1 - p0, a - p0), t1 = cross2(p1 - p0, b - p0);
    return s0 * s1 < 0.0 && t0 * t1 < 0.0;
}

inline float distanceToSegment(glm::vec2 p, glm::vec2 a, glm::vec2 b)
{
    const glm::vec2 ab = b - a;
    const float len2 = glm::dot(ab, ab);
    const float t = len2 > 0.0f ? std::clamp(glm::dot(p - a, ab) / len2, 0.0f, 1.0f) : 0.0f;
    return glm::distance(p, a + ab * t);
}

inline float distanceToPolyline(glm::vec2 p, const std::vector<glm::vec2>& points)
{
    float best = INFINITY;
    for (std::size_t k = 0; k + 1 < points.size(); ++k)
        best = std::min(best, distanceToSegment(p, points[k], points[k + 1]));
    return best;
}

inline std::vector<WallSegment2> wallSegments(const sim::Scene& scene)
{
    std::vector<WallSegment2> out;
    for (const sim::Wall& w : scene.walls)
        for (std::size_t k = 0; k + 1 < w.points.size(); ++k)
            out.push_back({w.points[k], w.points[k + 1]});
    return out;
}

// Moves from `before` to the world's current positions that cross any of `walls`.
inline std::size_t wallCrossings(const std::vector<glm::vec3>& before, const sim::World& world,
                                 const std::vector<WallSegment2>& walls)
{
    std::size_t n = 0;
    for (std::size_t i = 0; i < world.agentCount(); ++i)
        for (const WallSegment2& w : walls)
            n += crosses(xz(before[i]), xz(world.positions()[i]), w.a, w.b);
    return n;
}

// Pairs whose bodies overlap by more than `toleranceM` (all pairs; for small crowds).
inline std::size_t overlapsBeyond(const sim::World& world, float toleranceM)
{
    std::size_t n = 0;
    const auto p = world.positions();
    const auto r = world.radii();
    for (std::size_t i = 0; i < world.agentCount(); ++i)
        for (std::size_t j = i + 1; j < world.agentCount(); ++j)
            n += glm::distance(xz(p[i]), xz(p[j])) < r[i] + r[j] - toleranceM;
    return n;
}

inline bool finite(glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Runs `steps` steps and returns the recorded frames' hash: equal hashes = identical runs.
inline std::uint64_t runHash(const sim::Scene& scene, int threads, int steps, std::uint64_t seed = 0)
{
    sim::WorldOptions o;
    o.threads = threads;
    if (seed) {
        o.overrideSeed = true;
        o.seed = seed;
    }
    sim::World world(scene, o);
    sim::FrameCache cache;
    world.startRecording(cache);
    std::vector<sim::AgentFrame> frame;
    for (int s = 0; s < steps; ++s) {
        world.step();
        world.snapshot(frame);
        cache.append(frame);
    }
    return cache.hash();
}

inline std::vector<glm::vec3> copyPositions(const sim::World& world)
{
    return {world.positions().begin(), world.positions().end()};
}

}  // namespace throng::test::crowd
