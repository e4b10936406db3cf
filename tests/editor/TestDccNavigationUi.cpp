// Moving round the viewport the way Maya and Houdini users do, with real mouse and key
// events: the wheel zooms towards the cursor (the ground under it stays under it, from
// above, in 3D and on a hill), Alt+left drag orbits the 3D view and never reaches the
// active tool, Alt+middle drag pans, Alt+right drag zooms towards where it began; F frames
// the selection where its agents stand now, A frames everything.
#include "EditorTestSupport.h"
#include "EditorUiDriver.h"
#include "ShowInitialState.h"
#include "TestRegistry.h"

#include "editor/simulation/SimulationController.h"
#include "editor/viewport/Viewport.h"
#include "simcore/io/SceneIO.h"

#include <QAction>
#include <QApplication>
#include <QTest>
#include <QWheelEvent>

#include <glm/geometric.hpp>

#include <cmath>

using namespace throng;
using namespace throng::editor;
using namespace throng::editor::test;

namespace {

const QSize kSize{480, 360};

// A walled 24 x 16 m yard with one walker at (-6, -3) heading for a goal in the east.
const QByteArray kYard = R"(throng: 1
settings: {fps: 24, duration: 20, seed: 1, bounds: {min: [-15, -10], max: [15, 10]}}
agent_types: [{name: walker, radius: 0.3, max_speed: 1.4, max_force: 3, variation: {speed: [1, 1]}}]
goals: [{name: east, position: [9, -3], radius: 1}]
agents: [{id: 1, type: walker, position: [-6, 0, -3], goal: east}]
walls:
  - {points: [[-12, -8], [12, -8], [12, 8], [-12, 8], [-12, -8]]}
)";

// The yard on a hill rising 0.25 m per metre eastwards.
const QByteArray kHill = kYard + "terrain: {origin: [-20, -20], cell: 20, cols: 3, rows: 3, "
                                 "heights: [0, 5, 10, 0, 5, 10, 0, 5, 10]}\n";

double distance(QPointF a, QPointF b)
{
    return std::hypot(a.x() - b.x(), a.y() - b.y());
}

QString text(QPointF p)
{
    return QString("(%1, %2)").arg(p.x()).arg(p.y());
}

void wheel(QWidget& widget, QPointF pos, int angleDelta)
{
    QWheelEvent event(pos, widget.mapToGlobal(pos), QPoint(), QPoint(0, angleDelta), Qt::NoButton, Qt::NoModifier,
                      Qt::NoScrollPhase, false);
    QApplication::sendEvent(&widget, &event);
}

void altDrag(QWidget& widget, Qt::MouseButton button, QPoint from, QPoint to)
{
    QTest::mousePress(&widget, button, Qt::AltModifier, from);
    for (int k = 1; k <= 4; ++k)
        QTest::mouseMove(&widget, from + (to - from) * k / 4);
    QTest::mouseRelease(&widget, button, Qt::AltModifier, to);
}

// How many pixels one metre east of `p` spans: the zoom there.
double pixelsPerMetre(const Viewport& viewport, glm::vec3 p)
{
    return distance(viewport.worldToPixel(p), viewport.worldToPixel(p + glm::vec3(1, 0, 0)));
}

QAction* viewAction(MainWindow& window, const QString& text)
{
    for (QAction* a : window.findChildren<QAction*>())
        if (a->text().remove('&') == text)
            return a;
    return nullptr;
}

}  // namespace

class TestDccNavigationUi : public QObject {
    Q_OBJECT

private:
    QTemporaryDir m_dir;

private slots:
    void wheelZoomsTowardsTheCursor_data()
    {
        QTest::addColumn<int>("mode");
        QTest::addColumn<bool>("hill");
        QTest::newRow("top") << int(ViewMode::Top) << false;
        QTest::newRow("3D") << int(ViewMode::Orbit) << false;
        QTest::newRow("3D on a hill") << int(ViewMode::Orbit) << true;
    }

