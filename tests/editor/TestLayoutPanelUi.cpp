// The Layout panel driven like a user, on a recorded crossing: an operation added for the
// agent selected in the Outliner (the Add menu), given its offset in Properties, switched
// off with the keyboard, a second one for a group, reordered and removed with the panel's
// buttons and keys; the viewport shows each state; every step undoes, and undoing them
// all gives back the scene file byte for byte. The layout check flags what an edit breaks:
// its count in the HUD, rings on the frame's agents, the list with frames, and a
// double-click on a clash goes to its frame and agent. "Only the clicked agent" takes the
// member of a group clicked in the viewport. Renaming a group keeps the operations on it.
#include "EditorTestSupport.h"
#include "EditorUiDriver.h"
#include "TestRegistry.h"

#include "editor/commands/NameReferences.h"
#include "editor/layout/LayoutCheckWatch.h"
#include "editor/layout/LayoutPanel.h"
#include "editor/panels/OutlinerPanel.h"
#include "editor/panels/TimelinePanel.h"
#include "editor/panels/TimelineRuler.h"
#include "editor/simulation/SimulationController.h"
#include "editor/viewport/ShownAgents.h"
#include "editor/viewport/Viewport.h"
#include "editor/viewport/ViewportPalette.h"
#include "simcore/layout/LayoutApply.h"

#include <QAction>
#include <QCheckBox>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QLineEdit>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QSpinBox>
#include <QTest>
#include <QTimer>
#include <QToolBar>
#include <QToolButton>
#include <QTreeWidget>
#include <QUndoStack>

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>

using namespace throng;
using namespace throng::editor;
using namespace throng::editor::test;

namespace {

// Two placed walkers (ids 1 at z = -4, 2 at z = 4) and a spawned group of three (ids 3
// to 5) walk east at 1 m/s.
const QByteArray kLayoutScene = R"(throng: 1
settings: {fps: 24, duration: 10, seed: 3, bounds: {min: [-20, -20], max: [20, 20]}}
agent_types: [{name: walker, radius: 0.3, max_speed: 1, max_force: 3, variation: {speed: [1, 1]}}]
goals: [{name: east, position: [18, 0], radius: 1}]
agents:
  - {id: 1, type: walker, position: [-12, 0, -4], goal: east}
  - {id: 2, type: walker, position: [-12, 0, 4], goal: east}
groups:
  - {name: crowd, type: walker, count: 3, rect: {min: [-14, 10], max: [-10, 14]}, goal: east}
)";

constexpr std::size_t kRecorded = 72;

QDockWidget* showLayoutDock(MainWindow& window)
{
    auto* dock = window.findChild<QDockWidget*>("layoutDock");
    dock->show();
    dock->raise();
    QTest::qWait(0);
    return dock;
}

// Picks `kind` ("Translate") from the panel's Add menu with the mouse.
bool addFromMenu(MainWindow& window, const QString& kind)
{
    auto* add = window.layoutPanel().findChild<QToolButton*>("layoutAddButton");
    if (!add)
        return false;
    bool picked = false;
    whenShown([&picked, kind] { return picked = clickPopupItem(kind); });
    QTest::mouseClick(add, Qt::LeftButton);
    return QTest::qWaitFor([&] { return picked; }, 5000);
}

// Where the viewport draws agent `id` on the shown frame (its feet), or nothing.
std::optional<glm::vec3> shownFeet(MainWindow& window, sim::AgentId id)
{
    const ShownAgents& shown = window.viewport().shownAgents();
    const std::size_t i = shown.find(id);
    if (i == ShownAgents::kNone || !shown.drawn(i))
        return std::nullopt;
    return shown.feet(i);
}

// Where the simulation recorded agent `id` on `frame`.
glm::vec3 recordedFeet(MainWindow& window, sim::AgentId id, std::size_t frame)
{
    const sim::FrameCache& cache = window.simulation().cache();
    for (std::size_t i = 0; i < cache.agentCount(); ++i)
        if (cache.agents()[i].id == id)
            return cache.at(frame, i).position;
    qFatal("agent %u is not in the recording", unsigned(id));
}

