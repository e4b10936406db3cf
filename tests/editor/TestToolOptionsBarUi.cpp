// The tool options bar keeps one height whichever tool shows its options, so nothing
// below it jumps: clicking through every tool button, forward and back, leaves the
// bar's height and the viewport's place and size as they were.
#include "EditorTestSupport.h"
#include "EditorUiDriver.h"
#include "TestRegistry.h"

#include "editor/tools/ToolManager.h"

#include <QApplication>
#include <QTest>
#include <QToolBar>

using namespace throng;
using namespace throng::editor;
using namespace throng::editor::test;

class TestToolOptionsBarUi : public QObject {
    Q_OBJECT

private:
    QTemporaryDir m_dir;

private slots:
    void clickingThroughEveryToolMovesNothing()
    {
        MainWindow window;
        QVERIFY(showWithScene(window, m_dir, "crossroads.yaml"));
        auto* bar = window.findChild<QToolBar*>("toolOptionsToolBar");
        QVERIFY(bar && bar->isVisible());
        QWidget* vp = &window.viewport();
        auto viewportRect = [&] { return QRect(vp->mapTo(&window, QPoint(0, 0)), vp->size()); };
        QStringList keys;
        for (const ViewportTool* t : window.tools().tools())
            keys << t->objectKey();
        QCOMPARE(keys.size(), 19);  // with the action point, source, measure and layout move tools
        QVERIFY(clickToolButton(window, keys.front()));
        QApplication::processEvents();
        const int height = bar->height();
        const QRect place = viewportRect();
        QVERIFY(height >= 20);
        // Every tool, forward then back: each switch compared with the same height and
        // place, so any two tools agree.
        QStringList order = keys;
        for (auto it = keys.crbegin(); it != keys.crend(); ++it)
            order << *it;
        QString from = keys.front();
        for (const QString& to : order) {
            if (to == from)
                continue;
            QVERIFY(clickToolButton(window, to));
            QApplication::processEvents();
            QApplication::processEvents();
            const QString step = from + " -> " + to;
            QVERIFY2(bar->height() == height,
                     qPrintable(QString("%1: bar %2 px, was %3").arg(step).arg(bar->height()).arg(height)));
            QVERIFY2(viewportRect() == place, qPrintable(step));
            from = to;
        }
    }
};

THRONG_REGISTER_TEST(TestToolOptionsBarUi)
#include "TestToolOptionsBarUi.moc"
