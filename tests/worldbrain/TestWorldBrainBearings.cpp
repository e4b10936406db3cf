// The bearing sensors in a World: an observer facing +x with 1 to 8 neighbours around it
// reports each neighbour's bearing (+ = to its left), nearest first, as double-precision
// atan2 has it, in every lane of the four-at-a-time computation (WorldBrainSense.cpp) and
// with some lanes left over; nearest_bearing is the first of them, and the goal's and the
// neighbours' headings come out alike.
#include "TestRegistry.h"

#include "simcore/brain/BrainEvaluator.h"
#include "simcore/io/SceneIO.h"
#include "simcore/world/World.h"
#include "simcore/world/WorldBrain.h"

#include <QTest>

#include <cmath>
#include <string>
#include <vector>

using namespace throng::sim;

namespace {

struct Around {
    double distanceM, bearingDeg, headingDeg;  // + = left of the observer, which faces +x
};

// Neighbours at rising distances, all round (the type sees 360 degrees), facing every way.
const Around kAround[] = {{1.5, 12.0, 90.0},  {1.8, -37.5, -45.0}, {2.1, 101.0, 170.0}, {2.4, -158.0, 5.0},
                          {2.7, 64.0, -120.0}, {3.0, -3.0, 33.0},  {3.3, 177.5, -179.0}, {3.6, -91.0, 61.0}};

// The scene's heading is degrees from +x toward -z (the observer's left), as bearings are.
std::string sceneWith(int neighbours)
{
    std::string s = R"(throng: 1
settings: {fps: 24, seed: 3, bounds: {min: [-20, -20], max: [20, 20]}}
agent_types:
  - {name: observer, max_speed: 1, perception: 6, view_angle: 360, brain: eyes}
  - {name: other, max_speed: 1}
goals: [{name: there, position: [-4, -7], radius: 0.1}]
agents:
  - {id: 1, type: observer, position: [0, 0, 0], heading: 0, goal: there}
)";
    for (int k = 0; k < neighbours; ++k) {
        const Around& a = kAround[k];
        const double rad = a.bearingDeg * 3.14159265358979 / 180.0;
        s += "  - {id: " + std::to_string(k + 2) + ", type: other, position: [" +
             std::to_string(a.distanceM * std::cos(rad)) + ", 0, " + std::to_string(-a.distanceM * std::sin(rad)) +
             "], heading: " + std::to_string(a.headingDeg) + "}\n";
    }
    s += R"(brains:
  - name: eyes
    nodes:
      - {id: 1, type: input, params: {sensor: neighbour_bearing}}
      - {id: 2, type: filter, params: {mode: nearest}}
      - {id: 3, type: probe, params: {name: first}}
      - {id: 4, type: input, params: {sensor: nearest_bearing}}
      - {id: 5, type: probe, params: {name: nearest}}
      - {id: 6, type: input, params: {sensor: goal_bearing}}
      - {id: 7, type: probe, params: {name: goal}}
      - {id: 8, type: input, params: {sensor: neighbour_heading}}
      - {id: 9, type: filter, params: {mode: nearest}}
      - {id: 10, type: probe, params: {name: heading}}
    links:
      - {from: [1, 0], to: [2, 0]}
      - {from: [2, 0], to: [3, 0]}
      - {from: [4, 0], to: [5, 0]}
      - {from: [6, 0], to: [7, 0]}
      - {from: [8, 0], to: [9, 0]}
      - {from: [9, 0], to: [10, 0]}
)";
    return s;
}

std::vector<float> picked(const World& world, NodeId node)
{
    for (const BrainNodeValue& v : world.brainEvaluator(0)->pickedValues())
        if (v.node == node && v.port == 0)
            return v.values;
    return {};
}

float probe(const World& world, const std::string& name)
{
    for (const auto& [n, value] : world.brainEvaluator(0)->pickedProbes())
        if (n == name)
            return value;
    return NAN;
}

// The observer's bearing of `offset` (x, z), degrees, in double precision.
double bearingOf(double x, double z)
{
    return std::atan2(-z, x) * 180.0 / 3.14159265358979323846;
}

}  // namespace

class TestWorldBrainBearings : public QObject {
    Q_OBJECT
private slots:
    void eachNeighboursBearingNearestFirst_data()
    {
        QTest::addColumn<int>("neighbours");
        for (const int n : {1, 3, 4, 5, 8})  // a lane of four part full, full, and two full
            QTest::newRow(qPrintable(QString("%1 neighbours").arg(n))) << n;
    }
    void eachNeighboursBearingNearestFirst()
    {
        QFETCH(int, neighbours);
        const LoadResult r = parseScene(sceneWith(neighbours), "scene.yaml", "");
        QVERIFY2(r.ok(), r.ok() ? "" : r.diagnostics[0].format().c_str());
        QVERIFY(checkSceneBrains(r.scene).empty());
        World world(r.scene, {0, false, 1});
        QVERIFY(world.brainErrors().empty());
        world.pickBrainAgent(0);
        world.step();  // the sense reads the state the step starts from: the file's

        const std::vector<float> bearings = picked(world, 1), headings = picked(world, 8);
        QCOMPARE(int(bearings.size()), neighbours);
        QCOMPARE(int(headings.size()), neighbours);
        for (int k = 0; k < neighbours; ++k) {
            const Scene& s = r.scene;
            const glm::vec3 q = s.agents[std::size_t(k + 1)].position;
            const double want = bearingOf(q.x, q.z);
            QVERIFY2(std::fabs(double(bearings[std::size_t(k)]) - want) < 1e-4,
                     qPrintable(QString("neighbour %1: %2, not %3").arg(k).arg(bearings[std::size_t(k)]).arg(want)));
            QVERIFY(std::fabs(want - kAround[k].bearingDeg) < 1e-3);  // the placing itself
            // Its heading from the observer's: the file's heading, as the observer faces 0.
            QVERIFY2(std::fabs(double(headings[std::size_t(k)]) - kAround[k].headingDeg) < 1e-3,
                     qPrintable(QString("neighbour %1 faces %2, not %3")
                                    .arg(k)
                                    .arg(headings[std::size_t(k)])
                                    .arg(kAround[k].headingDeg)));
        }
        QCOMPARE(probe(world, "nearest"), bearings[0]);
        QCOMPARE(probe(world, "first"), bearings[0]);
        QVERIFY(std::fabs(double(probe(world, "goal")) - bearingOf(-4.0, -7.0)) < 1.0);  // its own spot in the goal's disk
    }
};

THRONG_REGISTER_TEST(TestWorldBrainBearings)
#include "TestWorldBrainBearings.moc"
