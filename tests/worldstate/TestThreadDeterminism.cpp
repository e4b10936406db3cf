// Same scene and seed, the same frames bit for bit on 1 and on 2 threads, and after a
// checkpoint restored into a World with another thread count: for walkers on paths with
// brains, traffic driven by the shipped car brain, heroes, A* and flow-field walkers
// leaving through exits, agents that hear each other, and a flock. Each scene is large
// enough that the second thread does work, and the test asserts that it did: the
// determinism tests these replace ran scenes smaller than one parallel chunk, so their
// second thread never stepped an agent and agreeing proved nothing.
#include "StateScenes.h"
#include "TestRegistry.h"

#include "simcore/io/SceneIO.h"
#include "simcore/world/World.h"
#include "simcore/world/WorldState.h"

#include <QFile>
#include <QTest>

#include <functional>
#include <string>

using namespace throng;
using namespace throng::sim;
using namespace throng::test::state;

namespace {

Scene parse(const std::string& text)
{
    LoadResult r = parseScene(text, "determinism.yaml", THRONG_SOURCE_DIR "/resources/scenes");
    if (!r.ok())
        qFatal("%s", r.diagnostics.front().format().c_str());
    return r.scene;
}

// The crossroads with ten times the walkers (on the shipped pedestrian brain), and 26
// more lanes of cars (on the shipped car brain) north of the city under a light of their
// own, so that the vehicles too are stepped on both threads.
Scene busyCrossroads()
{
    Scene scene = crossroads();
    for (SpawnGroup& g : scene.groups)
        g.count *= 10;
    scene.settings.boundsMax.y = 260.0f;
    TrafficLight light;
    light.name = "north_grid";
    light.greenS = 2.0f;
    light.yellowS = 1.0f;
    light.redS = 2.0f;
    std::uint32_t id = 900000;
    for (int k = 0; k < 26; ++k) {
        Lane lane;
        lane.name = "grid_" + std::to_string(k);
        const float z = 60.0f + 7.5f * float(k);
        lane.points = k % 2 ? std::vector<glm::vec2>{{50.0f, z}, {-50.0f, z}} : std::vector<glm::vec2>{{-50.0f, z}, {50.0f, z}};
        scene.lanes.push_back(lane);
        light.stopLines.push_back({lane.name, 50.0f, {}});
        for (int c = 0; c < 12; ++c)
            scene.vehicles.push_back({id++, "car", lane.name, 8.0f * float(c), 5.0f});
    }
    scene.trafficLights.push_back(light);
    return scene;
}

// 2,400 walkers find their way round boxes and posts to four goals by A*.
const char* kPlanned = R"(throng: 1
settings: {fps: 24, seed: 5, bounds: {min: [-60, -60], max: [60, 60]}, nav_cell: 0.5}
agent_types:
  - {name: walker, radius: 0.3, max_speed: 1.4, navigation: astar, behaviours: {arrival: 1, separation: 1.5}}
walls:
  - {points: [[-40, -40], [40, -40], [40, 40], [-40, 40], [-40, -40]]}
obstacles:
  - {shape: box, center: [0, 0], size: [16, 4], angle: 30}
  - {shape: box, center: [-18, 14], size: [4, 14]}
  - {shape: box, center: [18, -14], size: [4, 14]}
  - {shape: circle, center: [-14, -16], radius: 3}
  - {shape: circle, center: [14, 16], radius: 3}
goals:
  - {name: a, position: [34, 34], radius: 3}
  - {name: b, position: [-34, -34], radius: 3}
  - {name: c, position: [34, -34], radius: 3}
  - {name: d, position: [-34, 34], radius: 3}
groups:
  - {name: sw, type: walker, count: 600, rect: {min: [-36, -8], max: [-24, 8]}, goal: a}
  - {name: ne, type: walker, count: 600, rect: {min: [24, -8], max: [36, 8]}, goal: b}
  - {name: n, type: walker, count: 600, rect: {min: [-8, 24], max: [8, 36]}, goal: c}
  - {name: s, type: walker, count: 600, rect: {min: [-8, -36], max: [8, -24]}, goal: d}
)";

// 3,000 evacuees leave a hall through two doors along flow fields; those nearest the
// doors are out within the test's steps.
const char* kEvacuation = R"(throng: 1
settings: {fps: 24, seed: 9, bounds: {min: [-40, -30], max: [40, 30]}, nav_cell: 0.5}
agent_types:
  - {name: evacuee, radius: 0.25, max_speed: 1.3, navigation: flow_field, behaviours: {arrival: 1, separation: 1.5}}
walls:
  - {points: [[-30, -1.5], [-30, -20], [30, -20], [30, -1.5]]}
  - {points: [[30, 1.5], [30, 20], [-30, 20], [-30, 1.5]]}
goals:
  - {name: east, position: [31, 0], radius: 1.5, exit: true}
  - {name: west, position: [-31, 0], radius: 1.5, exit: true}
groups:
  - {name: east_half, type: evacuee, count: 1500, rect: {min: [2, -18], max: [28, 18]}, goal: east}
  - {name: west_half, type: evacuee, count: 1500, rect: {min: [-28, -18], max: [-2, 18]}, goal: west}
)";

// 3,000 talkers that hear each other on a sound channel and gather (a brain with
// per-source sensors).
const char* kChatter = R"(throng: 1
settings: {fps: 24, seed: 21, bounds: {min: [-60, -60], max: [60, 60]}}
agent_types:
  - name: talker
    max_speed: 1.3
    emits: {channel: chat, strength: 0.9, radius: 6}
    behaviours: {wander: 1, separation: 1, containment: 2}
    brain: gather
