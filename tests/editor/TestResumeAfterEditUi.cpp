// Editing the scene invalidates frames from the edit on (issue 6), driven as a user
// does: play the crossroads, scrub back to frame 40, draw a wall across a sidewalk with
// the wall tool (or lower a type's max speed in the properties panel). Frames 0..40 stay
// as recorded; the frames after are recomputed with the edit from frame 40's state, and
// differ near the wall while far walkers go on as before; undo recomputes them again
// from frame 40, as they first were.
#include "EditorTestSupport.h"
#include "EditorUiDriver.h"
#include "TestRegistry.h"

#include "editor/panels/OutlinerPanel.h"
#include "editor/panels/TimelinePanel.h"
#include "editor/simulation/SimulationController.h"
#include "editor/viewport/Viewport.h"

#include <glm/geometric.hpp>

#include <QDoubleSpinBox>
#include <QSlider>
#include <QTest>
#include <QTreeWidgetItem>

#include <algorithm>
#include <vector>

using namespace throng;
using namespace throng::editor;
using namespace throng::editor::test;

namespace {

using Frames = std::vector<std::vector<sim::AgentFrame>>;

constexpr std::size_t kEditFrame = 40, kLastFrame = 60;

Frames framesUpTo(const sim::FrameCache& cache, std::size_t last)
{
    Frames out;
    for (std::size_t f = 0; f <= last && f < cache.frameCount(); ++f)
        out.emplace_back(cache.frame(f).begin(), cache.frame(f).end());
    return out;
}

// Frames first..last of the cache have the positions of the recording.
bool samePositions(const sim::FrameCache& cache, const Frames& recording, std::size_t first, std::size_t last)
{
    for (std::size_t f = first; f <= last; ++f)
        for (std::size_t i = 0; i < cache.agentCount(); ++i)
            if (cache.at(f, i).position != recording[f][i].position)
                return false;
    return true;
}

glm::vec2 xz(glm::vec3 v) { return {v.x, v.z}; }

float distanceToSegment(glm::vec2 p, glm::vec2 a, glm::vec2 b)
{
    const glm::vec2 ab = b - a;
    const float t = std::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.0f, 1.0f);
    return glm::distance(p, a + ab * t);
}

bool crosses(glm::vec2 p0, glm::vec2 p1, glm::vec2 a, glm::vec2 b)
{
    auto cross = [](glm::vec2 u, glm::vec2 v) { return u.x * v.y - u.y * v.x; };
    return cross(b - a, p0 - a) * cross(b - a, p1 - a) < 0.0f && cross(p1 - p0, a - p0) * cross(p1 - p0, b - p0) < 0.0f;
}

}  // namespace

