// Moving around the viewport as a user does: the wheel zooms around the cursor, a middle
// or right drag pulls the ground along with the mouse, F brings the whole scene back,
// and the 3D view orbits with a right drag.
#include "EditorTestSupport.h"
#include "ShowInitialState.h"
#include "TestRegistry.h"

#include "simcore/io/SceneIO.h"

#include <QApplication>
#include <QTest>
#include <QWheelEvent>

#include <cmath>

using namespace throng;
using namespace throng::editor;
using namespace throng::editor::test;

namespace {

const QSize kSize{400, 300};
const glm::vec3 kCorner{3.0f, 0.0f, 2.0f};

double distance(QPointF a, QPointF b)
{
    return std::hypot(a.x() - b.x(), a.y() - b.y());
}

void wheel(QWidget& widget, QPointF pos, int angleDelta)
{
    QWheelEvent event(pos, widget.mapToGlobal(pos), QPoint(), QPoint(0, angleDelta), Qt::NoButton, Qt::NoModifier,
                      Qt::NoScrollPhase, false);
    QApplication::sendEvent(&widget, &event);
}

void drag(QWidget& widget, Qt::MouseButton button, QPoint from, QPoint to)
{
    QTest::mousePress(&widget, button, Qt::NoModifier, from);
    QTest::mouseMove(&widget, (from + to) / 2);
    QTest::mouseMove(&widget, to);
    QTest::mouseRelease(&widget, button, Qt::NoModifier, to);
}

}  // namespace

class TestViewportNavigation : public QObject {
    Q_OBJECT

private:
    QTemporaryDir m_dir;
    sim::Scene m_scene;

private slots:
    void initTestCase()
    {
        // A set from (-4, -3) to (4, 3) with one agent at its centre.
        const QString path = writeScene(m_dir, "box.yaml",
                                        "throng: 1\n"
                                        "agent_types: [{name: walker, radius: 0.4}]\n"
                                        "agents: [{type: walker, position: [0, 0]}]\n"
                                        "walls:\n"
                                        "  - {points: [[-4, -3], [4, -3], [4, 3], [-4, 3], [-4, -3]]}\n");
        const sim::LoadResult loaded = sim::loadScene(path.toStdString());
        QVERIFY(loaded.ok());
        m_scene = loaded.scene;
    }

    void wheelZoomsAroundTheCursor()
    {
        Viewport viewport;
        showInitialState(viewport, m_scene);
        renderOffscreen(viewport, kSize);
        const QPointF cursor = viewport.worldToPixel(kCorner);
        const double spanBefore = distance(viewport.worldToPixel({0, 0, 0}), cursor);
        wheel(viewport, cursor, 120);
        QVERIFY(distance(viewport.worldToPixel(kCorner), cursor) < 0.5);
        QVERIFY(distance(viewport.worldToPixel({0, 0, 0}), cursor) > 1.1 * spanBefore);
        wheel(viewport, cursor, -240);
        QVERIFY(distance(viewport.worldToPixel(kCorner), cursor) < 0.5);
        QVERIFY(distance(viewport.worldToPixel({0, 0, 0}), cursor) < spanBefore);
    }

    void dragPullsTheGroundAlong_data()
    {
        QTest::addColumn<int>("button");
        QTest::newRow("middle") << int(Qt::MiddleButton);
        QTest::newRow("right") << int(Qt::RightButton);
    }

    void dragPullsTheGroundAlong()
    {
        QFETCH(int, button);
        Viewport viewport;
        showInitialState(viewport, m_scene);
        renderOffscreen(viewport, kSize);
        const QPointF before = viewport.worldToPixel(kCorner);
        drag(viewport, Qt::MouseButton(button), {200, 150}, {260, 130});
        const QPointF after = viewport.worldToPixel(kCorner);
        QVERIFY2(distance(after, before + QPointF(60, -20)) < 0.5,
                 qPrintable(QString("moved from (%1, %2) to (%3, %4)")
                                .arg(before.x()).arg(before.y()).arg(after.x()).arg(after.y())));
    }

    void keyFBringsTheWholeSceneBack()
    {
        Viewport viewport;
        showInitialState(viewport, m_scene);
        const QImage framed = renderOffscreen(viewport, kSize);
        const QPointF home = viewport.worldToPixel({0, 0, 0});
        drag(viewport, Qt::MiddleButton, {200, 150}, {20, 20});
        wheel(viewport, {30, 30}, -600);
        QVERIFY(distance(viewport.worldToPixel({0, 0, 0}), home) > 50.0);
        QTest::keyClick(&viewport, Qt::Key_F);
        QVERIFY(distance(viewport.worldToPixel({0, 0, 0}), home) < 0.5);
        QCOMPARE(viewport.grabFramebuffer(), framed);
    }

    void rightDragOrbitsTheThreeDView()
    {
        Viewport viewport;
        showInitialState(viewport, m_scene);
        viewport.setViewMode(ViewMode::Orbit);
        renderOffscreen(viewport, kSize);
        // Orbiting turns around the scene's centre: the centre stays put, a corner moves.
        const QPointF centre = viewport.worldToPixel({0, 0, 0});
        const QPointF corner = viewport.worldToPixel(kCorner);
        drag(viewport, Qt::RightButton, {200, 150}, {280, 150});
        QVERIFY(distance(viewport.worldToPixel({0, 0, 0}), centre) < 0.5);
        QVERIFY(distance(viewport.worldToPixel(kCorner), corner) > 20.0);
    }
};

THRONG_REGISTER_TEST(TestViewportNavigation)
#include "TestViewportNavigation.moc"