void clickRow(QListWidget* list, int row)
{
    list->scrollToItem(list->item(row));
    QTest::mouseClick(list->viewport(), Qt::LeftButton, Qt::NoModifier, list->visualItemRect(list->item(row)).center());
}

bool hudHasLayoutLine(MainWindow& window)
{
    for (const QString& line : window.viewport().hud().lines())
        if (line.startsWith("Layout:"))
            return true;
    return false;
}

// The scene `yaml` opened as `name`, played until frame `recorded` is computed, and
// scrubbed with the arrow keys to frame `shown`: the take a layout edit works on.
bool openTake(MainWindow& window, const QTemporaryDir& dir, const QString& name, const QByteArray& yaml,
              std::size_t recorded, std::size_t shown)
{
    return showWithYaml(window, dir, name, yaml) && playUntilRecorded(window, recorded) &&
           scrubWithKeys(window, shown);
}

}  // namespace

class TestLayoutPanelUi : public QObject {
    Q_OBJECT

private:
    QTemporaryDir m_dir;

private slots:
    void everyLayoutEditIsOneUndoableStepAndUndoingAllRestoresTheFile()
    {
        MainWindow window;
        QVERIFY(openTake(window, m_dir, "layout.yaml", kLayoutScene, kRecorded - 1, 48));
        const QByteArray original = sceneYaml(window);
        QUndoStack& undo = *window.document().undoStack();
        const int startIndex = undo.index();
        showLayoutDock(window);
        LayoutPanel& panel = window.layoutPanel();
        QListWidget* list = panel.list();
        QCOMPARE(list->count(), 0);

        // Nothing selected: the Add menu refuses, says why, and adds nothing.
        window.document().setSelection({});
        QVERIFY(addFromMenu(window, "Translate"));
        QVERIFY(window.document().scene().layout.ops.empty());
        QVERIFY2(lastMessage(window).contains("select agents"), qPrintable(lastMessage(window)));

        // Agent 1 selected in the Outliner; Add > Translate makes one operation on it,
        // selected, so that Properties edits it.
        selectInOutliner(window, {{ItemKind::Agent, 0}});
        QVERIFY(addFromMenu(window, "Translate"));
        QCOMPARE(window.document().scene().layout.ops.size(), std::size_t(1));
        const sim::LayoutOp& made = window.document().scene().layout.ops[0];
        QCOMPARE(made.kind, sim::LayoutKind::Translate);
        QCOMPARE(made.agents.ids, (std::vector<std::uint32_t>{1}));
        QCOMPARE(made.name, std::string("Translate 1"));
        QCOMPARE(window.document().selection(), (Selection{{ItemKind::LayoutOp, 0}}));
        QCOMPARE(list->count(), 1);
        QVERIFY2(list->item(0)->text().contains("agent 1"), qPrintable(list->item(0)->text()));

        // 8 m north in Properties: agent 1 is drawn on agent 2's line, 8 m from where it
        // was recorded; agent 2 where it was.
        const glm::vec3 was1 = recordedFeet(window, 1, 48), was2 = recordedFeet(window, 2, 48);
        typeInto(window, field<QDoubleSpinBox>(window, "offsetZ"), "8");
        QCOMPARE(window.document().scene().layout.ops[0].offset, glm::vec2(0.0f, 8.0f));
        QTRY_VERIFY(shownFeet(window, 1) && std::abs(shownFeet(window, 1)->z - (was1.z + 8.0f)) < 1e-4f);
        QCOMPARE(shownFeet(window, 1)->x, was1.x);
        QCOMPARE(*shownFeet(window, 2), was2);

        // Moved, agent 1 starts inside agent 2; the two drift apart as each heads for the
        // goal. Recounted from the recording: the frames their bodies (0.3 m each, less the
        // check's 5 cm) overlap once agent 1 is 8 m north. The recording has them 8 m apart.
        const sim::FrameCache& cache = window.simulation().cache();
        std::size_t overlapping = 0;
        for (std::size_t f = 0; f < cache.frameCount(); ++f) {
            const glm::vec3 d = recordedFeet(window, 1, f) + glm::vec3(0, 0, 8) - recordedFeet(window, 2, f);
            overlapping += std::hypot(d.x, d.z) < 0.6f - 0.05f;
        }
        QVERIFY2(overlapping > 24, qPrintable(QString::number(overlapping)));
        // The HUD counts them, both are ringed on frame 0, and the list names the pair
        // over those frames.
        QTRY_VERIFY(hudHasLayoutLine(window));
        QCOMPARE(window.layoutCheck().last().overlaps.size(), overlapping);
        QVERIFY(scrubWithKeys(window, 0));
        QCOMPARE(window.viewport().layoutFlaggedCount(), std::size_t(2));
        QVERIFY(scrubWithKeys(window, 48));
        QTreeWidget* clashes = panel.clashes();
        QVERIFY(clashes->isVisible());
        QCOMPARE(clashes->topLevelItemCount(), 1);
        QCOMPARE(clashes->topLevelItem(0)->text(0), QString("0–%1").arg(overlapping - 1));
        QCOMPARE(clashes->topLevelItem(0)->text(1), QString("1"));
        QCOMPARE(clashes->topLevelItem(0)->text(2), QString("agent 2"));

        // Double-clicking the clash goes to its first frame and clicks agent 1.
        const QRect rect = clashes->visualItemRect(clashes->topLevelItem(0));
        QTest::mouseClick(clashes->viewport(), Qt::LeftButton, Qt::NoModifier, rect.center());
        QTest::mouseDClick(clashes->viewport(), Qt::LeftButton, Qt::NoModifier, rect.center());
        QTRY_COMPARE(window.viewport().frameIndex(), std::size_t(0));
        QCOMPARE(window.viewport().focusedAgent(), sim::AgentId(1));
        QVERIFY(scrubWithKeys(window, 48));

        // Space on the row switches it off: agent 1 is back where it was recorded, and
        // the check is clean.
        clickRow(list, 0);
        QTest::keyClick(list, Qt::Key_Space);
        QVERIFY(!window.document().scene().layout.ops[0].enabled);
        QTRY_COMPARE(*shownFeet(window, 1), was1);
        QTRY_VERIFY(!hudHasLayoutLine(window));
        QVERIFY(window.layoutCheck().last().overlaps.empty());
        QCOMPARE(window.viewport().layoutFlaggedCount(), std::size_t(0));

        // The group, selected in the Outliner: Add > Delete removes it from the shown frame on.
        selectInOutliner(window, {{ItemKind::Group, 0}});
        QVERIFY(addFromMenu(window, "Delete"));
        QCOMPARE(window.document().scene().layout.ops.size(), std::size_t(2));
        const sim::LayoutOp& gone = window.document().scene().layout.ops[1];
        QCOMPARE(gone.kind, sim::LayoutKind::Delete);
        QCOMPARE(gone.agents.groups, (std::vector<std::string>{"crowd"}));
        QCOMPARE(gone.firstFrame, std::size_t(48));
        QTRY_VERIFY(!shownFeet(window, 3) && !shownFeet(window, 4) && !shownFeet(window, 5));
        QVERIFY(shownFeet(window, 1) && shownFeet(window, 2));

        // Earlier (the panel's button) puts the delete first; Ctrl+Down puts it back.
        QCOMPARE(list->currentRow(), 1);
        auto* up = panel.findChild<QToolBar*>("layoutBar")->widgetForAction(panel.findChild<QAction*>("layoutUp"));
        QTest::mouseClick(up, Qt::LeftButton);
        QCOMPARE(window.document().scene().layout.ops[0].kind, sim::LayoutKind::Delete);
        QCOMPARE(window.document().scene().layout.ops[1].name, std::string("Translate 1"));
        QCOMPARE(list->currentRow(), 0);
        list->setFocus();
        QTest::keyClick(list, Qt::Key_Down, Qt::ControlModifier);
        QCOMPARE(window.document().scene().layout.ops[1].kind, sim::LayoutKind::Delete);

        // Delete on the selected row removes the operation: the group is back.
        clickRow(list, 1);
        QTest::keyClick(list, Qt::Key_Delete);
        QCOMPARE(window.document().scene().layout.ops.size(), std::size_t(1));
        QCOMPARE(list->count(), 1);
        QTRY_VERIFY(shownFeet(window, 3) && shownFeet(window, 4) && shownFeet(window, 5));

        // Each of add, offset, switch, add, earlier, later and remove was one step; undoing
        // them all gives back the file as it was, byte for byte, and redoing them the layer.
        const sim::LayoutLayer edited = window.document().scene().layout;
        QCOMPARE(undo.index() - startIndex, 7);
        for (int k = 0; k < 7; ++k)
            undo.undo();
        QCOMPARE(sceneYaml(window), original);
        QCOMPARE(list->count(), 0);
        QTRY_COMPARE(*shownFeet(window, 1), was1);
        for (int k = 0; k < 7; ++k)
            undo.redo();
        QVERIFY(window.document().scene().layout == edited);
    }