groups:
  - {name: crowd, type: talker, count: 3000, rect: {min: [-50, -50], max: [50, 50]}}
brains:
  - name: gather
    nodes:
      - {id: 1, type: input, params: {sensor: sound_source_bearing, channel: chat}}
      - {id: 2, type: filter, params: {mode: nearest}}
      - {id: 3, type: output, params: {channel: turn, scale: 1}}
      - {id: 4, type: input, params: {sensor: sound_source_strength, channel: chat}}
      - {id: 5, type: filter, params: {mode: count, threshold: 0.5}}
      - {id: 6, type: math.remap, params: {from: [0, 4], to: [1.3, 0.2]}}
      - {id: 7, type: output, params: {channel: speed}}
    links:
      - {from: [1, 0], to: [2, 0]}
      - {from: [2, 0], to: [3, 0]}
      - {from: [4, 0], to: [5, 0]}
      - {from: [5, 0], to: [6, 0]}
      - {from: [6, 0], to: [7, 0]}
)";

Scene smallMurmuration()
{
    Scene scene = parse([] {
        QFile f(QStringLiteral(THRONG_SOURCE_DIR "/resources/scenes/murmuration.yaml"));
        if (!f.open(QIODevice::ReadOnly))
            qFatal("cannot read murmuration.yaml");
        return f.readAll().toStdString();
    }());
    for (SpawnGroup& g : scene.groups)
        g.count = 8000;
    return scene;
}

// The scene of a data row (sameFramesForAnyThreadCount_data).
Scene makeScene(int row)
{
    const std::function<Scene()> make[] = {busyCrossroads, [] { return parse(kPlanned); },
                                           [] { return parse(kEvacuation); }, [] { return parse(kChatter); },
                                           smallMurmuration};
    return make[row]();
}

struct Run {
    std::uint64_t hash = 0;
    std::vector<std::uint64_t> chunksPerThread;  // of the World that ran the last steps
    std::size_t agents = 0, out = 0;
};

// `steps` frames on `threads`; with a checkpoint, the first half on `threads` and the
// second half restored into a World with `resumeThreads`.
Run run(const Scene& scene, int threads, std::size_t steps, int resumeThreads = 0)
{
    World world(scene, {0, false, threads});
    Run r;
    if (resumeThreads == 0) {
        r.hash = record(world, steps).hash();
        r.chunksPerThread = world.team().chunksRun();
    } else {
        const FrameCache first = record(world, steps / 2);
        World resumed(scene, {0, false, resumeThreads});
        resumed.restoreState(world.saveState());
        const FrameCache second = record(resumed, steps - steps / 2);
        r.hash = first.hash() ^ (second.hash() * 0x9e3779b97f4a7c15ull);
        r.chunksPerThread = resumed.team().chunksRun();
        for (std::size_t i = 0; i < resumed.agentCount(); ++i)
            r.out += resumed.isOut(i) ? 1 : 0;
    }
    r.agents = world.agentCount();
    for (std::size_t i = 0; r.out == 0 && i < world.agentCount(); ++i)
        r.out += world.isOut(i) ? 1 : 0;
    return r;
}

}  // namespace

class TestThreadDeterminism : public QObject {
    Q_OBJECT
private slots:
    void sameFramesForAnyThreadCount_data()
    {
        QTest::addColumn<int>("scene");
        QTest::addColumn<int>("steps");
        QTest::newRow("crossroads: path walkers with brains, cars with brains, a hero") << 0 << 72;
        QTest::newRow("A* walkers round boxes and posts") << 1 << 72;
        QTest::newRow("flow-field evacuation through exits") << 2 << 96;
        QTest::newRow("walkers that hear each other") << 3 << 72;
        QTest::newRow("a flock of 8,000") << 4 << 48;
    }

    void sameFramesForAnyThreadCount()
    {
        QFETCH(int, scene);
        QFETCH(int, steps);
        const Scene s = makeScene(scene);
        const auto n = std::size_t(steps);
        const Run one = run(s, 1, n), two = run(s, 2, n);
        QVERIFY2(one.agents >= 2400, qPrintable(QString("%1 agents").arg(one.agents)));
        // Both threads stepped agents in the two-thread run.
        QCOMPARE(two.chunksPerThread.size(), std::size_t(2));
        QVERIFY2(two.chunksPerThread[0] > 0 && two.chunksPerThread[1] > 0,
                 qPrintable(QString("chunks per thread: %1, %2").arg(two.chunksPerThread[0]).arg(two.chunksPerThread[1])));
        QCOMPARE(two.hash, one.hash);
    }

    void sameFramesAfterACheckpointOnAnotherThreadCount_data() { sameFramesForAnyThreadCount_data(); }

    // Half the frames on one thread count, the rest from its checkpoint on the other: the
    // same frames both ways round.
    void sameFramesAfterACheckpointOnAnotherThreadCount()
    {
        QFETCH(int, scene);
        QFETCH(int, steps);
        const Scene s = makeScene(scene);
        const auto n = std::size_t(steps);
        const Run oneThenTwo = run(s, 1, n, 2), twoThenOne = run(s, 2, n, 1);
        QCOMPARE(oneThenTwo.chunksPerThread.size(), std::size_t(2));
        QVERIFY2(oneThenTwo.chunksPerThread[1] > 0, "the resumed two-thread World's second thread did nothing");
        QCOMPARE(twoThenOne.hash, oneThenTwo.hash);
        if (scene == 2)
            QVERIFY2(oneThenTwo.out > 0, "nobody left through an exit within the test's steps");
    }
};

THRONG_REGISTER_TEST(TestThreadDeterminism)
#include "TestThreadDeterminism.moc"
