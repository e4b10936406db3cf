// The viewport that explains the crowd, driven like a user: the HUD counts what the shown
// frame holds (recounted here from the trajectories), Colour Agents By paints agents by
// group, goal and speed with a legend that names them, trails follow the selected agent
// and no other, and the steering overlay shows the selected agent's forces, neighbours
// and feelers on the shown frame, paused or playing.
#include "EditorTestSupport.h"
#include "TestRegistry.h"

#include "editor/simulation/SimulationController.h"
#include "editor/viewport/AgentColours.h"
#include "editor/viewport/DensityHeatmap.h"
#include "editor/viewport/FieldArrows.h"
#include "editor/viewport/SteeringOverlay.h"
#include "editor/viewport/Viewport.h"
#include "editor/viewport/ViewportPalette.h"

#include <glm/geometric.hpp>

#include <QApplication>
#include <QMenu>
#include <QRegularExpression>
#include <QSettings>
#include <QSpinBox>
#include <QTest>

#include <map>

using namespace throng;
using namespace throng::editor;
using namespace throng::editor::test;

namespace {

// Runners 1 and 2 leave through the door at once; runner 3 has nowhere to go. The close
// walkers reach their goal within two seconds, the far ones not before ten.
const QByteArray kScene = R"(throng: 1
settings: {fps: 24, duration: 20, seed: 3, bounds: {min: [-20, -20], max: [20, 20]}}
agent_types:
  - {name: walker, radius: 0.3, max_speed: 1.4, max_force: 3, variation: {speed: [1, 1]}}
  - {name: runner, radius: 0.3, max_speed: 3, max_force: 6, variation: {speed: [1, 1]}}
goals:
  - {name: near, position: [0, 0], radius: 2}
  - {name: door, position: [10, 8], radius: 1, exit: true}
agents:
  - {id: 1, type: runner, position: [5, 0, 8], goal: door}
  - {id: 2, type: runner, position: [4, 0, 6], goal: door}
  - {id: 3, type: runner, position: [-15, 0, 15]}
groups:
  - {name: close, type: walker, count: 6, rect: {min: [-4, -1], max: [-3, 1]}, goal: near}
  - {name: far, type: walker, count: 10, rect: {min: [-18, -18], max: [-15, -15]}, goal: near}
)";

// One walker (id 1) heads east past a post and a wall, through two others.
const QByteArray kSteeringScene = R"(throng: 1
settings: {fps: 24, duration: 20, seed: 3, bounds: {min: [-20, -20], max: [20, 20]}}
agent_types:
  - {name: walker, radius: 0.3, max_speed: 1.4, max_force: 3, perception: 4, variation: {speed: [1, 1]}}
goals:
  - {name: east, position: [15, 0], radius: 1}
walls:
  - {points: [[4, -6], [4, -1.2]]}
  - {points: [[4, 1.2], [4, 6]]}
obstacles:
  - {shape: circle, center: [-2, 3], radius: 0.5}
agents:
  - {id: 1, type: walker, position: [-8, 0, 0], goal: east}
  - {id: 2, type: walker, position: [-6.5, 0, 0.8], goal: east}
  - {id: 3, type: walker, position: [-6.5, 0, -0.8], goal: east}
)";

// Two walkers east on lines 6 m apart.
const QByteArray kTrailScene = R"(throng: 1
settings: {fps: 24, duration: 20, seed: 3, bounds: {min: [-20, -20], max: [20, 20]}}
agent_types: [{name: walker, radius: 0.3, max_speed: 1.4, max_force: 3, variation: {speed: [1, 1]}}]
goals: [{name: a, position: [15, -3], radius: 1}, {name: b, position: [15, 3], radius: 1}]
agents:
  - {id: 1, type: walker, position: [-8, 0, -3], goal: a}
  - {id: 2, type: walker, position: [-8, 0, 3], goal: b}
)";