    // Trails (T) with a layout operation selected follow its agents along the edited path:
    // behind agent 1 where the layer moved it, none where it was recorded.
    void trailsShowTheEditedPath()
    {
        MainWindow window;
        const QByteArray withLayer =
            kLayoutScene + "layout:\n  - {op: translate, agents: {ids: [1]}, offset: [0, 3]}\n";
        QVERIFY(showWithYaml(window, m_dir, "trails.yaml", withLayer));
        QVERIFY(playUntilRecorded(window, 72));
        showLayoutDock(window);
        clickRow(window.layoutPanel().list(), 0);
        Viewport& viewport = window.viewport();
        QTest::keyClick(&viewport, Qt::Key_Q);  // the HUD off: nothing over the trail
        QTest::keyClick(&viewport, Qt::Key_T);
        QVERIFY(viewport.overlays().trails);
        QVERIFY(scrubWithKeys(window, 72));
        QTest::qWait(50);
        const QImage image = viewport.grabFramebuffer();
        const glm::vec3 walked = recordedFeet(window, 1, 48), now = recordedFeet(window, 1, 72);
        QVERIFY2(glm::distance(walked, now) > 0.9f, "it walked");
        const int edited = pixelsOf(window, image, {walked.x, walked.z + 3.0f}, 0.15f, palette::kTrail, 70);
        const int recorded = pixelsOf(window, image, {walked.x, walked.z}, 0.15f, palette::kTrail, 70);
        QVERIFY2(edited >= 3 && recorded == 0, qPrintable(QString("%1 trail pixels on the edited path, %2 on the "
                                                                  "recorded one").arg(edited).arg(recorded)));
    }

