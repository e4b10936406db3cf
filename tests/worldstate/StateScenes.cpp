#include "StateScenes.h"

#include "simcore/io/SceneIO.h"

#include <glm/geometric.hpp>

#include <QFile>
#include <QTest>

#include <algorithm>
#include <stdexcept>
#include <string>

namespace throng::test::state {

namespace {

// Memory (a running maximum through state.memory), smoothing, a timer and an action
// layer with clip durations: every kind of state a brain keeps between steps.
const char* kBrain = R"(
brains:
  - name: fidget
    nodes:
      - {id: 1, type: input, params: {sensor: neighbour_density}}
      - {id: 2, type: state.smooth, params: {tau: 1.5}}
      - {id: 3, type: math.max}
      - {id: 4, type: state.memory, params: {initial: 0}}
      - {id: 5, type: fuzz.trapezoid, params: {points: [-1, -1, 0.15, 0.6]}}
      - {id: 6, type: output, params: {channel: speed, scale: 1.4}}
      - {id: 7, type: state.timer}
      - {id: 8, type: fuzz.triangle, params: {points: [0, 2, 4]}}
      - {id: 9, type: output.action, params: {actions: "walk idle", durations: [1.5, 0.5]}}
      - {id: 10, type: output, params: {channel: tag, tag: calm}}
    links:
      - {from: [1, 0], to: [2, 0]}
      - {from: [2, 0], to: [3, 0]}
      - {from: [4, 0], to: [3, 1]}
      - {from: [3, 0], to: [4, 0]}
      - {from: [4, 0], to: [5, 0]}
      - {from: [5, 0], to: [6, 0]}
      - {from: [5, 0], to: [7, 0]}
      - {from: [5, 0], to: [9, 0]}
      - {from: [7, 0], to: [8, 0]}
      - {from: [8, 0], to: [9, 1]}
      - {from: [5, 0], to: [10, 0]}
)";

std::string readResource(const char* name)
{
    QFile f(QStringLiteral(THRONG_SOURCE_DIR "/resources/scenes/") + QString::fromLatin1(name));
    if (!f.open(QIODevice::ReadOnly))
        throw std::runtime_error(std::string("cannot read ") + name);
    return f.readAll().toStdString();
}

sim::Scene parseOrThrow(const std::string& text)
{
    sim::LoadResult r = sim::parseScene(text, "state-test.yaml", THRONG_SOURCE_DIR "/resources/scenes");
    if (!r.ok())
        throw std::runtime_error(r.diagnostics.front().format());
    return r.scene;
}

}  // namespace

sim::Scene crossroads()
{
    return parseOrThrow(readResource("crossroads.yaml"));
}

sim::Scene crossroadsWithBrains()
{
    // The shipped crossroads with the pedestrians running `fidget`, listed first among
    // the scene's brains.
    std::string text = readResource("crossroads.yaml");
    const std::string brains = "\nbrains:\n", pedestrian = "  - name: pedestrian\n    kind: pedestrian\n";
    const std::size_t list = text.find(brains), type = text.find(pedestrian);
    if (list == std::string::npos || type == std::string::npos)
        throw std::runtime_error("crossroads.yaml has no brains list or no pedestrian type");
    const std::string fidget = std::string(kBrain).substr(std::string(kBrain).find("  - name: fidget"));
    text.insert(list + brains.size(), fidget);
    sim::Scene scene = parseOrThrow(text);
    for (sim::AgentType& t : scene.agentTypes)
        if (t.name == "pedestrian")
            t.brain = "fidget";  // in place of the shipped `pedestrian` brain
    return scene;
}

sim::Scene smallEvacuation()
{
    sim::Scene scene = parseOrThrow(readResource("evacuation.yaml"));
    for (sim::SpawnGroup& g : scene.groups)
        g.count = 150;
    // A crowd at the east door, so that agents leave (the out state) within the test's steps.
    sim::SpawnGroup door = scene.groups.front();
    door.name = "at_the_door";
    door.min = {64.0f, -4.0f};
    door.max = {69.0f, 4.0f};
    door.count = 60;
    scene.groups.push_back(door);
    return scene;
}

sim::FrameCache record(sim::World& world, std::size_t steps)
{
    sim::FrameCache cache;
    world.startRecording(cache);
    std::vector<sim::AgentFrame> frame;
    for (std::size_t s = 0; s < steps; ++s) {
        world.step();
        world.snapshot(frame);
        cache.append(frame);
    }
    return cache;
}

float largestMove(const sim::FrameCache& a, std::size_t fa, const sim::FrameCache& b, std::size_t fb)
{
    float most = 0.0f;
    for (std::size_t i = 0; i < std::min(a.agentCount(), b.agentCount()); ++i)
        most = std::max(most, glm::distance(a.at(fa, i).position, b.at(fb, i).position));
    return most;
}

}  // namespace throng::test::state
