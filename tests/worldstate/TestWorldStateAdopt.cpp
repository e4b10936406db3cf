// Resuming an edited scene from a checkpoint (issue 6): frames before the edit frame are
// the old run's; from there the edited scene runs from the state at that frame. A new
// wall holds and changes the walkers near it while far ones go on as before; a lower
// max speed holds from the edit on. (Edits of the agent set, light timing and the edits
// that are refused: TestWorldStateAgentSet.)
#include "StateScenes.h"
#include "TestRegistry.h"

#include "simcore/world/WorldState.h"

#include <glm/geometric.hpp>

#include <QTest>

#include <algorithm>
#include <cmath>

using namespace throng::sim;
using namespace throng::test::state;

namespace {

float cross2(glm::vec2 a, glm::vec2 b) { return a.x * b.y - a.y * b.x; }

bool crosses(glm::vec2 p0, glm::vec2 p1, glm::vec2 a, glm::vec2 b)
{
    const float d1 = cross2(b - a, p0 - a), d2 = cross2(b - a, p1 - a);
    const float d3 = cross2(p1 - p0, a - p0), d4 = cross2(p1 - p0, b - p0);
    return d1 * d2 < 0.0f && d3 * d4 < 0.0f;
}

float distanceToSegment(glm::vec2 p, glm::vec2 a, glm::vec2 b)
{
    const glm::vec2 ab = b - a;
    const float t = std::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.0f, 1.0f);
    return glm::distance(p, a + ab * t);
}

glm::vec2 xz(glm::vec3 v) { return {v.x, v.z}; }

constexpr std::size_t kEditStep = 100;

}  // namespace

class TestWorldStateAdopt : public QObject {
    Q_OBJECT

private slots:
    void unchangedSceneResumesBitIdentical()
    {
        const Scene scene = crossroadsWithBrains();
        World straight(scene);
        for (std::size_t s = 0; s < kEditStep; ++s)
            straight.step();
        const WorldState state = straight.saveState();
        const FrameCache reference = record(straight, 60);
        World resumed(scene);
        QVERIFY(resumed.adoptState(state, scene, scene));
        QCOMPARE(record(resumed, 60).hash(), reference.hash());
    }

    void newWallHoldsFromTheEditOn()
    {
        const Scene scene = crossroadsWithBrains();
        World straight(scene);
        for (std::size_t s = 0; s < kEditStep; ++s)
            straight.step();
        const WorldState state = straight.saveState();
        const FrameCache reference = record(straight, 72);

        // A wall across the north-west sidewalk, where the walkers of nw_round go north.
        Scene edited = scene;
        const glm::vec2 a(-9.0f, -20.0f), b(-5.0f, -20.0f);
        edited.walls.push_back({"", {a, b}});
        World resumed(edited);
        QVERIFY(resumed.adoptState(state, scene, edited));
        QCOMPARE(resumed.stepIndex(), std::uint64_t(kEditStep));
        const FrameCache after = record(resumed, 72);
        // The edit frame itself is the old run's state.
        QCOMPARE(largestMove(after, 0, reference, 0), 0.0f);

        std::size_t nearChanged = 0, far = 0, farSame = 0, veryFar = 0, veryFarSame = 0, crossings = 0;
        for (std::size_t i = 0; i < after.agentCount(); ++i) {
            const float d = distanceToSegment(xz(reference.at(0, i).position), a, b);
            if (d < 4.0f && glm::distance(after.at(72, i).position, reference.at(72, i).position) > 0.05f)
                ++nearChanged;
            // Walkers feel each other a perception radius (4 m) further each step: far
            // ones go on as before, early on. (A* walkers plan again on the edited grid.)
            if (d > 8.0f && after.agents()[i].typeIndex == 0) {
                ++far;
                farSame += after.at(1, i).position == reference.at(1, i).position ? 1 : 0;
            }
            if (d > 30.0f && after.agents()[i].typeIndex == 0) {
                ++veryFar;
                veryFarSame += glm::distance(after.at(4, i).position, reference.at(4, i).position) < 1e-3f ? 1 : 0;
            }
            for (std::size_t f = 1; f < after.frameCount(); ++f)
                crossings += crosses(xz(after.at(f - 1, i).position), xz(after.at(f, i).position), a, b) ? 1 : 0;
        }
        QVERIFY2(nearChanged > 0, "no walker near the new wall walked otherwise");
        QCOMPARE(crossings, std::size_t(0));
        QVERIFY(veryFar > 50);
        QVERIFY2(farSame == far, qPrintable(QString("%1 of %2 walkers 8 m away kept their way").arg(farSame).arg(far)));
        QVERIFY2(veryFarSame * 10 >= veryFar * 9,
                 qPrintable(QString("%1 of %2 walkers 30 m away kept their way").arg(veryFarSame).arg(veryFar)));
        // The reference run does walk through where the wall now stands.
        std::size_t oldCrossings = 0;
        for (std::size_t i = 0; i < reference.agentCount(); ++i)
            for (std::size_t f = 1; f < reference.frameCount(); ++f)
                oldCrossings += crosses(xz(reference.at(f - 1, i).position), xz(reference.at(f, i).position), a, b);
        QVERIFY(oldCrossings > 0);
    }

