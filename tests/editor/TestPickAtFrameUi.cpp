// Picking what the viewport shows, driven like a user: after playing, a click on where an
// agent walked to selects it and a click where it started selects nothing, in the top
// and the 3D view (on a hill too); a box takes the agents now inside it; scrubbing back
// moves what a click finds; a spawned member selects its group and is ringed; the brain
// editor inspects the agent clicked while it is open, ringed in its own colour; a car is
// picked where it drives.
#include "EditorTestSupport.h"
#include "EditorUiDriver.h"
#include "PanelTestScene.h"
#include "TestRegistry.h"

#include "editor/brain/BrainEditorPanel.h"
#include "editor/panels/OutlinerPanel.h"
#include "editor/simulation/SimulationController.h"
#include "editor/viewport/SelectionHighlight.h"
#include "editor/viewport/Viewport.h"
#include "editor/viewport/ViewportPalette.h"

#include <glm/geometric.hpp>

#include <QDockWidget>
#include <QTest>

#include <cmath>

using namespace throng;
using namespace throng::editor;
using namespace throng::editor::test;

namespace {

// Two placed walkers (ids 1, 2) and a spawned group of three (ids 3 to 5) walk east.
const QByteArray kScene = R"(throng: 1
settings: {fps: 24, duration: 20, seed: 3, bounds: {min: [-20, -20], max: [20, 20]}}
agent_types: [{name: walker, radius: 0.3, max_speed: 1.4, max_force: 3, variation: {speed: [1, 1]}}]
goals: [{name: east, position: [18, 0], radius: 1}]
agents:
  - {id: 1, type: walker, position: [-12, 0, -4], goal: east}
  - {id: 2, type: walker, position: [-12, 0, 4], goal: east}
groups:
  - {name: crowd, type: walker, count: 3, rect: {min: [-14, 10], max: [-10, 14]}, goal: east}
)";

// The same walkers on a hill that rises 0.25 m per metre eastwards (2.5 m at x = -10).
const QByteArray kHillScene = R"(throng: 1
settings: {fps: 24, duration: 20, seed: 3, bounds: {min: [-20, -20], max: [20, 20]}}
agent_types: [{name: walker, radius: 0.3, max_speed: 1.4, max_force: 3, variation: {speed: [1, 1]}}]
goals: [{name: east, position: [18, 0], radius: 1}]
agents:
  - {id: 1, type: walker, position: [-12, 0, -4], goal: east}
  - {id: 2, type: walker, position: [-12, 0, 4], goal: east}
terrain: {origin: [-20, -20], cell: 20, cols: 3, rows: 3, heights: [0, 5, 10, 0, 5, 10, 0, 5, 10]}
)";

constexpr std::size_t kPlayedFrame = 96;  // 4 s at 1.4 m/s: about 5.6 m from the start

Selection only(ItemKind kind, std::size_t index)
{
    return {SceneItem{kind, index}};
}

// The cache index of agent `id`.
std::size_t indexOf(MainWindow& window, sim::AgentId id)
{
    const auto agents = window.simulation().cache().agents();
    for (std::size_t i = 0; i < agents.size(); ++i)
        if (agents[i].id == id)
            return i;
    qFatal("no agent %u", unsigned(id));
}

// Where agent `id` stands in the frame the viewport shows.
glm::vec3 shownPosition(MainWindow& window, sim::AgentId id)
{
    return window.simulation().cache().at(window.viewport().frameIndex(), indexOf(window, id)).position;
}

// The pixel of the middle of the agent's body standing at `feet`: in 3D bodies stand
// 1.65 m tall (5.5 radii), from above the feet.
QPoint bodyPixel(MainWindow& window, glm::vec3 feet)
{
    const bool upright = window.viewport().viewMode() == ViewMode::Orbit;
    return window.viewport().worldToPixel(feet + glm::vec3(0.0f, upright ? 0.8f : 0.0f, 0.0f)).toPoint();
}

