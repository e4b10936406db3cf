// The window's workspaces driven like a user: Ctrl+B gives the brain editor room of its
// own beside the viewport and gives it back; each workspace keeps its arrangement; View >
// Reset Layout restores the default; a layout that no longer fits does not come back at
// the next launch; Properties needs no horizontal scroll bar at 1280 x 800; the foot is as
// low as the timeline needs, and the messages give back the height the analysis took.
#include "EditorTestSupport.h"
#include "EditorUiDriver.h"
#include "TestRegistry.h"

#include "editor/WorkspaceLayout.h"
#include "editor/brain/BrainEditorPanel.h"
#include "editor/panels/AnalysisPanel.h"
#include "editor/panels/OutlinerPanel.h"
#include "editor/panels/TimelinePanel.h"

#include <QAbstractButton>
#include <QApplication>
#include <QDockWidget>
#include <QMenu>
#include <QMenuBar>
#include <QScreen>
#include <QScrollArea>
#include <QScrollBar>
#include <QSettings>
#include <QSlider>
#include <QTabBar>
#include <QTest>
#include <QTimer>

using namespace throng;
using namespace throng::editor;
using namespace throng::editor::test;

namespace {

QDockWidget* dock(MainWindow& window, const char* name)
{
    return window.findChild<QDockWidget*>(name);
}

bool shown(MainWindow& window, const char* name)
{
    QDockWidget* d = dock(window, name);
    return d && d->isVisible();
}

void pressCtrlB(MainWindow& window)
{
    QTest::keyClick(&window.viewport(), Qt::Key_B, Qt::ControlModifier);
    QCoreApplication::processEvents();
}

// Opens the View menu with Alt+V and clicks `text` in it.
bool clickViewMenuItem(MainWindow& window, const QString& text)
{
    bool clicked = false;
    QTimer::singleShot(50, [&] {
        clicked = clickPopupItem(text);
        if (!clicked && QApplication::activePopupWidget())
            QApplication::activePopupWidget()->close();
    });
    QTest::keyClick(&window, Qt::Key_V, Qt::AltModifier);
    for (int i = 0; i < 150 && !clicked && QApplication::activePopupWidget(); ++i)
        QTest::qWait(20);
    QCoreApplication::processEvents();
    return clicked;
}

bool openAt(MainWindow& window, const QTemporaryDir& dir, QSize size)
{
    if (!showWithScene(window, dir, "crossroads.yaml"))
        return false;
    window.resize(size);
    QCoreApplication::processEvents();
    QTest::qWait(50);
    return window.size() == size;
}

}  // namespace

