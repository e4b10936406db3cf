#pragma once
// Shared by the demo tests: load a scene (failing on any diagnostic), run it, hash its
// frames, and the figures a user reads off a run. Header only; links throng::simcore.

#include "simcore/io/SceneIO.h"
#include "simcore/world/FrameCache.h"
#include "simcore/world/World.h"
#include "simcore/world/WorldBrain.h"

#include <glm/geometric.hpp>

#include <QtGlobal>

#include <cstdint>
#include <string>
#include <vector>

namespace throng::test::demos {

// A scene from text; any error or warning fails the test.
inline sim::Scene parse(const std::string& yaml)
{
    const sim::LoadResult r = sim::parseScene(yaml, "scene.yaml", THRONG_SOURCE_DIR "/resources/scenes");
    if (!r.diagnostics.empty())
        qFatal("%s", r.diagnostics[0].format().c_str());
    return r.scene;
}

// A shipped demo scene; any error or warning fails the test.
inline sim::Scene demo(const std::string& name)
{
    const sim::LoadResult r = sim::loadScene(THRONG_SOURCE_DIR "/resources/scenes/" + name);
    if (!r.diagnostics.empty())
        qFatal("%s", r.diagnostics[0].format().c_str());
    return r.scene;
}

inline sim::WorldOptions threads(int n)
{
    sim::WorldOptions o;
    o.threads = n;
    return o;
}

// Runs `steps` steps and returns the recorded frames' hash: equal hashes = identical runs.
inline std::uint64_t runHash(const sim::Scene& scene, int threadCount, int steps)
{
    sim::World world(scene, threads(threadCount));
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

inline glm::vec2 ground(glm::vec3 p) { return {p.x, p.z}; }

}  // namespace throng::test::demos
