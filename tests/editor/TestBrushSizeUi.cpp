// Every brush's size as a user changes it: ] grows and [ shrinks the radius in steps
// (clamped), a Ctrl+drag in the viewport sets it with the disk drawn at the new size and
// paints nothing, and the options bar's radius field follows. A size is a tool setting:
// no undo step, kept when the user comes back to the brush.
#include "EditorTestSupport.h"
#include "EditorUiDriver.h"
#include "TestRegistry.h"

#include "editor/tools/BrushTool.h"
#include "editor/tools/ToolManager.h"
#include "editor/viewport/ToolOverlay.h"
#include "editor/viewport/Viewport.h"

#include <glm/geometric.hpp>

#include <QDoubleSpinBox>
#include <QTest>
#include <QToolBar>
#include <QUndoStack>

#include <cmath>

using namespace throng;
using namespace throng::editor;
using namespace throng::editor::test;

namespace {

struct Brush {
    const char* key;    // the tool
    const char* field;  // its radius spin box in the options bar
};
constexpr Brush kBrushes[] = {{"crowdBrush", "brushRadius"},
                              {"eraseBrush", "eraseRadius"},
                              {"variationBrush", "variationBrushRadius"},
                              {"orientBrush", "orientBrushRadius"},
                              {"assignBrush", "assignBrushRadius"}};

BrushTool* brush(MainWindow& window, const char* key)
{
    return qobject_cast<BrushTool*>(window.tools().tool(key));
}

QDoubleSpinBox* radiusField(MainWindow& window, const char* name)
{
    return window.findChild<QToolBar*>("toolOptionsToolBar")->findChild<QDoubleSpinBox*>(name);
}

void press(MainWindow& window, Qt::Key key, int times = 1)
{
    for (int i = 0; i < times; ++i)
        QTest::keyClick(&window.viewport(), key);
}

// How far right of `centre` (widget pixels) the overlay's drawing reaches along its row:
// the disk's rim, as the user sees it.
int rimReachPx(MainWindow& window, QPoint centre)
{
    auto* overlay = window.viewport().findChild<ToolOverlay*>();
    if (!overlay)
        return -1;
    const QImage image = overlay->grab().toImage();
    const qreal dpr = image.devicePixelRatio();
    int reach = -1;
    for (int x = centre.x() + 3; x < overlay->width(); ++x)
        for (int dy = -1; dy <= 1; ++dy)
            if (qAlpha(image.pixel(QPoint(int(x * dpr), int((centre.y() + dy) * dpr)))) > 60)
                reach = x - centre.x();
    return reach;
}

}  // namespace

class TestBrushSizeUi : public QObject {
    Q_OBJECT

private:
    QTemporaryDir m_dir;

private slots:
    void bracketsStepEveryBrushAndItsFieldFollows()
    {
        MainWindow window;
        QVERIFY(showWithScene(window, m_dir, "crossroads.yaml"));
        const int steps = window.document().undoStack()->count();
        for (const Brush& b : kBrushes) {
            QVERIFY(clickToolButton(window, b.key));
            BrushTool* tool = brush(window, b.key);
            QDoubleSpinBox* field = radiusField(window, b.field);
            QVERIFY2(tool && field, b.key);
            window.viewport().setFocus();
            const float r0 = tool->radiusM();
            QCOMPARE(field->value(), double(r0));
            press(window, Qt::Key_BracketRight);
            QVERIFY2(std::abs(tool->radiusM() - r0 * 1.25f) < 1e-4f, b.key);
            QVERIFY2(std::abs(field->value() - double(tool->radiusM())) < 0.006, b.key);
            press(window, Qt::Key_BracketRight);
            QVERIFY2(std::abs(tool->radiusM() - r0 * 1.5625f) < 1e-4f, b.key);
            press(window, Qt::Key_BracketLeft, 3);
            QVERIFY2(std::abs(tool->radiusM() - r0 / 1.25f) < 1e-4f, b.key);
            QVERIFY2(std::abs(field->value() - double(r0 / 1.25f)) < 0.006, b.key);
            // Clamped at 0.1 m and at 100 m.
            press(window, Qt::Key_BracketLeft, 30);
            QCOMPARE(tool->radiusM(), 0.1f);
            QCOMPARE(field->value(), 0.1);
            press(window, Qt::Key_BracketRight, 40);
            QCOMPARE(tool->radiusM(), 100.0f);
            QCOMPARE(field->value(), 100.0);
            press(window, Qt::Key_BracketLeft, 20);  // 100 / 1.25^20 = 1.15 m
            QVERIFY2(std::abs(tool->radiusM() - 1.1529f) < 1e-3f, b.key);
        }
        // Sizes are settings, not edits; each brush keeps its own when the user comes back.
        QCOMPARE(window.document().undoStack()->count(), steps);
        QVERIFY(!window.document().isModified());
        QVERIFY(clickToolButton(window, "select"));
        for (const Brush& b : kBrushes) {
            QVERIFY(clickToolButton(window, b.key));
            QVERIFY2(std::abs(brush(window, b.key)->radiusM() - 1.1529f) < 1e-3f, b.key);
            QVERIFY2(std::abs(radiusField(window, b.field)->value() - 1.15) < 0.006, b.key);
        }
    }