// A stroke east across the middle, two goals, a packed group of 36 in 3 x 3 m and one
// walker on its own.
const QByteArray kFieldScene = R"(throng: 1
settings: {fps: 24, duration: 20, seed: 3, bounds: {min: [-20, -20], max: [20, 20]}}
agent_types: [{name: walker, radius: 0.25, max_speed: 1.4, max_force: 3, variation: {speed: [1, 1]}}]
goals: [{name: west, position: [-16, 10], radius: 1}, {name: north, position: [10, -16], radius: 1}]
walls: [{points: [[0, 4], [0, 16]]}]
flow_strokes: [{points: [[-15, 0], [15, 0]], width: 4}]
agents:
  - {id: 1, type: walker, position: [12, 0, 12]}
groups:
  - {name: packed, type: walker, count: 36, rect: {min: [-12, -12], max: [-9, -9]}}
)";

// Shows frame `frame` by typing it into the timeline's frame field.
void goToFrame(MainWindow& window, std::size_t frame)
{
    auto* field = window.findChild<QSpinBox*>("frameField");
    QVERIFY(field);
    typeInto(field, QString::number(frame));
    QTRY_COMPARE_WITH_TIMEOUT(window.viewport().frameIndex(), frame, 30000);
}

// The HUD's figure after `label` on one of its lines ("Agents 17" -> 17); -1 when absent.
long hudNumber(const Viewport& viewport, const QString& label)
{
    const QRegularExpression pattern("(?:^|\\s)" + QRegularExpression::escape(label) + "\\s+([0-9\\x{2009}]+)");
    for (const QString& line : viewport.hud().lines())
        if (const auto m = pattern.match(line); m.hasMatch())
            return m.captured(1).remove(QChar(0x2009)).toLong();
    return -1;
}

// Opens View > submenu > item with the mouse, as a user does.
bool chooseInViewMenu(MainWindow& window, const QString& submenu, const QString& item)
{
    QTest::keyClick(&window, Qt::Key_V, Qt::AltModifier);
    if (!QTest::qWaitFor([] { return qobject_cast<QMenu*>(QApplication::activePopupWidget()) != nullptr; }, 3000))
        return false;
    QMenu* viewMenu = qobject_cast<QMenu*>(QApplication::activePopupWidget());
    if (!clickPopupItem(submenu))
        return false;
    if (!QTest::qWaitFor([&] { return QApplication::activePopupWidget() && QApplication::activePopupWidget() != viewMenu; },
                         3000))
        return false;
    return clickPopupItem(item);
}

std::size_t cacheIndex(MainWindow& window, sim::AgentId id)
{
    const auto agents = window.simulation().cache().agents();
    for (std::size_t i = 0; i < agents.size(); ++i)
        if (agents[i].id == id)
            return i;
    return agents.size();
}

}  // namespace

class TestViewportExplainsUi : public QObject {
    Q_OBJECT

private:
    QTemporaryDir m_dir;

private slots:
    void init()
    {
        // Each test starts from the defaults, whatever an earlier one chose.
        QSettings().remove("viewport");
    }

