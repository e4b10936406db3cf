// Files as a user handles them: a scene file dragged from the file manager onto the
// window opens (anything else is refused), and File > Revert throws the edits away.
#include "EditorTestSupport.h"
#include "EditorUiDriver.h"
#include "TestRegistry.h"

#include "editor/viewport/Viewport.h"

#include <QAction>
#include <QApplication>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFile>
#include <QFileInfo>
#include <QLabel>
#include <QMenuBar>
#include <QMimeData>
#include <QTest>
#include <QUrl>

using namespace throng;
using namespace throng::editor;
using namespace throng::editor::test;

namespace {

const QByteArray kTwoWalkers = R"(throng: 1
agent_types:
  - name: walker
agents:
  - {type: walker, position: [0, 0]}
  - {type: walker, position: [1.5, -2], heading: 90}
)";

// Drags `path` from outside onto the middle of the window and drops it; returns whether
// the window accepted the drag.
bool dropFile(MainWindow& window, const QString& path)
{
    QMimeData data;
    data.setUrls({QUrl::fromLocalFile(path)});
    const QPoint at = window.rect().center();
    QDragEnterEvent enter(at, Qt::CopyAction, &data, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(&window, &enter);
    if (!enter.isAccepted())
        return false;
    QDropEvent drop(at, Qt::CopyAction, &data, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(&window, &drop);
    return drop.isAccepted();
}

QAction* fileAction(MainWindow& window, const QString& text)
{
    for (QAction* a : window.menuBar()->findChildren<QAction*>())
        if (a->text() == text)
            return a;
    return nullptr;
}

}  // namespace

class TestFilesUi : public QObject {
    Q_OBJECT

private:
    QTemporaryDir m_dir;

private slots:
    void droppingASceneFileOpensIt()
    {
        MainWindow window;
        QVERIFY(showWithScene(window, m_dir, "crossroads.yaml"));
        const QString other = writeScene(m_dir, "two.yaml", kTwoWalkers);
        const QString notes = writeScene(m_dir, "notes.txt", "not a scene");
        QVERIFY(!dropFile(window, notes));  // refused at the door
        QVERIFY(window.document().filePath().endsWith("crossroads.yaml"));

        QVERIFY(dropFile(window, other));
        QTRY_COMPARE(window.document().filePath(), QFileInfo(other).absoluteFilePath());
        QCOMPARE(window.document().scene().agents.size(), std::size_t(2));
        QTRY_COMPARE(window.findChild<QLabel*>("agentCountLabel")->text(), QString("2 agents"));
    }

    void droppingOverUnsavedChangesAsksFirst()
    {
        MainWindow window;
        QVERIFY(showWithScene(window, m_dir, "crossroads.yaml"));
        QVERIFY(clickToolButton(window, "obstacle"));
        clickOnGround(window, {-30, -30});
        int asked = 0;
        window.setUnsavedChangesPrompt([&asked] {
            ++asked;
            return QMessageBox::Cancel;
        });
        QVERIFY(dropFile(window, writeScene(m_dir, "two.yaml", kTwoWalkers)));
        QCOMPARE(asked, 1);
        QVERIFY(window.document().filePath().endsWith("crossroads.yaml"));
        QCOMPARE(window.document().scene().obstacles.size(), std::size_t(5));  // the edit is still there
    }

    void revertThrowsTheEditsAway()
    {
        MainWindow window;
        QVERIFY(showWithScene(window, m_dir, "crossroads.yaml"));
        const sim::Scene opened = window.document().scene();
        QVERIFY(clickToolButton(window, "crowdBrush"));
        dragOnGround(window, {{-38, -25}, {-14, -25}});
        QVERIFY(clickToolButton(window, "wall"));
        clickOnGround(window, {-30, -35});
        clickOnGround(window, {-20, -35});
        QTest::keyClick(&window.viewport(), Qt::Key_Return);
        QVERIFY(window.document().isModified());
        QVERIFY(!(window.document().scene() == opened));

        QAction* revert = fileAction(window, "Re&vert");
        QVERIFY(revert);
        revert->trigger();
        QVERIFY(window.document().scene() == opened);
        QVERIFY(!window.document().isModified());
        QCOMPARE(window.document().undoStack()->count(), 0);
        QTRY_COMPARE(window.findChild<QLabel*>("agentCountLabel")->text(), QString("%1 agents").arg(kCrossroadsAgents));
    }
};

THRONG_REGISTER_TEST(TestFilesUi)
#include "TestFilesUi.moc"