void click(MainWindow& window, QPoint pixel)
{
    QTest::mouseClick(&window.viewport(), Qt::LeftButton, Qt::NoModifier, pixel);
}

void boxDrag(MainWindow& window, QPoint from, QPoint to)
{
    QWidget* viewport = &window.viewport();
    QTest::mousePress(viewport, Qt::LeftButton, Qt::NoModifier, from);
    QTest::mouseMove(viewport, (from + to) / 2);
    QTest::mouseMove(viewport, to);
    QTest::mouseRelease(viewport, Qt::LeftButton, Qt::NoModifier, to);
}

// Of 24 points on a ring of `radiusM` round `centre` (x, z), how many show `colour`.
int ringPixels(MainWindow& window, glm::vec2 centre, float radiusM, glm::vec4 colour)
{
    QTest::qWait(50);
    const QImage image = window.viewport().grabFramebuffer();
    int hits = 0;
    for (int k = 0; k < 24; ++k) {
        const float a = float(k) * 6.2831853f / 24.0f;
        const glm::vec3 p(centre.x + radiusM * std::cos(a), 0.0f, centre.y + radiusM * std::sin(a));
        hits += sameColour(pixelAt(image, window.viewport(), window.viewport().worldToPixel(p)), colour, 40);
    }
    return hits;
}

bool outlinerSelects(MainWindow& window, SceneItem item)
{
    QTreeWidgetItem* heading = window.outliner().kindRow(item.kind);
    return heading && int(item.index) < heading->childCount() && heading->child(int(item.index))->isSelected();
}

QString where(glm::vec3 p)
{
    return QString("(%1, %2, %3)").arg(p.x).arg(p.y).arg(p.z);
}

}  // namespace

class TestPickAtFrameUi : public QObject {
    Q_OBJECT

private:
    QTemporaryDir m_dir;

    // Opens `yaml`, takes the select tool, plays to kPlayedFrame and pauses.
    bool openAndPlay(MainWindow& window, const QByteArray& yaml, ViewMode mode)
    {
        if (!showWithYaml(window, m_dir, "pick.yaml", yaml) || !clickToolButton(window, "select"))
            return false;
        if (mode == ViewMode::Orbit) {
            QTest::keyClick(&window.viewport(), Qt::Key_2, Qt::ControlModifier);
            if (window.viewport().viewMode() != ViewMode::Orbit)
                return false;
            QTest::keyClick(&window.viewport(), Qt::Key_A);
        }
        return playToFrame(window, kPlayedFrame);
    }

    // A click where agent 1 walked to selects it; where it started, nothing.
    void clickPicksTheShownAgent(MainWindow& window)
    {
        const glm::vec3 now = shownPosition(window, 1);
        const glm::vec3 start = window.document().scene().agents[0].position;
        QVERIFY2(glm::distance(now, start) > 4.0f, qPrintable(where(now)));
        click(window, bodyPixel(window, now));
        QVERIFY2(window.document().selection() == only(ItemKind::Agent, 0), qPrintable(where(now)));
        QVERIFY(outlinerSelects(window, {ItemKind::Agent, 0}));
        QCOMPARE(window.viewport().focusedAgent(), sim::AgentId(1));
        click(window, bodyPixel(window, start));
        QVERIFY(window.document().selection().empty());
        QCOMPARE(window.viewport().focusedAgent(), sim::AgentId(0));
    }

