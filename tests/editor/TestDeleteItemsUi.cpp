// Delete driven like a user: pick an agent, path, goal, lane, traffic light, hero or
// group in the viewport or the outliner, press Delete, and see it gone from the scene,
// the outliner and the viewport; Ctrl+Z brings the scene back bit for bit (the saved
// YAML is the same). Items still in use are refused with a message naming the users,
// unless the users go too; a deleted leader leaves its followers following nobody.
#include "EditorTestSupport.h"
#include "EditorUiDriver.h"
#include "PanelTestScene.h"
#include "TestRegistry.h"

#include "editor/panels/OutlinerPanel.h"
#include "editor/viewport/Viewport.h"

#include <QTest>

#include <algorithm>
#include <cmath>

using namespace throng;
using namespace throng::editor;
using namespace throng::editor::test;

Q_DECLARE_METATYPE(throng::editor::ItemKind)

namespace {

void pressDelete(MainWindow& window)
{
    QTest::keyClick(&window.viewport(), Qt::Key_Delete);
}

bool selects(MainWindow& window, glm::vec2 at, SceneItem item)
{
    clickOnGround(window, at);
    const Selection& s = window.document().selection();
    return std::find(s.begin(), s.end(), item) != s.end();
}

int outlinerRows(MainWindow& window, ItemKind kind)
{
    return window.outliner().kindRow(kind)->childCount();
}

}  // namespace

class TestDeleteItemsUi : public QObject {
    Q_OBJECT

private:
    QTemporaryDir m_dir;

private slots:
    void deleteRemovesTheItemAndUndoRestoresItExactly_data()
    {
        QTest::addColumn<ItemKind>("kind");
        QTest::addColumn<int>("index");
        QTest::addColumn<float>("pickX");  // NaN: picked in the outliner
        QTest::addColumn<float>("pickZ");
        QTest::addColumn<int>("agentsGone");  // shown agents the delete removes
        const float nan = std::nanf("");
        QTest::newRow("agent") << ItemKind::Agent << 2 << -2.0f << 0.0f << 1;
        QTest::newRow("path") << ItemKind::Path << 1 << -15.0f << 20.0f << 0;
        QTest::newRow("goal") << ItemKind::Goal << 1 << -25.0f << 15.0f << 0;
        QTest::newRow("lane") << ItemKind::Lane << 1 << 0.0f << -27.0f << 0;
        QTest::newRow("traffic light") << ItemKind::TrafficLight << 0 << 0.0f << 22.0f << 0;
        QTest::newRow("hero") << ItemKind::Hero << 0 << nan << nan << 1;
        QTest::newRow("group") << ItemKind::Group << 0 << nan << nan << 5;
    }

    void deleteRemovesTheItemAndUndoRestoresItExactly()
    {
        QFETCH(ItemKind, kind);
        QFETCH(int, index);
        QFETCH(float, pickX);
        QFETCH(float, pickZ);
        QFETCH(int, agentsGone);
        MainWindow window;
        QVERIFY(showWithYaml(window, m_dir, "delete.yaml", panelScene()));
        const QByteArray before = sceneYaml(window);
        const sim::Scene original = window.document().scene();
        const std::size_t count = itemCount(window.document().scene(), kind);
        const std::size_t shown = window.viewport().agentCount();
        const SceneItem item{kind, std::size_t(index)};
        const bool inViewport = !std::isnan(pickX);
        if (inViewport) {
            QVERIFY(clickToolButton(window, "select"));
            QVERIFY(selects(window, {pickX, pickZ}, item));
        } else {
            selectInOutliner(window, {item});
        }
        QVERIFY(window.document().selection() == Selection{item});

        pressDelete(window);
        QCOMPARE(itemCount(window.document().scene(), kind), count - 1);
        QCOMPARE(outlinerRows(window, kind), int(count - 1));
        QTRY_COMPARE(window.viewport().agentCount(), shown - std::size_t(agentsGone));
        QCOMPARE(window.document().undoStack()->count(), 1);
        if (inViewport)
            QVERIFY(!selects(window, {pickX, pickZ}, item));

        QTest::keyClick(&window.viewport(), Qt::Key_Z, Qt::ControlModifier);
        QCOMPARE(sceneYaml(window), before);
        QVERIFY(window.document().scene() == original);
        QCOMPARE(outlinerRows(window, kind), int(count));
        QTRY_COMPARE(window.viewport().agentCount(), shown);
        if (inViewport)
            QVERIFY(selects(window, {pickX, pickZ}, item));
    }