    void hudCountsWhatTheShownFrameHolds()
    {
        MainWindow window;
        QVERIFY(showWithYaml(window, m_dir, "hud.yaml", kScene));
        Viewport& viewport = window.viewport();
        QVERIFY(viewport.hud().isVisible());
        goToFrame(window, 96);
        QCOMPARE(hudNumber(viewport, "Frame"), 96L);
        QVERIFY2(viewport.hud().lines().front().contains("00:00:04:00"), qPrintable(viewport.hud().lines().front()));

        // Recount from the trajectories: who has been inside its goal's disk by now.
        const sim::FrameCache& cache = window.simulation().cache();
        const sim::Scene& scene = window.document().scene();
        const std::map<sim::AgentId, std::pair<glm::vec2, float>> goalOf = [&] {
            std::map<sim::AgentId, std::pair<glm::vec2, float>> goals;
            goals[1] = goals[2] = {scene.goals[1].position, scene.goals[1].radiusM};
            for (sim::AgentId id = 4; id < 20; ++id)
                goals[id] = {scene.goals[0].position, scene.goals[0].radiusM};
            return goals;
        }();
        long arrived = 0, out = 0, walkers = 0, runners = 0;
        for (std::size_t a = 0; a < cache.agentCount(); ++a) {
            const sim::AgentId id = cache.agents()[a].id;
            bool reached = false;
            if (const auto g = goalOf.find(id); g != goalOf.end())
                for (std::size_t f = 0; f <= 96 && !reached; ++f) {
                    const glm::vec3 p = cache.at(f, a).position;
                    reached = glm::distance(glm::vec2(p.x, p.z), g->second.first) <= g->second.second + 0.05f;
                }
            arrived += reached;
            const bool exited = reached && (id == 1 || id == 2);
            out += exited;
            if (!exited)
                (cache.agents()[a].typeIndex == 0 ? walkers : runners) += 1;
        }
        QVERIFY2(arrived >= 8, "the close walkers and both runners arrive within four seconds");
        QCOMPARE(out, 2L);
        QCOMPARE(hudNumber(viewport, "Arrived"), arrived);
        QCOMPARE(hudNumber(viewport, "Out"), out);
        QCOMPARE(hudNumber(viewport, "Agents"), walkers + runners);
        QCOMPARE(hudNumber(viewport, "walker"), walkers);
        QCOMPARE(hudNumber(viewport, "runner"), runners);
        QCOMPARE(walkers, 16L);
        QCOMPARE(runners, 1L);

        // Back at frame 0 nobody has arrived yet.
        goToFrame(window, 0);
        QCOMPARE(hudNumber(viewport, "Arrived"), 0L);
        QCOMPARE(hudNumber(viewport, "Agents"), 19L);

        // Shift+H hides it and brings it back; the choice is remembered.
        QTest::keyClick(&viewport, Qt::Key_H, Qt::ShiftModifier);
        QVERIFY(!viewport.hud().isVisible());
        QCOMPARE(QSettings().value("viewport/hud").toBool(), false);
        QTest::keyClick(&viewport, Qt::Key_H, Qt::ShiftModifier);
        QVERIFY(viewport.hud().isVisible());
    }

