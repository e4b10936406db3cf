// The select tool driven like a user: box-select painted agents, drag the selection
// (one undo step), and reshape a path with its point and radius handles.
#include "EditorUiDriver.h"
#include "TestRegistry.h"

#include "editor/viewport/Viewport.h"

#include <glm/geometric.hpp>

#include <QTest>

#include <algorithm>

using namespace throng;
using namespace throng::editor;
using namespace throng::editor::test;

namespace {

glm::vec2 ground(const sim::Agent& a)
{
    return {a.position.x, a.position.z};
}

bool selected(const Selection& selection, SceneItem item)
{
    return std::find(selection.begin(), selection.end(), item) != selection.end();
}

// A band of agents across the open block north-west of the crossing.
std::size_t paintBand(MainWindow& window)
{
    if (!clickToolButton(window, "crowdBrush"))
        return 0;
    dragOnGround(window, {{-38, -25}, {-14, -25}});
    return window.document().scene().agents.size();
}

}  // namespace

class TestSelectionUi : public QObject {
    Q_OBJECT

private:
    QTemporaryDir m_dir;

private slots:
    void boxSelectTakesWhatIsInsideAndDragMovesItAll()
    {
        MainWindow window;
        QVERIFY(showWithScene(window, m_dir, "crossroads.yaml"));
        QVERIFY(paintBand(window) >= 40);
        QVERIFY(clickToolButton(window, "select"));
        // From empty ground 5 m off the band, across it: x in [-30, -20].
        dragOnGround(window, {{-30, -31}, {-20, -19}});
        const std::vector<sim::Agent> before = window.document().scene().agents;
        const Selection selection = window.document().selection();
        std::size_t inside = 0;
        for (std::size_t i = 0; i < before.size(); ++i) {
            const float x = before[i].position.x;
            if (x > -29.8f && x < -20.2f) {
                QVERIFY2(selected(selection, {ItemKind::Agent, i}), qPrintable(QString("agent at x = %1").arg(x)));
                ++inside;
            } else if (x < -30.2f || x > -19.8f) {
                QVERIFY2(!selected(selection, {ItemKind::Agent, i}), qPrintable(QString("agent at x = %1").arg(x)));
            }
        }
        QVERIFY2(inside >= 10, qPrintable(QString::number(inside)));
        QVERIFY(selection.size() >= inside && selection.size() <= inside + 4);

        // Grab the selected agent nearest the middle and drag it 8 m north: all move.
        std::size_t grab = 0;
        float bestD = 1e9f;
        for (const SceneItem& item : selection) {
            const float d = glm::length(ground(before[item.index]) - glm::vec2(-25, -25));
            if (d < bestD) {
                bestD = d;
                grab = item.index;
            }
        }
        const glm::vec2 from = ground(before[grab]);
        dragOnGround(window, {from, from + glm::vec2(0, -8)});
        const std::vector<sim::Agent>& after = window.document().scene().agents;
        for (std::size_t i = 0; i < after.size(); ++i) {
            const glm::vec2 moved = ground(after[i]) - ground(before[i]);
            if (selected(selection, {ItemKind::Agent, i}))
                QVERIFY2(glm::length(moved - glm::vec2(0, -8)) < 0.3f,
                         qPrintable(QString("agent %1 moved by %2, %3").arg(i).arg(moved.x).arg(moved.y)));
            else
                QCOMPARE(moved, glm::vec2(0.0f));
        }
        QVERIFY(window.document().selection() == selection);  // dragging keeps the selection
        QCOMPARE(window.document().undoStack()->count(), 2);  // paint, move
        QTest::keyClick(&window.viewport(), Qt::Key_Z, Qt::ControlModifier);
        QTRY_VERIFY(window.document().scene().agents == before);
        QTest::keyClick(&window.viewport(), Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
        QTRY_VERIFY(!(window.document().scene().agents == before));
    }

    void pathHandlesReshapeAndWidenIt()
    {
        MainWindow window;
        QVERIFY(showWithScene(window, m_dir, "crossroads.yaml"));
        QVERIFY(clickToolButton(window, "select"));
        const sim::Path original = window.document().scene().paths[0];  // nw_round, 0.8 m
        QCOMPARE(original.name, std::string("nw_round"));
        clickOnGround(window, {-8.2f, -30.0f});  // on its centre line
        QVERIFY(window.document().selection() == (Selection{{ItemKind::Path, 0}}));

        // The radius handle sits on the band's edge beside the first segment's middle.
        const glm::vec2 mid = 0.5f * (original.points[0] + original.points[1]);
        const glm::vec2 dir = glm::normalize(original.points[1] - original.points[0]);
        const glm::vec2 handle = mid + glm::vec2(-dir.y, dir.x) * original.radiusM;
        dragOnGround(window, {handle, glm::vec2(mid.x - 3.0f, mid.y)});
        const sim::Path& path = window.document().scene().paths[0];
        QVERIFY2(std::abs(path.radiusM - 3.0f) < 0.15f, qPrintable(QString::number(path.radiusM)));
        QCOMPARE(path.points, original.points);

        // Drag its first point 4 m west and 4 m south.
        dragOnGround(window, {original.points[0], original.points[0] + glm::vec2(-4, 4)});
        QVERIFY2(glm::length(path.points[0] - (original.points[0] + glm::vec2(-4, 4))) < 0.3f,
                 qPrintable(QString("%1, %2").arg(path.points[0].x).arg(path.points[0].y)));
        QCOMPARE(path.points[1], original.points[1]);
        QCOMPARE(path.points[2], original.points[2]);

        QUndoStack* stack = window.document().undoStack();
        QCOMPARE(stack->count(), 2);  // one step per drag
        stack->undo();
        QCOMPARE(path.points, original.points);
        stack->undo();
        QCOMPARE(path.radiusM, original.radiusM);
    }

    void escapeDuringADragPutsItBack()
    {
        MainWindow window;
        QVERIFY(showWithScene(window, m_dir, "crossroads.yaml"));
        QVERIFY(clickToolButton(window, "select"));
        QWidget* viewport = &window.viewport();
        QTest::mousePress(viewport, Qt::LeftButton, Qt::NoModifier, pixelOf(window, {-7.5f, -20.0f}));
        for (int k = 1; k <= 5; ++k)
            QTest::mouseMove(viewport, pixelOf(window, {-7.5f - 2.0f * float(k), -20.0f}));
        QVERIFY(window.document().scene().obstacles[0].center.x < -15.0f);
        QTest::keyClick(viewport, Qt::Key_Escape);
        QTest::mouseRelease(viewport, Qt::LeftButton, Qt::NoModifier, pixelOf(window, {-17.5f, -20.0f}));
        QCOMPARE(window.document().scene().obstacles[0].center, glm::vec2(-7.5f, -20.0f));
        QVERIFY(!window.document().isModified());
    }
};

THRONG_REGISTER_TEST(TestSelectionUi)
#include "TestSelectionUi.moc"
