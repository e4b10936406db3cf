#pragma once
// The layout tests' shot: the square of kSquare (two groups crossing it, twelve walkers
// heading east, eight runners heading north, one placed agent in a group of its own)
// recorded for 80 frames, and what the tests read off it. Header only.

#include "export/TrajectoryCsv.h"
#include "export/UsdExporter.h"
#include "simcore/io/SceneIO.h"
#include "simcore/layout/LayoutApply.h"
#include "simcore/world/FrameCache.h"
#include "simcore/world/World.h"

#include <QFile>
#include <QString>
#include <QtGlobal>

#include <glm/vec2.hpp>

#include <cstdint>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace throng::test::layout {

inline const char* const kSquare = R"(throng: 1
settings: {fps: 10, duration: 8, seed: 4, bounds: {min: [-30, -30], max: [30, 30]}}
agent_types:
  - {name: walker, radius: 0.3}
  - {name: runner, radius: 0.3, max_speed: 3}
goals:
  - {name: east, position: [20, 0], radius: 2}
  - {name: north, position: [0, -20], radius: 2}
groups:
  - {name: eastbound, type: walker, count: 12, rect: {min: [-15, -4], max: [-10, 4]}, goal: east}
  - {name: northbound, type: runner, count: 8, rect: {min: [-4, 10], max: [4, 14]}, goal: north}
agents:
  - {id: 1, type: walker, position: [-12, -10], goal: east, group: loner}
)";

struct Shot {
    sim::Scene scene;
    sim::FrameCache cache;
};

inline Shot record(const std::string& yaml, std::uint64_t seed = 4)
{
    Shot s;
    const sim::LoadResult loaded = sim::parseScene(yaml, "square.yaml", "");
    if (!loaded.ok())
        qFatal("%s", loaded.diagnostics[0].format().c_str());
    s.scene = loaded.scene;
    s.scene.settings.seed = seed;
    sim::World world(s.scene);
    world.startRecording(s.cache);
    std::vector<sim::AgentFrame> frame;
    for (int f = 1; f < 80; ++f) {
        world.step();
        world.snapshot(frame);
        s.cache.append(frame);
    }
    return s;
}

inline std::size_t indexOf(const sim::FrameCache& cache, std::uint32_t id)
{
    for (std::size_t i = 0; i < cache.agentCount(); ++i)
        if (cache.agents()[i].id == id)
            return i;
    qFatal("no agent %u", id);
}

inline glm::vec2 xz(const sim::AgentFrame& a) { return {a.position.x, a.position.z}; }

inline bool sameFrame(const sim::AgentFrame& a, const sim::AgentFrame& b)
{
    return a.position == b.position && a.headingRad == b.headingRad && a.speed == b.speed && a.phase == b.phase &&
           a.clip == b.clip && a.out == b.out && a.present == b.present && a.arrived == b.arrived;
}

inline sim::LayoutOp op(sim::LayoutKind kind, std::vector<std::uint32_t> ids)
{
    sim::LayoutOp o;
    o.kind = kind;
    o.agents.ids = std::move(ids);
    return o;
}

// Expand (factor > 1) or squeeze (< 1) the members of `group` about their centre.
inline sim::LayoutOp expandGroup(const std::string& group, float factor)
{
    sim::LayoutOp o;
    o.kind = sim::LayoutKind::Expand;
    o.agents.groups = {group};
    o.factor = factor;
    return o;
}

// The trajectories CSV of `cache`, written to `path` and read back: by agent id, frame ->
// the row's text.
inline std::map<std::uint32_t, std::map<int, std::string>> csvRows(const sim::FrameCache& cache,
                                                                   const std::string& path)
{
    if (!exporting::writeTrajectoryCsv(cache, path).ok())
        qFatal("cannot write %s", path.c_str());
    std::map<std::uint32_t, std::map<int, std::string>> rows;
    std::ifstream in(path);
    std::string line;
    std::getline(in, line);
    while (std::getline(in, line)) {
        std::istringstream s(line);
        std::string frame, agent;
        std::getline(s, frame, ',');
        std::getline(s, agent, ',');
        rows[std::uint32_t(std::stoul(agent))][std::stoi(frame)] = line;
    }
    return rows;
}

// The laid-out shot written as USD (the far characters, no set) and read back as text, as
// a reader sees it; empty when it could not be written or read.
inline QString usdText(const sim::Scene& scene, const sim::FrameCache& laid, const QString& path)
{
    exporting::UsdOptions usd;
    usd.path = path.toStdString();
    usd.lod = exporting::Lod::Far;
    usd.includeSet = false;
    if (!exporting::exportUsd(scene, laid, usd).ok())
        return {};
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? QString::fromUtf8(file.readAll()) : QString();
}

}  // namespace throng::test::layout