    void colourByGroupGoalAndSpeed()
    {
        MainWindow window;
        QVERIFY(showWithYaml(window, m_dir, "colour.yaml", kScene));
        Viewport& viewport = window.viewport();
        QCOMPARE(viewport.colourBy(), ColourBy::Tint);
        QVERIFY(chooseInViewMenu(window, "Colour Agents By", "Group"));
        QTRY_COMPARE(viewport.colourBy(), ColourBy::Group);
        QTest::qWait(50);
        QImage image = viewport.grabFramebuffer();
        const sim::FrameCache& cache = window.simulation().cache();
        auto colourAt = [&](sim::AgentId id) {
            const glm::vec3 p = cache.at(viewport.frameIndex(), cacheIndex(window, id)).position;
            // Behind the body's middle: the nose is drawn in front.
            const float heading = cache.at(viewport.frameIndex(), cacheIndex(window, id)).headingRad;
            const glm::vec3 back = p - 0.12f * glm::vec3(std::cos(heading), 0.0f, -std::sin(heading));
            return pixelAt(image, viewport, viewport.worldToPixel(back));
        };
        // Group 'close' takes the first category colour, 'far' the second; the placed
        // runners belong to no group.
        const sim::AgentId closeMember = 4, farMember = 10, runner = 3;
        QVERIFY2(sameColour(colourAt(closeMember), glm::vec4(AgentColours::categoryColour(0), 1.0f), 10),
                 qPrintable(describe(colourAt(closeMember))));
        QVERIFY2(sameColour(colourAt(farMember), glm::vec4(AgentColours::categoryColour(1), 1.0f), 10),
                 qPrintable(describe(colourAt(farMember))));
        QVERIFY2(sameColour(colourAt(runner), glm::vec4(AgentColours::kNoCategory, 1.0f), 10),
                 qPrintable(describe(colourAt(runner))));
        QStringList lines = viewport.hud().lines();
        QVERIFY2(lines.contains("Colour by Group") && lines.contains("  \u25A0 close") && lines.contains("  \u25A0 far") &&
                     lines.contains("  \u25A0 none"),
                 qPrintable(lines.join('\n')));

        // Shift+C goes on to the goal: the runners' door and the walkers' goal differ.
        QTest::keyClick(&viewport, Qt::Key_C, Qt::ShiftModifier);
        QCOMPARE(viewport.colourBy(), ColourBy::Goal);
        QTest::qWait(50);
        image = viewport.grabFramebuffer();
        // Placed agents come first: the runners' door is the first goal given, then the
        // groups' goal.
        QVERIFY2(sameColour(colourAt(1), glm::vec4(AgentColours::categoryColour(0), 1.0f), 10), qPrintable(describe(colourAt(1))));
        QVERIFY(sameColour(colourAt(closeMember), glm::vec4(AgentColours::categoryColour(1), 1.0f), 10));
        QVERIFY(sameColour(colourAt(farMember), glm::vec4(AgentColours::categoryColour(1), 1.0f), 10));
        QVERIFY(sameColour(colourAt(runner), glm::vec4(AgentColours::kNoCategory, 1.0f), 10));
        lines = viewport.hud().lines();
        QVERIFY2(lines.indexOf("  \u25A0 door") >= 0 && lines.indexOf("  \u25A0 door") < lines.indexOf("  \u25A0 near"),
                 qPrintable(lines.join('\n')));

        // By speed, while they walk: the one with nowhere to go is blue, walkers at full
        // speed red.
        QVERIFY(chooseInViewMenu(window, "Colour Agents By", "Speed"));
        QTRY_COMPARE(viewport.colourBy(), ColourBy::Speed);
        goToFrame(window, 48);
        QTest::qWait(50);
        image = viewport.grabFramebuffer();
        const float farSpeed = cache.at(48, cacheIndex(window, farMember)).speed;
        QVERIFY2(farSpeed > 1.3f, qPrintable(QString::number(double(farSpeed))));
        QVERIFY2(sameColour(colourAt(runner), glm::vec4(AgentColours::gradientColour(0.0f), 1.0f), 12),
                 qPrintable(describe(colourAt(runner))));
        QVERIFY2(sameColour(colourAt(farMember), glm::vec4(AgentColours::gradientColour(farSpeed / 1.4f), 1.0f), 12),
                 qPrintable(describe(colourAt(farMember)) + " expected " +
                            describe(glm::vec4(AgentColours::gradientColour(farSpeed / 1.4f), 1.0f))));
        QCOMPARE(QSettings().value("viewport/colourBy").toString(), QString("speed"));
    }

