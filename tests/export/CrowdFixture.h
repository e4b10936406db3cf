#pragma once
// A hand-made recording for the exporter tests: three agents of two types walking straight
// lines at constant velocity, so every frame's true value is known in closed form. Never
// runs a World. Test-only.

#include "simcore/scene/Scene.h"
#include "simcore/world/FrameCache.h"

#include <glm/vec3.hpp>

#include <cstddef>

namespace throng::test {

struct CrowdFixture {
    static constexpr float kFps = 24.0f;
    static constexpr std::size_t kFrames = 49;  // 0 .. 2 s
    static constexpr std::size_t kMiddleFrame = 24;

    sim::Scene scene;      // types "walker" (radius 0.3) and "runner" (radius 0.25, tinted)
    sim::FrameCache cache; // agents 7 (walker, +x), 42 (runner, -z), 1000 (walker, +x+z, climbing)

    static CrowdFixture make();
    // A big synthetic crowd of one type "walker" wearing the four humanoid looks: agents
    // on a 2 m grid, each its own heading and pace (standing, strolling, walking, jogging,
    // running), every third stopping half-way. Deterministic.
    static CrowdFixture makeCrowd(std::size_t agents, std::size_t frames);
    // Where dense agent `agent` truly is at `frame`: start + velocity * frame / fps.
    static glm::vec3 truePosition(std::size_t agent, std::size_t frame);
    // Its direction of travel on the ground, unit length (x, 0, z).
    static glm::vec3 trueGroundDirection(std::size_t agent);
};

}  // namespace throng::test