    void onlyTheClickedAgentTakesOneMemberOfAGroup()
    {
        MainWindow window;
        QVERIFY(openTake(window, m_dir, "clicked.yaml", kLayoutScene, 24, 24));
        showLayoutDock(window);
        // A click on a member of the group in the viewport selects the group and
        // focuses the member.
        const glm::vec3 feet = recordedFeet(window, 4, 24);
        clickToolButton(window, "select");
        clickOnGround(window, {feet.x, feet.z});
        QTRY_COMPARE(window.viewport().focusedAgent(), sim::AgentId(4));
        QCOMPARE(window.document().selection(), (Selection{{ItemKind::Group, 0}}));
        auto* only = window.layoutPanel().findChild<QCheckBox*>("layoutClickedOnly");
        QTest::mouseClick(only, Qt::LeftButton, Qt::NoModifier, QPoint(6, only->height() / 2));
        QVERIFY(only->isChecked());
        QVERIFY(addFromMenu(window, "Time offset"));
        const sim::LayoutOp& later = window.document().scene().layout.ops.at(0);
        QCOMPARE(later.agents.ids, (std::vector<std::uint32_t>{4}));
        QVERIFY(later.agents.groups.empty());
        QCOMPARE(later.frames, 24);  // one second at 24 fps
        // Shown 24 frames later: on frame 24 it stands where it stood on frame 0.
        QTRY_VERIFY(shownFeet(window, 4) && glm::length(*shownFeet(window, 4) - recordedFeet(window, 4, 0)) < 1e-4f);
    }