    void fieldsAndDensityShowOnTheGround()
    {
        MainWindow window;
        QVERIFY(showWithYaml(window, m_dir, "fields.yaml", kFieldScene));
        Viewport& viewport = window.viewport();
        auto countNear = [&](const QImage& image, glm::vec2 at, float r, glm::vec4 colour) {
            return pixelsOf(window, image, at, r, colour, 30);
        };
        // The sketched field: arrows along the stroke besides the set's own (the stroke
        // and its band's arrows are drawn in violet too).
        QImage image = viewport.grabFramebuffer();
        int before = 0;
        for (float x : {-10.0f, -5.0f, 5.0f, 10.0f})
            before += countNear(image, {x, 1.0f}, 1.0f, FieldArrows::kSketchColour);
        QTest::keyClick(&viewport, Qt::Key_F, Qt::ShiftModifier);
        QVERIFY(viewport.overlays().sketchField);
        QTest::qWait(50);
        image = viewport.grabFramebuffer();
        int after = 0;
        for (float x : {-10.0f, -5.0f, 5.0f, 10.0f})
            after += countNear(image, {x, 1.0f}, 1.0f, FieldArrows::kSketchColour);
        QVERIFY2(after >= before + 12, qPrintable(QString("%1 violet pixels before, %2 after").arg(before).arg(after)));
        QVERIFY(viewport.hud().lines().contains("Sketched field: 1 strokes"));
        QTest::keyClick(&viewport, Qt::Key_F, Qt::ShiftModifier);

        // The goal's flow field: the first goal's until another is selected.
        QTest::keyClick(&viewport, Qt::Key_G, Qt::ShiftModifier);
        QVERIFY(viewport.overlays().goalField);
        QVERIFY(viewport.hud().lines().contains("Flow field to goal 'west'"));
        QTest::qWait(50);
        image = viewport.grabFramebuffer();
        QVERIFY2(countNear(image, {8.0f, 8.0f}, 1.0f, FieldArrows::kGoalColour) >= 3, "arrows round the wall");
        selectInOutliner(window, {{ItemKind::Goal, 1}});
        QTRY_VERIFY(viewport.hud().lines().contains("Flow field to goal 'north'"));
        QTest::keyClick(&viewport, Qt::Key_G, Qt::ShiftModifier);
        QVERIFY(!viewport.overlays().goalField);

        // The density map: coloured under the packed group, plain ground far from it.
        QTest::keyClick(&viewport, Qt::Key_M);
        QVERIFY(viewport.overlays().density);
        QTest::qWait(50);
        image = viewport.grabFramebuffer();
        const QRgb empty = pixelAt(image, viewport, viewport.worldToPixel({5.5f, 0.0f, -12.5f}));
        QVERIFY2(sameColour(empty, palette::kGround, 6), qPrintable(describe(empty)));
        // Independent recount: agents of the frame within 1 m of the group's middle, per m².
        const sim::FrameCache& cache = window.simulation().cache();
        int within = 0;
        for (const sim::AgentFrame& f : cache.frame(viewport.frameIndex()))
            within += glm::distance(glm::vec2(f.position.x, f.position.z), glm::vec2(-10.5f, -10.5f)) <= 1.0f;
        const double counted = within / 3.14159;
        const QString peakLine = viewport.hud().lines().filter("Density map").value(0);
        const QRegularExpression peak("peak ([0-9.]+)");
        QVERIFY2(peak.match(peakLine).hasMatch(), qPrintable(peakLine));
        const double shown = peak.match(peakLine).captured(1).toDouble();
        QVERIFY2(counted > 2.0 && shown > 0.6 * counted && shown < 1.6 * counted,
                 qPrintable(QString("peak %1 in the HUD, %2 per m² counted").arg(shown).arg(counted)));
        // Beside the packed walkers the ground takes the map's colour; without it, plain.
        const glm::vec2 beside(-8.6f, -10.5f);
        const int plainWithMap = countNear(image, beside, 0.25f, palette::kGround);
        QTest::keyClick(&viewport, Qt::Key_M);
        QVERIFY(!viewport.overlays().density);
        QTest::qWait(50);
        image = viewport.grabFramebuffer();
        const int plainWithout = countNear(image, beside, 0.25f, palette::kGround);
        QVERIFY2(plainWithMap * 4 < plainWithout && plainWithout >= 10,
                 qPrintable(QString("%1 plain ground pixels beside the crowd with the map, %2 without")
                                .arg(plainWithMap)
                                .arg(plainWithout)));

        // Colour by density: the packed walkers warmer than the one alone.
        QVERIFY(chooseInViewMenu(window, "Colour Agents By", "Density"));
        QTRY_COMPARE(viewport.colourBy(), ColourBy::Density);
        QTest::qWait(50);
        image = viewport.grabFramebuffer();
        const glm::vec3 lone = cache.at(viewport.frameIndex(), cacheIndex(window, 1)).position;
        const QRgb alone = pixelAt(image, viewport, viewport.worldToPixel(lone - glm::vec3(0.1f, 0.0f, 0.0f)));
        DensityHeatmap recount;
        recount.build(cache.frame(viewport.frameIndex()), {-20.0f, -20.0f}, {20.0f, 20.0f});
        const glm::vec4 loneColour(glm::vec3(DensityHeatmap::colourFor(recount.densityAt({lone.x, lone.z}))), 1.0f);
        QVERIFY2(sameColour(alone, loneColour, 12), qPrintable(describe(alone) + " expected " + describe(loneColour)));
        QVERIFY(recount.densityAt({lone.x, lone.z}) < 1.0f);
        QVERIFY(viewport.hud().lines().contains("Colour by Density (agents per m²)"));
    }

