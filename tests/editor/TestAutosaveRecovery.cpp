// Crash recovery as a user meets it: paint, the minute's autosave writes the recovery
// copy, the editor dies without closing; the next start offers the changes back, and
// they return unsaved and belonging to the scene's own file. Saving or saying no
// removes the copy.
#include "EditorUiDriver.h"
#include "TestRegistry.h"

#include "editor/AutosaveRecovery.h"
#include "editor/viewport/Viewport.h"

#include <QFile>
#include <QTest>

using namespace throng;
using namespace throng::editor;
using namespace throng::editor::test;

class TestAutosaveRecovery : public QObject {
    Q_OBJECT

private:
    QTemporaryDir m_dir;

private slots:
    void initTestCase()
    {
        QFile::remove(AutosaveRecovery::recoveryPath());
    }

    void changesLeftByACrashComeBackUnsaved()
    {
        QString sceneFile;
        std::vector<sim::Agent> painted;
        {
            MainWindow crashed;
            QVERIFY(showWithScene(crashed, m_dir, "crossroads.yaml"));
            QVERIFY(crashed.autosave().saveNow());
            QVERIFY2(!crashed.autosave().hasRecovery(), "nothing to recover before an edit");
            QVERIFY(clickToolButton(crashed, "crowdBrush"));
            dragOnGround(crashed, {{-35, -25}, {-15, -25}});
            painted = crashed.document().scene().agents;
            QVERIFY(painted.size() > 20);
            QVERIFY(crashed.autosave().saveNow());
            QVERIFY(crashed.autosave().hasRecovery());
            sceneFile = crashed.document().filePath();
        }  // destroyed without closing: as a crash leaves it

        MainWindow next;
        next.show();
        next.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&next));
        bool asked = false;
        QVERIFY(next.offerRecovery([&asked] { return asked = true; }));
        QVERIFY(asked);
        QCOMPARE(next.document().filePath(), sceneFile);
        QVERIFY(next.document().isModified());
        QCOMPARE(next.document().scene().agents.size(), painted.size());
        for (std::size_t i = 0; i < painted.size(); ++i)
            QCOMPARE(next.document().scene().agents[i].id, painted[i].id);

        QTest::keyClick(&next.viewport(), Qt::Key_S, Qt::ControlModifier);
        QVERIFY(!next.document().isModified());
        QVERIFY2(!next.autosave().hasRecovery(), "a save makes the recovery copy pointless");
    }

    void sayingNoDiscardsTheCopy()
    {
        {
            MainWindow crashed;
            QVERIFY(showWithScene(crashed, m_dir, "crossroads.yaml"));
            QVERIFY(clickToolButton(crashed, "trafficLight"));
            clickOnGround(crashed, {20, -12});
            QVERIFY(crashed.autosave().saveNow());
        }
        MainWindow next;
        QVERIFY(!next.offerRecovery([] { return false; }));
        QVERIFY(!next.autosave().hasRecovery());
        QVERIFY(next.document().scene().trafficLights.empty());
        QVERIFY(!next.offerRecovery([] { return true; }));  // nothing left to offer
    }
};

THRONG_REGISTER_TEST(TestAutosaveRecovery)
#include "TestAutosaveRecovery.moc"