    void wheelZoomsTowardsTheCursor()
    {
        QFETCH(int, mode);
        QFETCH(bool, hill);
        Viewport viewport;
        showInitialState(viewport, loadTestScene(m_dir, hill ? kHill : kYard));
        viewport.setViewMode(ViewMode(mode));
        renderOffscreen(viewport, kSize);
        const QPointF cursor(360, 110);  // off the centre, over the yard's north-east
        const std::optional<glm::vec3> under = viewport.pixelToGround(cursor);
        QVERIFY(under);
        QVERIFY(!hill || under->y > 2.0f);
        const double zoomBefore = pixelsPerMetre(viewport, *under);
        for (const int notches : {3, -5, 2}) {
            wheel(viewport, cursor, 120 * notches);
            const QPointF now = viewport.worldToPixel(*under);
            QVERIFY2(distance(now, cursor) < 1.5, qPrintable(text(now)));
        }
        wheel(viewport, cursor, 120 * 4);
        QVERIFY(distance(viewport.worldToPixel(*under), cursor) < 1.5);
        QVERIFY2(pixelsPerMetre(viewport, *under) > 1.5 * zoomBefore,
                 qPrintable(QString("%1 px/m, was %2").arg(pixelsPerMetre(viewport, *under)).arg(zoomBefore)));
    }

    void altRightDragZoomsTowardsWhereItBegan_data()
    {
        QTest::addColumn<int>("mode");
        QTest::newRow("top") << int(ViewMode::Top);
        QTest::newRow("3D") << int(ViewMode::Orbit);
    }

    void altRightDragZoomsTowardsWhereItBegan()
    {
        QFETCH(int, mode);
        Viewport viewport;
        showInitialState(viewport, loadTestScene(m_dir, kYard));
        viewport.setViewMode(ViewMode(mode));
        renderOffscreen(viewport, kSize);
        const QPoint start(150, 220);
        const std::optional<glm::vec3> under = viewport.pixelToGround(start);
        QVERIFY(under);
        const double before = pixelsPerMetre(viewport, *under);
        altDrag(viewport, Qt::RightButton, start, start + QPoint(60, 0));
        QVERIFY2(distance(viewport.worldToPixel(*under), start) < 1.5, qPrintable(text(viewport.worldToPixel(*under))));
        const double in = pixelsPerMetre(viewport, *under);
        QVERIFY2(in > 1.4 * before, qPrintable(QString("%1 px/m, was %2").arg(in).arg(before)));
        altDrag(viewport, Qt::RightButton, start, start + QPoint(-120, 0));
        QVERIFY(distance(viewport.worldToPixel(*under), start) < 1.5);
        QVERIFY(pixelsPerMetre(viewport, *under) < 0.8 * before);
    }

    void altMiddleDragPans_data()
    {
        QTest::addColumn<int>("mode");
        QTest::newRow("top") << int(ViewMode::Top);
        QTest::newRow("3D") << int(ViewMode::Orbit);
    }

    void altMiddleDragPans()
    {
        QFETCH(int, mode);
        Viewport viewport;
        showInitialState(viewport, loadTestScene(m_dir, kYard));
        viewport.setViewMode(ViewMode(mode));
        renderOffscreen(viewport, kSize);
        const QPoint centre(240, 180);
        const std::optional<glm::vec3> under = viewport.pixelToGround(centre);
        QVERIFY(under);
        const double zoom = pixelsPerMetre(viewport, *under);
        altDrag(viewport, Qt::MiddleButton, centre, centre + QPoint(70, 0));
        // The ground under the mouse goes with it, and nothing zooms.
        const QPointF now = viewport.worldToPixel(*under);
        QVERIFY2(distance(now, centre + QPoint(70, 0)) < 1.5, qPrintable(text(now)));
        QVERIFY(std::abs(pixelsPerMetre(viewport, *under) - zoom) < 0.02 * zoom);
    }