    void ctrlDragSetsTheSizeWithTheDiskShownAndPaintsNothing()
    {
        MainWindow window;
        QVERIFY(showWithScene(window, m_dir, "crossroads.yaml"));
        QWidget* vp = &window.viewport();
        const glm::vec2 centre(-30.0f, -25.0f);
        const QPoint c = pixelOf(window, centre);
        const double pxPerM = pixelOf(window, centre + glm::vec2(10.0f, 0.0f)).x() / 10.0 - c.x() / 10.0;
        QVERIFY2(pxPerM > 3.0, qPrintable(QString::number(pxPerM)));
        const int steps = window.document().undoStack()->count();
        const std::size_t agents = window.document().scene().agents.size();
        for (const Brush& b : kBrushes) {
            QVERIFY(clickToolButton(window, b.key));
            BrushTool* tool = brush(window, b.key);
            const float r0 = tool->radiusM();
            // Ctrl+press at the centre and drag 4 m worth of pixels to the right.
            const QPoint end = c + QPoint(int(std::lround(4.0 * pxPerM)), 0);
            QTest::mouseMove(vp, c);
            QTest::mousePress(vp, Qt::LeftButton, Qt::ControlModifier, c);
            for (int k = 1; k <= 10; ++k)
                QTest::mouseMove(vp, c + (end - c) * k / 10);
            QVERIFY2(tool->isResizing(), b.key);
            QVERIFY2(std::abs(tool->radiusM() - (r0 + 4.0f)) < 0.15f, qPrintable(QString::number(tool->radiusM())));
            QVERIFY(tool->diskCentre());
            QVERIFY(glm::length(glm::vec2(tool->diskCentre()->x, tool->diskCentre()->z) - centre) < 0.2f);
            QVERIFY2(std::abs(radiusField(window, b.field)->value() - double(tool->radiusM())) < 0.006, b.key);
            // The disk is drawn at the new radius, around the point the drag began.
            QTRY_VERIFY2(std::abs(rimReachPx(window, c) - (r0 + 4.0) * pxPerM) < 3.0,
                         qPrintable(QString("%1: rim %2 px, want %3").arg(b.key).arg(rimReachPx(window, c))
                                        .arg((r0 + 4.0) * pxPerM)));
            QTest::mouseRelease(vp, Qt::LeftButton, Qt::ControlModifier, end);
            QVERIFY(!tool->isResizing());
            QVERIFY2(std::abs(tool->radiusM() - (r0 + 4.0f)) < 0.15f, b.key);
            QCOMPARE(window.document().scene().agents.size(), agents);
            QCOMPARE(window.document().undoStack()->count(), steps);
        }

        // Escape during a resize gives the size back; the next plain drag paints with the new one.
        QVERIFY(clickToolButton(window, "crowdBrush"));
        BrushTool* crowd = brush(window, "crowdBrush");
        const float r1 = crowd->radiusM();
        QTest::mousePress(vp, Qt::LeftButton, Qt::ControlModifier, c);
        QTest::mouseMove(vp, c + QPoint(int(2 * pxPerM), 0));
        QVERIFY(crowd->radiusM() > r1 + 1.5f);
        QTest::keyClick(vp, Qt::Key_Escape);
        QCOMPARE(crowd->radiusM(), r1);
        QTest::mouseRelease(vp, Qt::LeftButton, Qt::ControlModifier, c + QPoint(int(2 * pxPerM), 0));
        QCOMPARE(window.document().scene().agents.size(), agents);
        dragOnGround(window, {centre, centre + glm::vec2(2.0f, 0.0f)});
        const std::vector<sim::Agent>& now = window.document().scene().agents;
        QVERIFY(now.size() > agents + 20);
        float farthest = 0.0f;
        for (std::size_t i = agents; i < now.size(); ++i)
            farthest = std::max(farthest, std::abs(now[i].position.z - centre.y));
        QVERIFY2(farthest > 3.5f && farthest <= r1 + 0.01f,
                 qPrintable(QString("farthest %1 m, radius %2 m").arg(farthest).arg(r1)));
    }
};

THRONG_REGISTER_TEST(TestBrushSizeUi)
#include "TestBrushSizeUi.moc"