    // A box round both placed agents' shown bodies takes the two of them, not the group.
    void boxTakesTheShownAgents(MainWindow& window)
    {
        const QPoint a = bodyPixel(window, shownPosition(window, 1)), b = bodyPixel(window, shownPosition(window, 2));
        const QPoint margin(25, 25);
        const QRect box = QRect(a, b).normalized().adjusted(-margin.x(), -margin.y(), margin.x(), margin.y());
        boxDrag(window, box.topLeft(), box.bottomRight());
        const Selection selection = window.document().selection();
        QVERIFY2(selection.size() == 2, qPrintable(QString::number(selection.size())));
        QVERIFY(outlinerSelects(window, {ItemKind::Agent, 0}) && outlinerSelects(window, {ItemKind::Agent, 1}));
        // The same box drawn round where they started catches nobody.
        const QPoint s0 = bodyPixel(window, window.document().scene().agents[0].position);
        const QPoint s1 = bodyPixel(window, window.document().scene().agents[1].position);
        const QRect startBox = QRect(s0, s1).normalized().adjusted(-margin.x(), -margin.y(), margin.x(), margin.y());
        boxDrag(window, startBox.topLeft(), startBox.bottomRight());
        QVERIFY(window.document().selection().empty());
    }

private slots:
    void topViewPicksWhereAgentsAreNow()
    {
        MainWindow window;
        QVERIFY(openAndPlay(window, kScene, ViewMode::Top));
        clickPicksTheShownAgent(window);
        if (QTest::currentTestFailed())
            return;
        boxTakesTheShownAgents(window);
    }

    void threeDViewPicksWhereAgentsAreNow()
    {
        MainWindow window;
        QVERIFY(openAndPlay(window, kScene, ViewMode::Orbit));
        clickPicksTheShownAgent(window);
        if (QTest::currentTestFailed())
            return;
        boxTakesTheShownAgents(window);
    }

    void threeDViewPicksAgentsOnAHill()
    {
        MainWindow window;
        QVERIFY(openAndPlay(window, kHillScene, ViewMode::Orbit));
        const glm::vec3 now = shownPosition(window, 1);
        QVERIFY2(now.y > 3.0f, qPrintable(where(now)));
        // Below it on the flat ground y = 0 there is nothing to click.
        click(window, bodyPixel(window, {now.x, 0.0f, now.z}));
        QVERIFY(window.document().selection().empty());
        click(window, bodyPixel(window, now));
        QVERIFY2(window.document().selection() == only(ItemKind::Agent, 0), qPrintable(where(now)));
    }

    void scrubbingBackMovesWhatAClickFinds()
    {
        MainWindow window;
        QVERIFY(openAndPlay(window, kScene, ViewMode::Top));
        const glm::vec3 late = shownPosition(window, 1);
        QVERIFY(scrubWithKeys(window, 24));
        const glm::vec3 early = shownPosition(window, 1);
        QVERIFY2(glm::distance(late, early) > 3.0f, qPrintable(where(late) + " " + where(early)));
        click(window, bodyPixel(window, late));
        QVERIFY(window.document().selection().empty());
        click(window, bodyPixel(window, early));
        QVERIFY(window.document().selection() == only(ItemKind::Agent, 0));
        // Its ring is drawn where it stands on the scrubbed frame, not where it was.
        const float ring = 0.3f + 0.25f;
        QVERIFY(ringPixels(window, {early.x, early.z}, ring, palette::kSelection) >= 16);
        QVERIFY(ringPixels(window, {late.x, late.z}, ring, palette::kSelection) <= 2);
    }

    void aGroupMemberSelectsItsGroupAndIsRinged()
    {
        MainWindow window;
        QVERIFY(openAndPlay(window, kScene, ViewMode::Top));
        const glm::vec3 member = shownPosition(window, 4);
        QVERIFY2(member.x > -9.0f, qPrintable(where(member)));  // it left the spawn area
        click(window, bodyPixel(window, member));
        QVERIFY(window.document().selection() == only(ItemKind::Group, 0));
        QVERIFY(outlinerSelects(window, {ItemKind::Group, 0}));
        QCOMPARE(window.viewport().focusedAgent(), sim::AgentId(4));
        const float ring = 0.3f + 0.25f;
        QVERIFY(ringPixels(window, {member.x, member.z}, ring, palette::kSelection) >= 16);
        // Playing on, the ring goes with it.
        QVERIFY(playToFrame(window, kPlayedFrame + 48));
        const glm::vec3 later = shownPosition(window, 4);
        QVERIFY(glm::distance(later, member) > 1.5f);
        QVERIFY(ringPixels(window, {later.x, later.z}, ring, palette::kSelection) >= 16);
        QVERIFY(ringPixels(window, {member.x, member.z}, ring, palette::kSelection) <= 2);
        // A box round the members takes their group once.
        click(window, bodyPixel(window, window.document().scene().agents[0].position));
        QVERIFY(window.document().selection().empty());
        QRect box;
        for (sim::AgentId id : {3u, 4u, 5u}) {
            const QPoint p = bodyPixel(window, shownPosition(window, id));
            box = box.isNull() ? QRect(p, p) : box.united(QRect(p, p));
        }
        box.adjust(-15, -15, 15, 15);
        boxDrag(window, box.topLeft(), box.bottomRight());
        QVERIFY(window.document().selection() == only(ItemKind::Group, 0));
    }