    void trailsFollowTheSelectedAgentOnly()
    {
        MainWindow window;
        QVERIFY(showWithYaml(window, m_dir, "trails.yaml", kTrailScene));
        Viewport& viewport = window.viewport();
        QTest::keyClick(&viewport, Qt::Key_Q);
        QTest::mouseClick(&viewport, Qt::LeftButton, Qt::NoModifier, viewport.worldToPixel({-8.0f, 0.0f, -3.0f}).toPoint());
        QCOMPARE(viewport.focusedAgent(), sim::AgentId(1));
        QTest::keyClick(&viewport, Qt::Key_T);
        QVERIFY(viewport.overlays().trails);
        goToFrame(window, 72);
        QTest::qWait(50);
        const QImage image = viewport.grabFramebuffer();
        const sim::FrameCache& cache = window.simulation().cache();
        // Where agent 1 was a second ago, and agent 2 (not selected).
        const glm::vec3 walked1 = cache.at(48, cacheIndex(window, 1)).position;
        const glm::vec3 walked2 = cache.at(48, cacheIndex(window, 2)).position;
        const glm::vec3 now1 = cache.at(72, cacheIndex(window, 1)).position;
        QVERIFY2(glm::distance(walked1, now1) > 1.0f, "it walked");
        const int onTrail = pixelsOf(window, image, {walked1.x, walked1.z}, 0.15f, palette::kTrail, 70);
        const int offTrail = pixelsOf(window, image, {walked2.x, walked2.z}, 0.15f, palette::kTrail, 70);
        QVERIFY2(onTrail >= 3 && offTrail == 0, qPrintable(QString("%1 trail pixels behind the selected agent, %2 behind the other")
                                                              .arg(onTrail)
                                                              .arg(offTrail)));
        // T again: gone.
        QTest::keyClick(&viewport, Qt::Key_T);
        QTest::qWait(50);
        const QImage without = viewport.grabFramebuffer();
        QCOMPARE(pixelsOf(window, without, {walked1.x, walked1.z}, 0.15f, palette::kTrail, 70), 0);
    }