    // Layout Move: a drag moves the selected agent's recorded path by the drag (one step,
    // a new Translate); a second drag with that operation selected changes its offset;
    // Shift+drag turns a group about its centre on the shown frame; Escape takes a drag back.
    void layoutMoveDragsTheSelectedAgentsAsOneStep()
    {
        MainWindow window;
        QVERIFY(openTake(window, m_dir, "move.yaml", kLayoutScene, 48, 24));
        QUndoStack& undo = *window.document().undoStack();
        const int start = undo.index();
        selectInOutliner(window, {{ItemKind::Agent, 0}});
        QVERIFY(clickToolButton(window, "layoutMove"));
        const glm::vec3 was = recordedFeet(window, 1, 24);
        const glm::vec2 from(was.x, was.z);
        dragOnGround(window, {from, from + glm::vec2(3.0f, 2.0f)});
        QCOMPARE(window.document().scene().layout.ops.size(), std::size_t(1));
        const sim::LayoutOp& moved = window.document().scene().layout.ops[0];
        QCOMPARE(moved.kind, sim::LayoutKind::Translate);
        QCOMPARE(moved.agents.ids, (std::vector<std::uint32_t>{1}));
        QVERIFY2(glm::length(moved.offset - glm::vec2(3.0f, 2.0f)) < 0.05f,
                 qPrintable(QString("%1, %2").arg(moved.offset.x).arg(moved.offset.y)));
        QCOMPARE(undo.index() - start, 1);
        QCOMPARE(window.document().selection(), (Selection{{ItemKind::LayoutOp, 0}}));
        // The operation selected, its agent is ringed (and its trail drawn when trails are on).
        QCOMPARE(window.viewport().watchedAgents(), (std::vector<sim::AgentId>{1}));
        QTRY_VERIFY(shownFeet(window, 1) &&
                    glm::length(*shownFeet(window, 1) - (was + glm::vec3(moved.offset.x, 0, moved.offset.y))) < 1e-4f);

        // The operation selected: another drag adds a metre east to the same operation.
        const glm::vec2 at = from + moved.offset;
        dragOnGround(window, {at, at + glm::vec2(1.0f, 0.0f)});
        QCOMPARE(window.document().scene().layout.ops.size(), std::size_t(1));
        QVERIFY(glm::length(window.document().scene().layout.ops[0].offset - glm::vec2(4.0f, 2.0f)) < 0.08f);
        QCOMPARE(undo.index() - start, 2);

        // Shift+drag a quarter turn from +x to +z (clockwise seen from above) about the group's centre.
        selectInOutliner(window, {{ItemKind::Group, 0}});
        glm::vec2 centre(0.0f);
        for (const sim::AgentId id : {3u, 4u, 5u})
            centre += glm::vec2(recordedFeet(window, id, 24).x, recordedFeet(window, id, 24).z) / 3.0f;
        QWidget* view = &window.viewport();
        QTest::mousePress(view, Qt::LeftButton, Qt::ShiftModifier, pixelOf(window, centre + glm::vec2(4.0f, 0.0f)));
        for (int k = 1; k <= 12; ++k) {
            const float a = float(k) / 12.0f * 1.5707963f;
            QTest::mouseMove(view, pixelOf(window, centre + 4.0f * glm::vec2(std::cos(a), std::sin(a))));
        }
        QTest::mouseRelease(view, Qt::LeftButton, Qt::NoModifier, pixelOf(window, centre + glm::vec2(0.0f, 4.0f)));
        QCOMPARE(window.document().scene().layout.ops.size(), std::size_t(2));
        const sim::LayoutOp& turned = window.document().scene().layout.ops[1];
        QCOMPARE(turned.kind, sim::LayoutKind::Rotate);
        QCOMPARE(turned.agents.groups, (std::vector<std::string>{"crowd"}));
        QVERIFY(turned.pivot && glm::length(*turned.pivot - centre) < 1e-3f);
        QVERIFY2(std::abs(turned.angleDeg + 90.0f) < 2.0f, qPrintable(QString::number(turned.angleDeg)));  // clockwise
        // Each member stands where the quarter turn of its recorded place about the centre is.
        for (const sim::AgentId id : {3u, 4u, 5u}) {
            const glm::vec3 r = recordedFeet(window, id, 24);
            const glm::vec2 rel = glm::vec2(r.x, r.z) - centre;
            const glm::vec2 expected = centre + glm::vec2(-rel.y, rel.x);
            auto near = [&] {
                const std::optional<glm::vec3> now = shownFeet(window, id);
                return now && glm::length(glm::vec2(now->x, now->z) - expected) < 0.1f;
            };
            QTRY_VERIFY(near());
            const glm::vec3 now = *shownFeet(window, id);
            QVERIFY2(near(),
                     qPrintable(QString("agent %1 at %2, %3; expected %4, %5")
                                    .arg(id).arg(now.x).arg(now.z).arg(expected.x).arg(expected.y)));
        }
        QCOMPARE(undo.index() - start, 3);

        // Escape during a drag: nothing added, no step.
        selectInOutliner(window, {{ItemKind::Agent, 1}});
        QTest::mousePress(view, Qt::LeftButton, Qt::NoModifier, pixelOf(window, {0.0f, 0.0f}));
        QTest::mouseMove(view, pixelOf(window, {2.0f, 0.0f}));
        QTest::mouseMove(view, pixelOf(window, {3.0f, 0.0f}));
        QTest::keyClick(view, Qt::Key_Escape);
        QTest::mouseRelease(view, Qt::LeftButton, Qt::NoModifier, pixelOf(window, {3.0f, 0.0f}));
        QCOMPARE(window.document().scene().layout.ops.size(), std::size_t(2));
        QCOMPARE(undo.index() - start, 3);
    }

