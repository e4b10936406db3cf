// The editor window as a user drives it: opening a scene shows its agents (spawn groups
// included) in the status bar, a broken scene lists its errors with their lines in the
// Messages dock and leaves the open scene alone, the View menu switches cameras and the
// window comes back where it was left.
#include "EditorTestSupport.h"
#include "TestRegistry.h"

#include "editor/MainWindow.h"
#include "editor/MessagesPanel.h"

#include <QAction>
#include <QDockWidget>
#include <QFileInfo>
#include <QLabel>
#include <QMenuBar>
#include <QTest>

using namespace throng;
using namespace throng::editor;
using namespace throng::editor::test;

namespace {

// Two placed agents and a group of five.
const QByteArray kSevenAgents = "throng: 1\n"
                                "agent_types: [{name: walker}]\n"
                                "agents:\n"
                                "  - {type: walker, position: [0, 0]}\n"
                                "  - {type: walker, position: [1, 0]}\n"
                                "groups:\n"
                                "  - {name: crowd, type: walker, count: 5, rect: {min: [-5, -5], max: [-1, -1]}}\n";

// Line 5, column 11: a negative radius.
const QByteArray kBrokenOnLine5 = "throng: 1\n"
                                  "agent_types: [{name: walker}]\n"
                                  "agents:\n"
                                  "  - {type: walker, position: [0, 0]}\n"
                                  "obstacles: [{shape: circle, center: [1, 1], radius: -2}]\n";

QString statusText(MainWindow& window, const char* name)
{
    const QLabel* label = window.findChild<QLabel*>(name);
    return label ? label->text() : QStringLiteral("<no label %1>").arg(name);
}

QAction* menuAction(MainWindow& window, const QString& text)
{
    for (QAction* menu : window.menuBar()->actions())
        for (QAction* action : menu->menu()->actions())
            if (action->text().remove('&') == text)
                return action;
    return nullptr;
}

}  // namespace

class TestMainWindow : public QObject {
    Q_OBJECT

private:
    QTemporaryDir m_dir;

private slots:
    void openingASceneShowsItsAgentCount()
    {
        MainWindow window;
        window.show();
        QVERIFY(window.openScene(writeScene(m_dir, "seven.yaml", kSevenAgents)));
        // The agents come with frame 0, which the simulation's thread makes.
        QTRY_COMPARE(statusText(window, "agentCountLabel"), QString("7 agents"));
        QCOMPARE(statusText(window, "frameLabel"), QString("Frame 0"));
        QVERIFY(window.windowTitle().contains("seven.yaml"));
    }

    void brokenSceneIsListedWithItsLineAndTheSceneStays()
    {
        MainWindow window;
        window.show();
        QVERIFY(window.openScene(writeScene(m_dir, "seven.yaml", kSevenAgents)));
        const QString broken = writeScene(m_dir, "broken.yaml", kBrokenOnLine5);
        QVERIFY(!window.openScene(broken));

        QStringList rows;
        for (int i = 0; i < window.messages().count(); ++i)
            rows << window.messages().item(i)->text();
        const QString expected = broken + ":5:";
        QVERIFY2(rows.filter(expected).size() == 1 && rows.filter(expected).front().contains("error"),
                 qPrintable("looked for '" + expected + "' in:\n" + rows.join('\n')));
        QVERIFY(window.findChild<QDockWidget*>("messagesDock")->isVisible());
        QTRY_COMPARE(statusText(window, "agentCountLabel"), QString("7 agents"));
        QVERIFY(window.windowTitle().contains("seven.yaml"));
        QCOMPARE(window.document().scene().agents.size(), std::size_t(2));
    }

    void viewMenuSwitchesTheCamera()
    {
        MainWindow window;
        window.show();
        QAction* orbit = menuAction(window, "3D View");
        QAction* top = menuAction(window, "Top View");
        QVERIFY(orbit && top);
        QVERIFY(!orbit->toolTip().isEmpty());
        orbit->trigger();
        QCOMPARE(window.viewport().viewMode(), ViewMode::Orbit);
        top->trigger();
        QCOMPARE(window.viewport().viewMode(), ViewMode::Top);
        QVERIFY(top->isChecked());
    }

    void fileActionsHaveShortcutsAndTooltips()
    {
        MainWindow window;
        for (const QString& text : {QString("Open..."), QString("Save"), QString("Save As..."), QString("Quit")}) {
            QAction* action = menuAction(window, text);
            QVERIFY2(action, qPrintable("no File action " + text));
            QVERIFY2(!action->toolTip().isEmpty() && action->toolTip() != text, qPrintable(text));
        }
        QCOMPARE(menuAction(window, "Open...")->shortcut(), QKeySequence(QKeySequence::Open));
        QCOMPARE(menuAction(window, "Save")->shortcut(), QKeySequence(QKeySequence::Save));
    }

    void openedScenesAreRememberedInOpenRecent()
    {
        const QString first = writeScene(m_dir, "first.yaml", kSevenAgents);
        const QString second = writeScene(m_dir, "second.yaml", kSevenAgents);
        {
            MainWindow window;
            QVERIFY(window.openScene(first));
            QVERIFY(window.openScene(second));
        }
        MainWindow later;
        QAction* recent = menuAction(later, "Open Recent");
        QVERIFY(recent && recent->menu());
        const QList<QAction*> entries = recent->menu()->actions();
        QVERIFY(entries.size() >= 2);
        QCOMPARE(entries[0]->toolTip(), QFileInfo(second).absoluteFilePath());
        QCOMPARE(entries[1]->toolTip(), QFileInfo(first).absoluteFilePath());
        entries[1]->trigger();
        QCOMPARE(later.document().filePath(), QFileInfo(first).absoluteFilePath());
    }

    void windowComesBackWhereItWasLeft()
    {
        const QRect placed(120, 90, 900, 640);
        {
            MainWindow window;
            window.show();
            window.setGeometry(placed);
            QTRY_COMPARE(window.size(), placed.size());
            window.close();
        }
        MainWindow reopened;
        QCOMPARE(reopened.size(), placed.size());
    }
};

THRONG_REGISTER_TEST(TestMainWindow)
#include "TestMainWindow.moc"