    void altLeftDragOrbitsAndNeverReachesTheTool()
    {
        MainWindow window;
        QVERIFY(showWithYaml(window, m_dir, "yard.yaml", kYard));
        QVERIFY(clickToolButton(window, "select"));
        Viewport& viewport = window.viewport();
        QTest::keyClick(&viewport, Qt::Key_2, Qt::ControlModifier);
        QCOMPARE(viewport.viewMode(), ViewMode::Orbit);
        QTest::keyClick(&viewport, Qt::Key_A);
        QTest::qWait(50);
        const QPointF centre(0.5 * viewport.width(), 0.5 * viewport.height());
        const std::optional<glm::vec3> pivot = viewport.pixelToGround(centre);
        QVERIFY(pivot);
        const glm::vec3 corner(12, 0, 8);
        const QPointF cornerBefore = viewport.worldToPixel(corner);
        const QPoint agent = viewport.worldToPixel({-6.0f, 0.8f, -3.0f}).toPoint();
        // Alt+left from the agent across the yard: a plain drag there would grab and move it.
        altDrag(viewport, Qt::LeftButton, agent, agent + QPoint(120, 40));
        QVERIFY2(distance(viewport.worldToPixel(*pivot), centre) < 1.5, qPrintable(text(viewport.worldToPixel(*pivot))));
        QVERIFY(distance(viewport.worldToPixel(corner), cornerBefore) > 30.0);
        QVERIFY(window.document().selection().empty());
        QCOMPARE(window.document().undoStack()->count(), 0);
        QVERIFY(window.document().scene().agents[0].position == glm::vec3(-6, 0, -3));
        // An Alt+click on it does not select it either; a plain one does.
        const QPoint moved = viewport.worldToPixel({-6.0f, 0.8f, -3.0f}).toPoint();
        QTest::mouseClick(&viewport, Qt::LeftButton, Qt::AltModifier, moved);
        QVERIFY(window.document().selection().empty());
        QTest::mouseClick(&viewport, Qt::LeftButton, Qt::NoModifier, moved);
        QVERIFY(window.document().selection() == (Selection{{ItemKind::Agent, 0}}));
    }

    void keyFFramesTheSelectionWhereItIsNowAndAFramesAll()
    {
        MainWindow window;
        QVERIFY(showWithYaml(window, m_dir, "yard.yaml", kYard));
        QVERIFY(clickToolButton(window, "select"));
        QAction* frameSelection = viewAction(window, "Frame Selection");
        QAction* frameAll = viewAction(window, "Frame All");
        QVERIFY(frameSelection && frameAll);
        QCOMPARE(frameSelection->shortcut(), QKeySequence(Qt::Key_F));
        QCOMPARE(frameAll->shortcut(), QKeySequence(Qt::Key_A));
        Viewport& viewport = window.viewport();
        viewport.frameAll();
        const glm::vec3 corner(12, 0, 8);
        const QPointF home = viewport.worldToPixel(corner);
        const double homeZoom = pixelsPerMetre(viewport, corner);

        // Nothing selected: F shows everything, as A does.
        wheel(viewport, {60, 60}, 600);
        QVERIFY(distance(viewport.worldToPixel(corner), home) > 50.0);
        QTest::keyClick(&viewport, Qt::Key_F);
        QVERIFY2(distance(viewport.worldToPixel(corner), home) < 1.0, qPrintable(text(viewport.worldToPixel(corner))));

        QVERIFY(playToFrame(window, 72));
        const std::size_t frame = viewport.frameIndex();
        const glm::vec3 now = window.simulation().cache().at(frame, 0).position;
        QVERIFY(glm::distance(now, glm::vec3(-6, 0, -3)) > 3.0f);
        QTest::mouseClick(&viewport, Qt::LeftButton, Qt::NoModifier, viewport.worldToPixel(now).toPoint());
        QVERIFY(window.document().selection() == (Selection{{ItemKind::Agent, 0}}));
        QTest::keyClick(&viewport, Qt::Key_F);
        const QPointF centre(0.5 * viewport.width(), 0.5 * viewport.height());
        QVERIFY2(distance(viewport.worldToPixel(now), centre) < 2.0, qPrintable(text(viewport.worldToPixel(now))));
        QVERIFY(pixelsPerMetre(viewport, now) > 2.0 * homeZoom);

        QTest::keyClick(&viewport, Qt::Key_A);
        QVERIFY(distance(viewport.worldToPixel(corner), home) < 1.0);
        QVERIFY(std::abs(pixelsPerMetre(viewport, corner) - homeZoom) < 0.01 * homeZoom);
    }
};

THRONG_REGISTER_TEST(TestDccNavigationUi)
#include "TestDccNavigationUi.moc"
