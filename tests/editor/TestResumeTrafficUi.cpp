// A lane drawn with the real lane tool at frame 40 of the crossroads resumes the run from
// frame 40 (issue 6), not from frame 0: the first batch after the edit says resumedAt 40,
// frames 0..40 stay as recorded (the lane carries no vehicle), and undo gives the
// original recording back bit for bit. A hero drawn at frame 40 walks its keyframed way
// from there. Driven as a user does, with real mouse and key events.
#include "EditorTestSupport.h"
#include "EditorUiDriver.h"
#include "TestRegistry.h"

#include "editor/panels/TimelinePanel.h"
#include "editor/simulation/SimulationController.h"
#include "editor/viewport/Viewport.h"
#include "simcore/hero/HeroTrack.h"

#include <glm/geometric.hpp>

#include <QTest>

#include <algorithm>

using namespace throng;
using namespace throng::editor;
using namespace throng::editor::test;

namespace {

constexpr std::size_t kEditFrame = 40, kLastFrame = 60;

}  // namespace

class TestResumeTrafficUi : public QObject {
    Q_OBJECT

private:
    QTemporaryDir m_dir;

private slots:
    void aLaneDrawnAtFrameFortyResumesThereAndUndoGivesTheRecordingBack()
    {
        MainWindow window;
        QVERIFY(showWithScene(window, m_dir, "crossroads.yaml"));
        SimulationController& sim = window.simulation();
        QVERIFY(playUntilRecorded(window, kLastFrame));
        const std::uint64_t original = hashOfFirst(sim.cache(), kLastFrame + 1);
        const std::uint64_t kept = sim.cache().hashFrames(0, kEditFrame + 1);
        const std::size_t restarts = sim.restarts();
        QCOMPARE(sim.lastResumedAt(), std::size_t(0));
        QVERIFY(scrubWithKeys(window, kEditFrame));

        // A lane in the north-west block, clicked point by point, ended with Return.
        QVERIFY(clickToolButton(window, "lane"));
        for (glm::vec2 p : {glm::vec2(-40, -30), glm::vec2(-20, -30), glm::vec2(-20, -20)})
            clickOnGround(window, p);
        QTest::keyClick(&window.viewport(), Qt::Key_Return);
        QCOMPARE(window.document().scene().lanes.size(), std::size_t(5));
        QTRY_COMPARE(sim.lastResumedAt(), kEditFrame);
        QCOMPARE(sim.restarts(), restarts);
        QCOMPARE(sim.currentFrame(), kEditFrame);
        QCOMPARE(sim.cache().hashFrames(0, kEditFrame + 1), kept);
        QVERIFY(playUntilRecorded(window, kLastFrame));
        QCOMPARE(sim.restarts(), restarts);
        QCOMPARE(sim.cache().hashFrames(0, kEditFrame + 1), kept);

        // Undo at frame 40: the original recording, bit for bit.
        QVERIFY(scrubWithKeys(window, kEditFrame));
        QTest::keyClick(&window.viewport(), Qt::Key_Z, Qt::ControlModifier);
        QCOMPARE(window.document().scene().lanes.size(), std::size_t(4));
        QTRY_COMPARE(sim.recordedFrames(), kEditFrame + 1);
        QVERIFY(playUntilRecorded(window, kLastFrame));
        QCOMPARE(sim.restarts(), restarts);
        QCOMPARE(sim.lastResumedAt(), kEditFrame);
        QCOMPARE(hashOfFirst(sim.cache(), kLastFrame + 1), original);
    }

    void aHeroDrawnMidRunWalksItsWayFromThere()
    {
        // A hero goes where its keyframes say at every frame, also one drawn at frame 40
        // of a recorded run (the run resumes there with it).
        MainWindow window;
        QVERIFY(showWithScene(window, m_dir, "crossroads.yaml"));
        SimulationController& sim = window.simulation();
        QVERIFY(playUntilRecorded(window, kLastFrame));
        QVERIFY(scrubWithKeys(window, kEditFrame));
        QVERIFY(clickToolButton(window, "hero"));
        for (glm::vec2 p : {glm::vec2(-40, -30), glm::vec2(-30, -30), glm::vec2(-30, -20)})
            clickOnGround(window, p);
        QTest::keyClick(&window.viewport(), Qt::Key_Return);
        const sim::Scene& scene = window.document().scene();
        QCOMPARE(scene.heroes.size(), std::size_t(2));
        const sim::Hero hero = scene.heroes.back();
        QTRY_COMPARE(sim.recordedFrames(), kEditFrame + 1);
        QVERIFY(playUntilRecorded(window, kLastFrame));
        // One agent of the recording is the hero, and no other has its id.
        const sim::FrameCache& cache = sim.cache();
        std::vector<std::size_t> withId;
        for (std::size_t a = 0; a < cache.agentCount(); ++a)
            if (cache.agents()[a].id == hero.id)
                withId.push_back(a);
        QVERIFY2(withId.size() == 1,
                 qPrintable(QString("%1 agents have the hero's id %2").arg(withId.size()).arg(hero.id)));
        const sim::HeroTrack track(hero);
        float worst = 0.0f;
        for (std::size_t f = kEditFrame + 1; f <= kLastFrame; ++f) {
            const sim::AgentFrame& at = cache.at(f, withId.front());
            QVERIFY(at.present);
            const glm::vec3 want = track.positionAt(double(f) / double(cache.fps()));
            worst = std::max(worst, glm::distance(glm::vec2(at.position.x, at.position.z), glm::vec2(want.x, want.z)));
        }
        QVERIFY2(worst < 0.01f, qPrintable(QString("the hero strays %1 m from its way").arg(worst)));
    }
};

THRONG_REGISTER_TEST(TestResumeTrafficUi)
#include "TestResumeTrafficUi.moc"