    void editBetweenCheckpointsStepsTheRecordedSceneToTheEditFrame()
    {
        // As the editor does: checkpoint at 24, edit at 40 -- steps 24..40 again with the
        // recorded scene, then the edited scene takes over frame 40's state.
        const Scene scene = crossroads();
        World straight(scene);
        for (int s = 0; s < 24; ++s)
            straight.step();
        const WorldState at24 = straight.saveState();
        const FrameCache reference = record(straight, 20);  // frames 24..44
        Scene edited = scene;
        const glm::vec2 a(-8.9f, -25.0f), b(-5.2f, -25.0f);
        edited.walls.push_back({"", {a, b}});
        World recorded(scene);
        recorded.restoreState(at24);
        for (int s = 24; s < 40; ++s)
            recorded.step();
        World resumed(edited);
        QVERIFY(resumed.adoptState(recorded.saveState(), scene, edited));
        const FrameCache after = record(resumed, 4);  // frames 40..44
        std::size_t far = 0, farSame = 0;
        for (std::size_t i = 0; i < after.agentCount(); ++i) {
            QCOMPARE(after.at(0, i).position, reference.at(16, i).position);
            if (distanceToSegment(xz(reference.at(16, i).position), a, b) > 8.0f && after.agents()[i].typeIndex == 0) {
                ++far;
                farSame += after.at(1, i).position == reference.at(17, i).position ? 1 : 0;
            }
        }
        QVERIFY2(farSame == far, qPrintable(QString("%1 of %2 walkers 8 m away kept their way").arg(farSame).arg(far)));
    }

    void lowerMaxSpeedHoldsFromTheEditOn()
    {
        const Scene scene = crossroadsWithBrains();
        World straight(scene);
        for (std::size_t s = 0; s < kEditStep; ++s)
            straight.step();
        const WorldState state = straight.saveState();
        const FrameCache reference = record(straight, 48);

        Scene edited = scene;
        edited.agentTypes[0].maxSpeed = 0.5f;  // pedestrian; speed factors reach 1.2
        World resumed(edited);
        QVERIFY(resumed.adoptState(state, scene, edited));
        const FrameCache after = record(resumed, 48);
        QCOMPARE(largestMove(after, 0, reference, 0), 0.0f);
        // Pedestrians above the new top speed (a hero's push may still hurry one along).
        std::size_t pedestrians = 0, fastBefore = 0, fastAfter = 0;
        for (std::size_t i = 0; i < after.agentCount(); ++i) {
            if (after.agents()[i].typeIndex != 0)
                continue;
            ++pedestrians;
            fastBefore += reference.at(48, i).speed > 0.5f * 1.2f + 1e-3f ? 1 : 0;
            fastAfter += after.at(48, i).speed > 0.5f * 1.2f + 1e-3f ? 1 : 0;
        }
        QVERIFY2(fastBefore * 3 > pedestrians, qPrintable(QString("%1 of %2").arg(fastBefore).arg(pedestrians)));
        QVERIFY2(fastAfter * 50 < pedestrians, qPrintable(QString("%1 of %2").arg(fastAfter).arg(pedestrians)));
        QVERIFY(largestMove(after, 48, reference, 48) > 0.5f);
    }
};

THRONG_REGISTER_TEST(TestWorldStateAdopt)
#include "TestWorldStateAdopt.moc"