    void aPathAGroupFollowsIsRefusedUnlessTheGroupGoesToo()
    {
        MainWindow window;
        QVERIFY(showWithYaml(window, m_dir, "refuse.yaml", panelScene()));
        const QByteArray before = sceneYaml(window);
        selectInOutliner(window, {{ItemKind::Path, 0}});  // "loop", followed by "loopers"
        pressDelete(window);
        QCOMPARE(sceneYaml(window), before);
        QCOMPARE(window.document().undoStack()->count(), 0);
        QVERIFY2(lastMessage(window).contains("loop is still used by group loopers"), qPrintable(lastMessage(window)));

        selectInOutliner(window, {{ItemKind::Path, 0}, {ItemKind::Group, 0}});
        pressDelete(window);
        QCOMPARE(window.document().scene().paths.size(), std::size_t(1));
        QVERIFY(window.document().scene().groups.empty());
        QTest::keyClick(&window.viewport(), Qt::Key_Z, Qt::ControlModifier);
        QCOMPARE(sceneYaml(window), before);
    }

    void aLaneAGoalOrATypeInUseIsRefusedNamingTheUsers()
    {
        MainWindow window;
        QVERIFY(showWithYaml(window, m_dir, "users.yaml", panelScene()));
        const QByteArray before = sceneYaml(window);
        selectInOutliner(window, {{ItemKind::Lane, 0}});  // "main"
        pressDelete(window);
        QVERIFY2(lastMessage(window).contains("vehicle 1") &&
                     lastMessage(window).contains("the stop line of traffic light signal"),
                 qPrintable(lastMessage(window)));
        selectInOutliner(window, {{ItemKind::Goal, 0}});  // "east": all six walkers
        pressDelete(window);
        QVERIFY2(lastMessage(window).contains("Agent 1 (walker)") && lastMessage(window).contains("3 more"),
                 qPrintable(lastMessage(window)));
        selectInOutliner(window, {{ItemKind::AgentType, 1}});  // "runner": the hero
        pressDelete(window);
        QVERIFY2(lastMessage(window).contains("hero courier"), qPrintable(lastMessage(window)));
        QCOMPARE(sceneYaml(window), before);
        QCOMPARE(window.document().undoStack()->count(), 0);
    }

    void deletingALeaderClearsItsFollowersInTheSameStep()
    {
        MainWindow window;
        QVERIFY(showWithYaml(window, m_dir, "leader.yaml", panelScene()));
        const QByteArray before = sceneYaml(window);
        QCOMPARE(window.document().scene().agents[5].leader, 1u);
        QVERIFY(clickToolButton(window, "select"));
        QVERIFY(selects(window, {-10, 0}, {ItemKind::Agent, 0}));  // walker 1
        pressDelete(window);
        const sim::Scene& scene = window.document().scene();
        QCOMPARE(scene.agents.size(), std::size_t(5));
        QCOMPARE(scene.agents[4].id, 6u);
        QCOMPARE(scene.agents[4].leader, 0u);
        QCOMPARE(window.document().undoStack()->count(), 1);
        QTest::keyClick(&window.viewport(), Qt::Key_Z, Qt::ControlModifier);
        QCOMPARE(sceneYaml(window), before);
        QCOMPARE(scene.agents[5].leader, 1u);
    }
};

THRONG_REGISTER_TEST(TestDeleteItemsUi)
#include "TestDeleteItemsUi.moc"