    // Duplicate from the Add menu: the viewport draws one more agent, a metre east of its
    // source; Swap's look and tint are set in Properties, numbered from 1 (0: untinted).
    void duplicateAndSwapFromThePanel()
    {
        MainWindow window;
        QVERIFY(openTake(window, m_dir, "copies.yaml", kLayoutScene, 24, 24));
        showLayoutDock(window);
        const std::size_t drawn = window.viewport().agentCount();
        selectInOutliner(window, {{ItemKind::Agent, 1}});
        QVERIFY(addFromMenu(window, "Duplicate"));
        QTRY_COMPARE(window.viewport().agentCount(), drawn + 1);
        const glm::vec3 source = recordedFeet(window, 2, 24);
        QTRY_VERIFY(shownFeet(window, sim::kFirstCopyId));
        QVERIFY(glm::length(*shownFeet(window, sim::kFirstCopyId) - (source + glm::vec3(1, 0, 0))) < 1e-4f);

        selectInOutliner(window, {{ItemKind::Agent, 0}});
        QVERIFY(addFromMenu(window, "Swap"));
        QCOMPARE(window.document().scene().layout.ops.back().kind, sim::LayoutKind::Swap);
        typeInto(window, field<QSpinBox>(window, "tint"), "0");
        QCOMPARE(window.document().scene().layout.ops.back().tint, -1);  // untinted
        typeInto(window, field<QSpinBox>(window, "look"), "2");
        QCOMPARE(window.document().scene().layout.ops.back().look, 1);
        QVERIFY(window.layoutPanel().list()->item(1)->text().contains("look 2, untinted"));
    }

    // Agent 1 moved onto agent 2's line by the file's layer: the HUD counts the overlaps;
    // Add > Resolve with nothing selected nudges agent 1 off agent 2, the HUD's count goes,
    // and agent 2 stays where the simulation put it.
    void resolveFromThePanelClearsTheCheck()
    {
        MainWindow window;
        const QByteArray withLayer =
            kLayoutScene + "layout:\n  - {op: translate, agents: {ids: [1]}, offset: [0, 8]}\n";
        QVERIFY(openTake(window, m_dir, "resolve.yaml", withLayer, 48, 0));
        showLayoutDock(window);
        QTRY_VERIFY(hudHasLayoutLine(window));
        window.document().setSelection({});
        QVERIFY(addFromMenu(window, "Resolve"));
        QCOMPARE(window.document().scene().layout.ops.back().kind, sim::LayoutKind::Resolve);
        QTRY_VERIFY(!hudHasLayoutLine(window));
        QVERIFY(window.layoutCheck().last().overlaps.empty());
        QTRY_COMPARE(*shownFeet(window, 2), recordedFeet(window, 2, 0));
        const glm::vec3 one = *shownFeet(window, 1), two = *shownFeet(window, 2);
        QVERIFY2(std::hypot(one.x - two.x, one.z - two.z) >= 0.6f - 0.05f,
                 qPrintable(QString::number(std::hypot(one.x - two.x, one.z - two.z))));
        QVERIFY(window.layoutPanel().list()->item(1)->text().contains("every edited agent"));
    }