    void aVehicleIsPickedWhereItDrivesNow()
    {
        MainWindow window;
        QVERIFY(openAndPlay(window, trafficScene(), ViewMode::Top));
        // Car 50 starts 10 m along lane "side", at (-20, -27), at 4 m/s.
        const glm::vec3 now = shownPosition(window, 50);
        const glm::vec3 start(-20, 0, -27);
        QVERIFY2(glm::distance(now, start) > 4.0f, qPrintable(where(now)));
        click(window, bodyPixel(window, now));
        QVERIFY(window.document().selection() == only(ItemKind::Vehicle, 1));
        QVERIFY(outlinerSelects(window, {ItemKind::Vehicle, 1}));
        click(window, bodyPixel(window, start));
        QVERIFY(window.document().selection() != only(ItemKind::Vehicle, 1));
    }

    void theBrainEditorInspectsTheClickedAgent()
    {
        MainWindow window;
        QVERIFY(openAndPlay(window, kScene, ViewMode::Top));
        auto* panel = window.findChild<BrainEditorPanel*>();
        QVERIFY(panel && !panel->isVisible());
        QVERIFY(panel);
        // Closed, the brain editor follows nobody.
        click(window, bodyPixel(window, shownPosition(window, 2)));
        QCOMPARE(panel->pickedAgent(), std::ptrdiff_t(-1));
        QTest::keyClick(&window.viewport(), Qt::Key_B, Qt::ControlModifier);
        QTRY_VERIFY(panel->isVisible());
        QTest::qWait(100);  // the smaller viewport frames the scene again on its next paint
        QVERIFY(window.viewport().frameIndex() >= kPlayedFrame);
        const glm::vec3 member = shownPosition(window, 5);
        click(window, bodyPixel(window, member));
        QCOMPARE(panel->pickedAgent(), std::ptrdiff_t(indexOf(window, 5)));
        QCOMPARE(window.viewport().inspectedAgent(), sim::AgentId(5));
        // Its ring lies just outside the selection's, in the inspection colour.
        const float inspected = 0.3f + 0.25f + 0.42f;
        QVERIFY(ringPixels(window, {member.x, member.z}, inspected, SelectionHighlight::kInspectedColour) >= 16);
        // Clicking another agent inspects that one instead.
        click(window, bodyPixel(window, shownPosition(window, 1)));
        QVERIFY(window.document().selection() == only(ItemKind::Agent, 0));
        QCOMPARE(panel->pickedAgent(), std::ptrdiff_t(indexOf(window, 1)));
        QCOMPARE(window.viewport().inspectedAgent(), sim::AgentId(1));
        const glm::vec3 one = shownPosition(window, 1);
        QVERIFY(ringPixels(window, {one.x, one.z}, inspected, SelectionHighlight::kInspectedColour) >= 16);
        QVERIFY(ringPixels(window, {member.x, member.z}, inspected, SelectionHighlight::kInspectedColour) <= 2);
    }
};

THRONG_REGISTER_TEST(TestPickAtFrameUi)
#include "TestPickAtFrameUi.moc"