    void steeringShowsTheSelectedAgentsForces()
    {
        MainWindow window;
        QVERIFY(showWithYaml(window, m_dir, "steering.yaml", kSteeringScene));
        Viewport& viewport = window.viewport();
        SimulationController& sim = window.simulation();
        // Frames computed before anyone is watched carry nothing.
        goToFrame(window, 40);
        QVERIFY(sim.steering(40).empty());

        QTest::keyClick(&viewport, Qt::Key_Q);
        const glm::vec3 at40 = sim.cache().at(40, cacheIndex(window, 1)).position;
        QTest::mouseClick(&viewport, Qt::LeftButton, Qt::NoModifier, viewport.worldToPixel(at40).toPoint());
        QCOMPARE(viewport.focusedAgent(), sim::AgentId(1));
        QTest::keyClick(&viewport, Qt::Key_D);
        QVERIFY(viewport.overlays().steering);
        const std::size_t recordedAtWatch = sim.recordedFrames();
        // The shown frame is computed again in the background for the watched agent.
        QTRY_VERIFY_WITH_TIMEOUT(!sim.steering(40).empty(), 20000);
        const sim::AgentDebug a = sim.steering(40).front();
        QCOMPARE(a.id, sim::AgentId(1));
        // What was published is the recorded frame's state.
        QVERIFY(glm::distance(a.position, at40) < 1e-4f);
        QVERIFY(std::abs(glm::length(a.velocity) - sim.cache().at(40, cacheIndex(window, 1)).speed) < 1e-3f);
        // Its two companions walk beside it, within its perception.
        QCOMPARE(a.neighbours.size(), std::size_t(2));
        QVERIFY(!a.feelers.empty());
        QVERIFY(a.hasTarget);
        bool seeks = false;
        for (const sim::AgentDebug::Force& f : a.forces)
            seeks = seeks || (f.behaviour == sim::Behaviour::Seek && glm::length(f.force) > 0.0f) ||
                    (f.behaviour == sim::Behaviour::Arrival && f.force.x > 0.0f);
        QVERIFY2(seeks, "it steers east, to its goal");

        // The HUD lists its forces, strongest first, in the arrows' colours.
        QTRY_VERIFY(viewport.hud().lines().join('\n').contains("Agent 1:"));
        const QStringList lines = viewport.hud().lines();
        const QString title = lines.filter("Agent 1:").front();
        QVERIFY2(title.contains("2 neighbours"), qPrintable(title));
        // And draws them: its velocity arrow reaches a second ahead, its feelers orange.
        QTest::qWait(50);
        const QImage image = viewport.grabFramebuffer();
        const glm::vec2 mid = glm::vec2(a.position.x, a.position.z) +
                              0.7f * SteeringOverlay::kMetresPerMps * glm::vec2(a.velocity.x, a.velocity.z);
        QVERIFY2(pixelsOf(window, image, mid, 0.12f, palette::kVelocity, 40) >= 2, "the velocity arrow");
        const sim::AgentDebug::Feeler side = a.feelers[1];
        const glm::vec3 onFeeler = 0.5f * (side.from + side.to);
        QVERIFY2(pixelsOf(window, image, {onFeeler.x, onFeeler.z}, 0.1f, palette::kFeeler, 40) >= 1, "a side feeler");
        // Off, nothing of it is drawn.
        QTest::keyClick(&viewport, Qt::Key_D);
        QTest::qWait(50);
        const QImage off = viewport.grabFramebuffer();
        QCOMPARE(pixelsOf(window, off, mid, 0.12f, palette::kVelocity, 40), 0);
        QTest::keyClick(&viewport, Qt::Key_D);

        // Playing on, every frame computed from then on carries its annotations (the
        // runner may have had a burst of up to eight under way when it was told).
        const std::size_t from = recordedAtWatch + 8;
        QVERIFY(playToFrame(window, from + 24));
        const std::size_t last = sim.recordedFrames() - 1;
        QVERIFY(last >= from + 24);
        for (std::size_t f = from; f <= last; ++f)
            QVERIFY2(sim.steering(f).size() == 1, qPrintable(QString("frame %1").arg(f)));
        // Deselected (a click on empty ground), the agent's steering goes from the frame
        // recorded for it: the HUD asks for an agent and no arrow of it is drawn. (Before,
        // a frame recorded while it was watched kept showing it.) A frame where it walks.
        const std::size_t walking = from + 12;
        goToFrame(window, walking);
        QTRY_VERIFY(viewport.hud().lines().join('\n').contains("Agent 1:"));
        const sim::AgentDebug watched = sim.steering(walking).front();
        QVERIFY(glm::length(watched.velocity) > 0.5f);
        const glm::vec2 ahead =
            glm::vec2(watched.position.x, watched.position.z) +
            0.7f * SteeringOverlay::kMetresPerMps * glm::vec2(watched.velocity.x, watched.velocity.z);
        QTest::qWait(50);
        QVERIFY2(pixelsOf(window, viewport.grabFramebuffer(), ahead, 0.12f, palette::kVelocity, 40) >= 2,
                 "the velocity arrow while selected");
        QTest::mouseClick(&viewport, Qt::LeftButton, Qt::NoModifier, viewport.worldToPixel({-17, 0, -17}).toPoint());
        QVERIFY(window.document().selection().empty());
        QCOMPARE(viewport.focusedAgent(), sim::AgentId(0));
        QVERIFY(sim.steering(walking).empty());
        QTRY_VERIFY(viewport.hud().lines().join('\n').contains("select an agent to see its steering"));
        QVERIFY(!viewport.hud().lines().join('\n').contains("Agent 1:"));
        QTest::qWait(50);
        QCOMPARE(pixelsOf(window, viewport.grabFramebuffer(), ahead, 0.12f, palette::kVelocity, 40), 0);
        // Off: nobody is watched any more.
        QTest::keyClick(&viewport, Qt::Key_D);
        QVERIFY(sim.runner().watchedAgents().empty());
    }
};

THRONG_REGISTER_TEST(TestViewportExplainsUi)
#include "TestViewportExplainsUi.moc"