    // The retime drag: with the clicked member's time offset selected, the scrub bar marks
    // it, and a Shift+drag of 12 frames on the bar makes it 36 frames later, as one step;
    // the viewport shows the member where it stood 36 frames earlier.
    void shiftDragOnTheTimelineRetimes()
    {
        MainWindow window;
        const QByteArray withLayer =
            kLayoutScene + "layout:\n  - {op: time_offset, agents: {ids: [1]}, later: 24}\n";
        QVERIFY(openTake(window, m_dir, "retime.yaml", withLayer, 60, 48));
        showLayoutDock(window);
        TimelineRuler* ruler = window.timeline().scrubBar();
        QVERIFY(!ruler->retime());
        clickRow(window.layoutPanel().list(), 0);
        QCOMPARE(window.document().selection(), (Selection{{ItemKind::LayoutOp, 0}}));
        QVERIFY(ruler->retime() && ruler->retime()->from == 0 && ruler->retime()->frames == 24);
        QUndoStack& undo = *window.document().undoStack();
        const int start = undo.index();
        const int y = ruler->height() / 2;
        QTest::mousePress(ruler, Qt::LeftButton, Qt::ShiftModifier, QPoint(ruler->xOfFrame(10), y));
        for (int f = 11; f <= 22; ++f)
            QTest::mouseMove(ruler, QPoint(ruler->xOfFrame(f), y));
        QTest::mouseRelease(ruler, Qt::LeftButton, Qt::ShiftModifier, QPoint(ruler->xOfFrame(22), y));
        QCOMPARE(window.document().scene().layout.ops[0].frames, 36);
        QCOMPARE(undo.index() - start, 1);
        QCOMPARE(ruler->retime()->frames, 36);
        QCOMPARE(window.simulation().currentFrame(), std::size_t(48));  // the drag did not scrub
        QTRY_VERIFY(shownFeet(window, 1) && glm::length(*shownFeet(window, 1) - recordedFeet(window, 1, 12)) < 1e-4f);
        undo.undo();
        QCOMPARE(window.document().scene().layout.ops[0].frames, 24);
    }

    // Ctrl+drag with Layout Move draws a lasso round the group's three walkers where frame
    // 24 has them: a Translate of the agents inside that lasso on frame 24 (exactly those
    // three), which a plain drag then moves.
    void aLassoOnTheShownFrameSelectsTheAgentsInside()
    {
        MainWindow window;
        QVERIFY(openTake(window, m_dir, "lasso.yaml", kLayoutScene, 30, 24));
        QVERIFY(clickToolButton(window, "layoutMove"));
        glm::vec2 lo(1e9f), hi(-1e9f);
        for (const sim::AgentId id : {3u, 4u, 5u}) {
            const glm::vec3 p = recordedFeet(window, id, 24);
            lo = glm::min(lo, glm::vec2(p.x, p.z));
            hi = glm::max(hi, glm::vec2(p.x, p.z));
        }
        lo -= glm::vec2(1.0f);
        hi += glm::vec2(1.0f);
        QWidget* view = &window.viewport();
        const std::vector<glm::vec2> corners{lo, {hi.x, lo.y}, hi, {lo.x, hi.y}, lo + glm::vec2(0.0f, 0.3f)};
        QTest::mousePress(view, Qt::LeftButton, Qt::ControlModifier, pixelOf(window, corners[0]));
        for (std::size_t c = 1; c < corners.size(); ++c)
            for (int k = 1; k <= 10; ++k)
                QTest::mouseMove(view, pixelOf(window, corners[c - 1] + (corners[c] - corners[c - 1]) * (k / 10.0f)));
        QTest::mouseRelease(view, Qt::LeftButton, Qt::ControlModifier, pixelOf(window, corners.back()));
        QCOMPARE(window.document().scene().layout.ops.size(), std::size_t(1));
        const sim::LayoutOp lassoed = window.document().scene().layout.ops[0];
        QCOMPARE(lassoed.agents.lassoFrame, std::size_t(24));
        QVERIFY(lassoed.agents.lasso.size() >= 8);
        QCOMPARE(window.document().selection(), (Selection{{ItemKind::LayoutOp, 0}}));
        const sim::Scene& scene = window.document().scene();
        const sim::LayoutSelection chosen = sim::selectLayoutAgents(scene, scene.layout, window.simulation().cache());
        std::vector<sim::AgentId> ids;
        for (const std::size_t i : chosen.agents[0])
            ids.push_back(window.simulation().cache().agents()[i].id);
        std::sort(ids.begin(), ids.end());
        QCOMPARE(ids, (std::vector<sim::AgentId>{3, 4, 5}));
        // A plain drag now moves them (the lassoed operation is selected).
        const glm::vec3 was = recordedFeet(window, 4, 24);
        dragOnGround(window, {{was.x, was.z}, {was.x + 2.0f, was.z}});
        QVERIFY(glm::length(window.document().scene().layout.ops[0].offset - glm::vec2(2.0f, 0.0f)) < 0.05f);
    }

