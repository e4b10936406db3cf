// A crowd-brush stroke at a paused frame shows its agents at once (issue 6): the edit
// frame is recorded again from the edited World, so frame 40 shows the new agents where
// they were painted while frames 0..39 stay as recorded; undo gives frame 40 back as it
// was, bit for bit. Driven as a user does, with real mouse and key events.
#include "EditorTestSupport.h"
#include "EditorUiDriver.h"
#include "TestRegistry.h"

#include "editor/panels/TimelinePanel.h"
#include "editor/simulation/SimulationController.h"
#include "editor/viewport/Viewport.h"

#include <glm/geometric.hpp>

#include <QTest>
#include <QToolButton>

#include <algorithm>

using namespace throng;
using namespace throng::editor;
using namespace throng::editor::test;

namespace {

constexpr std::size_t kEditFrame = 40, kLastFrame = 60;
constexpr float kBrushRadiusM = 3.0f;  // the crowd brush's default radius

float distanceToSegment(glm::vec2 p, glm::vec2 a, glm::vec2 b)
{
    const glm::vec2 ab = b - a;
    const float t = std::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.0f, 1.0f);
    return glm::distance(p, a + ab * t);
}

}  // namespace

class TestPaintedAgentsShowUi : public QObject {
    Q_OBJECT

private:
    QTemporaryDir m_dir;

private slots:
    void aStrokeWhilePausedShowsItsAgentsAtTheEditFrame()
    {
        MainWindow window;
        QVERIFY(showWithScene(window, m_dir, "crossroads.yaml"));
        SimulationController& sim = window.simulation();
        QVERIFY(clickButton(window, "playButton"));
        QTRY_VERIFY_WITH_TIMEOUT(sim.recordedFrames() > kLastFrame, 90000);
        QVERIFY(clickButton(window, "playButton"));
        QVERIFY(!sim.isPlaying());
        QVERIFY(scrubWithKeys(window, kEditFrame));
        const std::uint64_t before = sim.cache().hashFrames(0, kEditFrame);
        const std::uint64_t original = hashOfFirst(sim.cache(), kEditFrame + 1);
        std::vector<sim::AgentFrame> originalFrame(sim.cache().frame(kEditFrame).begin(), sim.cache().frame(kEditFrame).end());
        const std::size_t restarts = sim.restarts();
        QCOMPARE(window.viewport().agentCount(), kCrossroadsAgents);

        // Paint on the north-west block's sidewalk side, paused at frame 40.
        const glm::vec2 from(-38.0f, -25.0f), to(-26.0f, -25.0f);
        QVERIFY(clickToolButton(window, "crowdBrush"));
        dragOnGround(window, {from, to});
        const std::vector<sim::Agent> placed = window.document().scene().agents;
        QVERIFY(placed.size() >= 4);

        // Frame 40 itself shows them, without a step and without a restart.
        QTRY_COMPARE(window.viewport().agentCount(), kCrossroadsAgents + placed.size());
        QCOMPARE(sim.currentFrame(), kEditFrame);
        QCOMPARE(window.viewport().frameIndex(), kEditFrame);
        QCOMPARE(sim.lastResumedAt(), kEditFrame);
        QCOMPARE(sim.restarts(), restarts);
        QCOMPARE(sim.recordedFrames(), kEditFrame + 1);
        const sim::FrameCache& cache = sim.cache();
        QCOMPARE(cache.agentCount(), kCrossroadsAgents + placed.size());
        QCOMPARE(cache.hashFrames(0, kEditFrame), before);
        // Everyone who was there stands where they stood; the new ones where painted.
        for (std::size_t i = 0; i < kCrossroadsAgents; ++i)
            QCOMPARE(cache.at(kEditFrame, i).position, originalFrame[i].position);
        std::size_t inside = 0;
        for (std::size_t i = kCrossroadsAgents; i < cache.agentCount(); ++i) {
            QVERIFY(!cache.at(kEditFrame - 1, i).present);
            QVERIFY(cache.at(kEditFrame, i).present);
            const auto it = std::find_if(placed.begin(), placed.end(),
                                         [&](const sim::Agent& a) { return a.id == cache.agents()[i].id; });
            QVERIFY(it != placed.end());
            const glm::vec2 p(cache.at(kEditFrame, i).position.x, cache.at(kEditFrame, i).position.z);
            QCOMPARE(p, glm::vec2(it->position.x, it->position.z));
            inside += distanceToSegment(p, from, to) <= kBrushRadiusM + 0.25f ? 1 : 0;  // + picking round-off
        }
        QCOMPARE(inside, placed.size());

        // Undo: frame 40 is the original again, bit for bit, and shown so.
        QTest::keyClick(&window.viewport(), Qt::Key_Z, Qt::ControlModifier);
        QVERIFY(window.document().scene().agents.empty());
        QTRY_COMPARE(sim.cache().agentCount(), kCrossroadsAgents);
        QTRY_COMPARE(hashOfFirst(sim.cache(), kEditFrame + 1), original);
        QCOMPARE(sim.restarts(), restarts);
        QCOMPARE(sim.currentFrame(), kEditFrame);
        QTRY_COMPARE(window.viewport().agentCount(), kCrossroadsAgents);
    }
};

THRONG_REGISTER_TEST(TestPaintedAgentsShowUi)
#include "TestPaintedAgentsShowUi.moc"
