#pragma once
// Shared helpers of the worldnav tests: load a scene from text or a demo file, run a World
// until a condition holds or a time runs out, and scale the evacuation hall.

#include "simcore/io/SceneIO.h"
#include "simcore/world/World.h"

#include <QTest>

#include <functional>
#include <string>

namespace throng::test {

inline sim::Scene parse(const std::string& yaml)
{
    const sim::LoadResult r = sim::parseScene(yaml, "scene.yaml", THRONG_SOURCE_DIR "/resources");
    if (!r.ok())
        qFatal("%s", r.diagnostics[0].format().c_str());
    return r.scene;
}

inline sim::Scene loadDemo(const char* name)
{
    const sim::LoadResult r = sim::loadScene(std::string(THRONG_SOURCE_DIR "/resources/scenes/") + name);
    if (!r.ok())
        qFatal("%s", r.diagnostics[0].format().c_str());
    return r.scene;
}

// Steps until done(world) or maxS seconds of simulated time; returns the steps taken.
inline std::size_t runUntil(sim::World& world, double maxS, const std::function<bool(const sim::World&)>& done)
{
    std::size_t steps = 0;
    while (world.timeS() < maxS && !done(world)) {
        world.step();
        ++steps;
    }
    return steps;
}

inline std::size_t arrivedCount(const sim::World& world)
{
    std::size_t n = 0;
    for (std::size_t i = 0; i < world.agentCount(); ++i)
        n += world.hasArrived(i) ? 1 : 0;
    return n;
}

inline std::size_t outCount(const sim::World& world)
{
    std::size_t n = 0;
    for (std::size_t i = 0; i < world.agentCount(); ++i)
        n += world.isOut(i) ? 1 : 0;
    return n;
}

// The evacuation hall scaled by s about the origin (walls, pillars, exits, spawn areas,
// bounds), with `total` people shared over its groups in proportion.
inline sim::Scene scaledEvacuation(float s, std::uint32_t total)
{
    sim::Scene scene = loadDemo("evacuation.yaml");
    scene.settings.boundsMin *= s;
    scene.settings.boundsMax *= s;
    for (sim::Wall& w : scene.walls)
        for (glm::vec2& p : w.points)
            p *= s;
    for (sim::Obstacle& o : scene.obstacles)
        o.center *= s;
    for (sim::Goal& g : scene.goals) {
        g.position *= s;
        g.radiusM *= s;
    }
    std::uint32_t before = 0;
    for (const sim::SpawnGroup& g : scene.groups)
        before += g.count;
    std::uint32_t left = total;
    for (std::size_t k = 0; k < scene.groups.size(); ++k) {
        sim::SpawnGroup& g = scene.groups[k];
        g.min *= s;
        g.max *= s;
        g.count = k + 1 == scene.groups.size() ? left : std::uint32_t(std::uint64_t(g.count) * total / before);
        left -= g.count;
    }
    return scene;
}

}  // namespace throng::test