    // A shot too large to check in a moment (here: a limit of 10 agent-frames) is not
    // checked by itself: the panel says so, and Check runs it.
    void aLargeShotIsCheckedWhenAsked()
    {
        MainWindow window;
        window.layoutCheck().setAutomaticLimit(10);
        const QByteArray withLayer =
            kLayoutScene + "layout:\n  - {op: translate, agents: {ids: [1]}, offset: [0, 8]}\n";
        QVERIFY(showWithYaml(window, m_dir, "large.yaml", withLayer));
        QVERIFY(playUntilRecorded(window, 24));
        showLayoutDock(window);
        auto* label = window.layoutPanel().findChild<QLabel*>("layoutCheckLabel");
        QTRY_VERIFY2(label->text().contains("press Check"), qPrintable(label->text()));
        QVERIFY(!hudHasLayoutLine(window));
        QVERIFY(window.layoutCheck().last().overlaps.empty());
        QTest::mouseClick(window.layoutPanel().findChild<QPushButton*>("layoutCheckButton"), Qt::LeftButton);
        QVERIFY(!window.layoutCheck().last().overlaps.empty());
        QVERIFY(hudHasLayoutLine(window));
        QVERIFY2(label->text().startsWith("The layout edits make"), qPrintable(label->text()));
    }

    void renamingAGroupOrTypeKeepsTheOperationsOnIt()
    {
        MainWindow window;
        const QByteArray withLayer =
            kLayoutScene + "layout:\n  - {op: delete, agents: {groups: [crowd], types: [walker]}}\n";
        QVERIFY(showWithYaml(window, m_dir, "rename.yaml", withLayer));
        selectInOutliner(window, {{ItemKind::Group, 0}});
        typeInto(window, field<QLineEdit>(window, "name"), "parade");
        QCOMPARE(window.document().scene().groups[0].name, std::string("parade"));
        QCOMPARE(window.document().scene().layout.ops[0].agents.groups, (std::vector<std::string>{"parade"}));
        selectInOutliner(window, {{ItemKind::AgentType, 0}});
        typeInto(window, field<QLineEdit>(window, "name"), "stroller");
        QCOMPARE(window.document().scene().layout.ops[0].agents.types, (std::vector<std::string>{"stroller"}));
        // A type an operation still selects is not deleted from under it.
        selectInOutliner(window, {{ItemKind::AgentType, 0}});
        QTest::keyClick(&window.outliner(), Qt::Key_Delete);
        QCOMPARE(window.document().scene().agentTypes.size(), std::size_t(1));
        QVERIFY2(lastMessage(window).startsWith("Nothing deleted"), qPrintable(lastMessage(window)));
        const std::vector<NameUse> uses = nameUses(window.document().scene(), ItemKind::AgentType, "stroller");
        QVERIFY(std::any_of(uses.begin(), uses.end(), [](const NameUse& use) {
            return use.user == SceneItem{ItemKind::LayoutOp, 0} && use.who == "layout operation Delete 1";
        }));
    }
};

THRONG_REGISTER_TEST(TestLayoutPanelUi)
#include "TestLayoutPanelUi.moc"