class TestResumeAfterEditUi : public QObject {
    Q_OBJECT

private:
    QTemporaryDir m_dir;

private slots:
    void aWallRecomputesFramesFromTheEditOnAndUndoAgain()
    {
        MainWindow window;
        QVERIFY(showWithScene(window, m_dir, "crossroads.yaml"));
        SimulationController& sim = window.simulation();
        QVERIFY(playUntilRecorded(window, kLastFrame));
        const Frames before = framesUpTo(sim.cache(), kLastFrame);
        QVERIFY(scrubWithKeys(window, kEditFrame));

        // A wall across the north-west sidewalk, where the nw_round walkers go north.
        const glm::vec2 a(-8.9f, -25.0f), b(-5.2f, -25.0f);
        QVERIFY(clickToolButton(window, "wall"));
        clickOnGround(window, a);
        clickOnGround(window, b);
        QTest::keyClick(&window.viewport(), Qt::Key_Return);
        QCOMPARE(window.document().scene().walls.size(), std::size_t(5));
        const glm::vec2 wa = window.document().scene().walls.back().points.front();
        const glm::vec2 wb = window.document().scene().walls.back().points.back();

        // Frames up to the edit stay, the playhead too; the scrub bar shows what is kept.
        QTRY_COMPARE(sim.recordedFrames(), kEditFrame + 1);
        QCOMPARE(sim.currentFrame(), kEditFrame);
        QCOMPARE(window.timeline().scrubBar()->cachedFrames(), kEditFrame + 1);
        QVERIFY(samePositions(sim.cache(), before, 0, kEditFrame));

        QVERIFY(playUntilRecorded(window, kLastFrame));
        QVERIFY(samePositions(sim.cache(), before, 0, kEditFrame));
        std::size_t nearChanged = 0, far = 0, farSame = 0, veryFar = 0, veryFarSame = 0, crossings = 0;
        for (std::size_t i = 0; i < sim.cache().agentCount(); ++i) {
            const float d = distanceToSegment(xz(before[kEditFrame][i].position), wa, wb);
            const float moved = glm::distance(sim.cache().at(kLastFrame, i).position, before[kLastFrame][i].position);
            nearChanged += d < 4.0f && moved > 0.05f ? 1 : 0;
            // Walkers feel each other a perception radius (4 m) further each step: far
            // ones go on as before, early on. (A* walkers plan again on the edited grid.)
            if (d > 8.0f && sim.cache().agents()[i].typeIndex == 0) {
                ++far;
                farSame += sim.cache().at(kEditFrame + 1, i).position == before[kEditFrame + 1][i].position;
            }
            if (d > 30.0f && sim.cache().agents()[i].typeIndex == 0) {
                ++veryFar;
                veryFarSame += glm::distance(sim.cache().at(kEditFrame + 4, i).position,
                                             before[kEditFrame + 4][i].position) < 1e-3f;
            }
            for (std::size_t f = kEditFrame + 1; f <= kLastFrame; ++f)
                crossings += crosses(xz(sim.cache().at(f - 1, i).position), xz(sim.cache().at(f, i).position), wa, wb);
        }
        QVERIFY2(nearChanged > 0, "no walker near the new wall walked otherwise");
        QCOMPARE(crossings, std::size_t(0));
        QVERIFY(veryFar > 50);
        QVERIFY2(farSame == far, qPrintable(QString("%1 of %2 walkers 8 m away as before").arg(farSame).arg(far)));
        QVERIFY2(veryFarSame * 10 >= veryFar * 9,
                 qPrintable(QString("%1 of %2 walkers 30 m away as before").arg(veryFarSame).arg(veryFar)));

        // Undo at frame 40: recomputed from there again, and now as before the wall.
        QVERIFY(scrubWithKeys(window, kEditFrame));
        QTest::keyClick(&window.viewport(), Qt::Key_Z, Qt::ControlModifier);
        QCOMPARE(window.document().scene().walls.size(), std::size_t(4));
        QTRY_COMPARE(sim.recordedFrames(), kEditFrame + 1);
        QCOMPARE(sim.currentFrame(), kEditFrame);
        QVERIFY(playUntilRecorded(window, kLastFrame));
        QVERIFY(samePositions(sim.cache(), before, 0, kLastFrame));
    }

    void aLowerMaxSpeedHoldsFromTheEditOn()
    {
        MainWindow window;
        QVERIFY(showWithScene(window, m_dir, "crossroads.yaml"));
        SimulationController& sim = window.simulation();
        QVERIFY(playUntilRecorded(window, kLastFrame));
        const Frames before = framesUpTo(sim.cache(), kLastFrame);
        QVERIFY(scrubWithKeys(window, kEditFrame));

        // The pedestrian type, picked in the outliner, gets 0.5 m/s in the properties panel.
        QTreeWidgetItem* types = window.outliner().kindRow(ItemKind::AgentType);
        types->setExpanded(true);
        QTest::mouseClick(window.outliner().viewport(), Qt::LeftButton, Qt::NoModifier,
                          window.outliner().visualItemRect(types->child(0)).center());
        auto* maxSpeed = window.findChild<QWidget*>("properties")->findChild<QDoubleSpinBox*>("maxSpeed");
        QVERIFY(maxSpeed);
        QCOMPARE(maxSpeed->value(), 1.4);
        maxSpeed->selectAll();
        QTest::keyClicks(maxSpeed, "0.5");
        QTest::keyClick(maxSpeed, Qt::Key_Return);
        QCOMPARE(window.document().scene().agentTypes[0].maxSpeed, 0.5f);
        QTRY_COMPARE(sim.recordedFrames(), kEditFrame + 1);
        QCOMPARE(sim.currentFrame(), kEditFrame);

        QVERIFY(playUntilRecorded(window, kLastFrame));
        QVERIFY(samePositions(sim.cache(), before, 0, kEditFrame));
        // Pedestrians above the new top speed (speed factors reach 1.2) at the last frame.
        std::size_t pedestrians = 0, fastBefore = 0, fastAfter = 0;
        for (std::size_t i = 0; i < sim.cache().agentCount(); ++i) {
            if (sim.cache().agents()[i].typeIndex != 0)
                continue;
            ++pedestrians;
            fastBefore += before[kLastFrame][i].speed > 0.601f;
            fastAfter += sim.cache().at(kLastFrame, i).speed > 0.601f;
        }
        QVERIFY2(fastBefore * 3 > pedestrians, qPrintable(QString("%1 of %2").arg(fastBefore).arg(pedestrians)));
        QVERIFY2(fastAfter * 50 < pedestrians, qPrintable(QString("%1 of %2").arg(fastAfter).arg(pedestrians)));
    }
};

THRONG_REGISTER_TEST(TestResumeAfterEditUi)
#include "TestResumeAfterEditUi.moc"