class TestWorkspaceUi : public QObject {
    Q_OBJECT

private:
    QTemporaryDir m_dir;

private slots:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
    }

    void init() { QSettings().clear(); }

    void ctrlBGivesTheBrainEditorItsOwnRoomAndGivesItBack()
    {
        MainWindow window;
        QVERIFY(openAt(window, m_dir, {1280, 800}));
        const QSize viewportBefore = window.viewport().size();
        QSlider* scrub = window.timeline().scrubBar();
        const int scrubBefore = scrub->width();
        QVERIFY(!window.brainEditor().isVisible());
        pressCtrlB(window);
        QCOMPARE(window.workspace().current(), Workspace::Brains);
        QVERIFY(window.brainEditor().isVisible());
        // The docks that give it room are put away; the timeline and the viewport stay usable.
        QVERIFY(!shown(window, "outlinerDock") && !shown(window, "propertiesDock") && !shown(window, "historyDock"));
        QVERIFY(shown(window, "timelineDock"));
        QVERIFY2(window.viewport().width() >= 360 && window.viewport().height() >= 260,
                 qPrintable(QString("%1 x %2").arg(window.viewport().width()).arg(window.viewport().height())));
        QVERIFY2(window.brainEditor().width() >= 420, qPrintable(QString::number(window.brainEditor().width())));
        QVERIFY2(window.viewport().height() >= viewportBefore.height() - 2,
                 qPrintable(QString("%1 -> %2").arg(viewportBefore.height()).arg(window.viewport().height())));
        QVERIFY2(scrub->width() >= scrubBefore - 2, qPrintable(QString("%1 -> %2").arg(scrubBefore).arg(scrub->width())));
        // The workspace tab shows where we are; Ctrl+B again is back to the layout as it was.
        QCOMPARE(window.findChild<QTabBar*>("workspaceTabs")->currentIndex(), 1);
        pressCtrlB(window);
        QCOMPARE(window.workspace().current(), Workspace::Layout);
        QVERIFY(!window.brainEditor().isVisible());
        QVERIFY(shown(window, "outlinerDock") && shown(window, "propertiesDock") && shown(window, "historyDock"));
        QTRY_COMPARE(window.viewport().size(), viewportBefore);
        // The tab bar switches too.
        auto* tabs = window.findChild<QTabBar*>("workspaceTabs");
        QTest::mouseClick(tabs, Qt::LeftButton, Qt::NoModifier, tabs->tabRect(1).center());
        QCOMPARE(window.workspace().current(), Workspace::Brains);
        QVERIFY(window.brainEditor().isVisible());
    }

    void eachWorkspaceKeepsItsArrangementAndResetRestoresIt()
    {
        MainWindow window;
        QVERIFY(openAt(window, m_dir, {1400, 900}));
        // The user closes History with its title bar's close button.
        auto* close = dock(window, "historyDock")->findChild<QAbstractButton*>("qt_dockwidget_closebutton");
        QVERIFY(close);
        QTest::mouseClick(close, Qt::LeftButton);
        QVERIFY(!shown(window, "historyDock"));
        pressCtrlB(window);
        pressCtrlB(window);
        QVERIFY(!shown(window, "historyDock"));  // kept, not reset, by the round trip
        QVERIFY(shown(window, "outlinerDock"));
        QVERIFY(clickViewMenuItem(window, "Reset Layout"));
        QVERIFY(shown(window, "historyDock"));
        QVERIFY(shown(window, "outlinerDock") && shown(window, "propertiesDock") && shown(window, "timelineDock"));
    }

    void aSavedLayoutComesBackAtTheNextLaunch()
    {
        {
            MainWindow window;
            QVERIFY(openAt(window, m_dir, {1400, 900}));
            dock(window, "historyDock")->findChild<QAbstractButton*>("qt_dockwidget_closebutton")->click();
            pressCtrlB(window);
            window.close();
        }
        MainWindow next;
        next.show();
        next.activateWindow();
        QVERIFY(QTest::qWaitForWindowExposed(&next));
        QVERIFY(QTest::qWaitForWindowActive(&next));
        QCOMPARE(next.workspace().current(), Workspace::Brains);
        QVERIFY(next.brainEditor().isVisible());
        pressCtrlB(next);
        QVERIFY(!shown(next, "historyDock"));
        QVERIFY(shown(next, "outlinerDock"));
    }

    void aBrokenLayoutDoesNotComeBack()
    {
        {
            MainWindow window;
            QVERIFY(openAt(window, m_dir, {1400, 900}));
            QDockWidget* properties = dock(window, "propertiesDock");
            properties->setFloating(true);
            properties->move(40000, 40000);  // dragged off every screen
            QCoreApplication::processEvents();
            window.close();
        }
        {
            MainWindow next;
            next.show();
            QVERIFY(QTest::qWaitForWindowExposed(&next));
            QDockWidget* properties = dock(next, "propertiesDock");
            QVERIFY(properties->isVisible());
            const QRect screen = next.screen()->availableGeometry();
            QVERIFY2(!properties->isFloating() || screen.intersects(properties->frameGeometry()),
                     "the off-screen dock came back off the screen");
        }
        // A layout written by an older build is not applied either.
        QSettings settings;
        settings.setValue("workspace/version", 1);
        settings.setValue("workspace/layout/window", QByteArray("garbage"));
        MainWindow again;
        again.show();
        QVERIFY(QTest::qWaitForWindowExposed(&again));
        QVERIFY(shown(again, "outlinerDock") && shown(again, "propertiesDock") && shown(again, "timelineDock"));
        QCOMPARE(again.size(), QSize(1280, 800));
    }

    void propertiesFitAt1280x800WithoutAHorizontalScrollBar()
    {
        MainWindow window;
        QVERIFY(openAt(window, m_dir, {1280, 800}));
        auto* scroll = window.findChild<QWidget*>("properties")->findChild<QScrollArea*>();
        QVERIFY(scroll);
        const sim::Scene& scene = window.document().scene();
        int checked = 0;
        for (int k = 0; k < kItemKindCount; ++k) {
            const auto kind = ItemKind(k);
            if (itemCount(scene, kind) == 0)
                continue;
            if (kind == ItemKind::Settings) {
                QTreeWidgetItem* row = window.outliner().kindRow(kind);
                QTest::mouseClick(window.outliner().viewport(), Qt::LeftButton, Qt::NoModifier,
                                  window.outliner().visualItemRect(row).center());
                QCOMPARE(window.document().selection(), (Selection{{kind, 0}}));
            } else {
                selectInOutliner(window, {{kind, 0}});
            }
            QCoreApplication::processEvents();
            QTest::qWait(30);
            QWidget* widest = nullptr;
            for (QWidget* w : scroll->widget()->findChildren<QWidget*>())
                if (w->isVisible() && (!widest || w->minimumSizeHint().width() > widest->minimumSizeHint().width()))
                    widest = w;
            QVERIFY2(!scroll->horizontalScrollBar()->isVisible(),
                     qPrintable(kindTitle(kind) + QString(": %1 px of fields in a %2 px panel; the widest is %3 (%4 px)")
                                                      .arg(scroll->widget()->minimumSizeHint().width())
                                                      .arg(scroll->viewport()->width())
                                                      .arg(widest ? widest->objectName() + " " + widest->metaObject()->className() : "")
                                                      .arg(widest ? widest->minimumSizeHint().width() : 0)));
            ++checked;
        }
        QVERIFY2(checked >= 10, qPrintable(QString::number(checked)));
    }

    void theFootIsAsLowAsTheTimelineNeeds()
    {
        // At 1280 x 800 the bottom row (timeline, messages, and the analysis behind them)
        // is as tall as the timeline's controls ask, not as the analysis' charts: the
        // viewport keeps the height.
        MainWindow window;
        QVERIFY(openAt(window, m_dir, {1280, 800}));
        auto* timeline = window.findChild<QDockWidget*>("timelineDock");
        QVERIFY(timeline && shown(window, "timelineDock"));
        // (The messages' own minimum and the tab bar under them set it, a little above the
        // timeline's 80-odd px; the analysis would ask for 190.)
        QVERIFY2(timeline->height() < window.analysis().minimumSizeHint().height(),
                 qPrintable(QString("%1 px, the analysis asks %2")
                                .arg(timeline->height())
                                .arg(window.analysis().minimumSizeHint().height())));
        QVERIFY2(window.viewport().height() >= 560, qPrintable(QString::number(window.viewport().height())));
        // The transport controls stay under the ruler, whatever the dock's height.
        auto* ruler = window.findChild<QWidget*>("scrubBar");
        auto* play = window.findChild<QAbstractButton*>("playButton");
        QVERIFY(ruler && play);
        QVERIFY(play->mapTo(&window, QPoint(0, 0)).y() - ruler->mapTo(&window, QPoint(0, ruler->height())).y() < 12);
    }

    void theMessagesGiveBackTheHeightTheAnalysisTook()
    {
        MainWindow window;
        QVERIFY(openAt(window, m_dir, {1280, 800}));
        QDockWidget* timeline = dock(window, "timelineDock");
        QDockWidget* analysis = dock(window, "analysisDock");
        auto* scroll = window.findChild<QScrollArea*>("analysisScroll");
        QVERIFY(timeline && analysis && scroll);
        const int low = timeline->height(), viewport = window.viewport().height();

        // The analysis brought forward takes the height it needs...
        QVERIFY(clickDockTab(window, "Analysis"));
        QTRY_VERIFY(timeline->height() > low + 40);
        QTRY_VERIFY(!scroll->verticalScrollBar()->isVisible());
        QVERIFY(window.viewport().height() < viewport);
        // ...and the messages give it back.
        QVERIFY(clickDockTab(window, "Messages"));
        QTRY_COMPARE(timeline->height(), low);
        QCOMPARE(window.viewport().height(), viewport);

        // A height the user sets while the analysis is forward stays.
        QVERIFY(clickDockTab(window, "Analysis"));
        QTRY_VERIFY(timeline->height() > low + 40);
        const int grown = timeline->height();
        // The separator between the viewport and the row: drag it 60 px up.
        const int gap = timeline->mapTo(&window, QPoint(0, 0)).y() - 3;
        const QPoint from(window.width() / 2, gap), to(window.width() / 2, gap - 60);
        QTest::mousePress(window.windowHandle(), Qt::LeftButton, Qt::NoModifier, from);
        for (int step = 1; step <= 6; ++step)
            QTest::mouseMove(window.windowHandle(), from + (to - from) * step / 6);
        QTest::mouseRelease(window.windowHandle(), Qt::LeftButton, Qt::NoModifier, to);
        QTRY_VERIFY2(timeline->height() >= grown + 40, qPrintable(QString("%1 px after the drag, %2 before")
                                                                      .arg(timeline->height())
                                                                      .arg(grown)));
        const int set = timeline->height();
        QVERIFY(clickDockTab(window, "Messages"));
        QTest::qWait(100);
        QCOMPARE(timeline->height(), set);
    }
};

THRONG_REGISTER_TEST(TestWorkspaceUi)
#include "TestWorkspaceUi.moc"
