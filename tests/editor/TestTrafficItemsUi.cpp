// Crosswalks and vehicles as items, driven like a user: pick them in the viewport or the
// outliner, edit them in the properties panel (a crosswalk's ends and width, a vehicle's
// type, lane, start distance and speed), see the outliner and the simulation follow, undo
// back to the same saved bytes; a rename carries the stop lines; Delete refuses a
// crosswalk a light still stops at; a message about "vehicles[1].lane" selects the car; the
// crossroads' knobs (car following per lane, type and scene, delays, margins) are set there.
#include "EditorTestSupport.h"
#include "EditorUiDriver.h"
#include "PanelTestScene.h"
#include "TestRegistry.h"

#include "editor/MessagesPanel.h"
#include "editor/panels/OutlinerPanel.h"
#include "editor/simulation/SimulationController.h"
#include "editor/viewport/Viewport.h"
#include "editor/viewport/ViewportPalette.h"

#include <glm/geometric.hpp>

#include <QComboBox>
#include <QCoreApplication>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QLineEdit>
#include <QTest>

#include <cmath>
#include <optional>

using namespace throng;
using namespace throng::editor;
using namespace throng::editor::test;

namespace {

QStringList comboItems(QComboBox* combo)
{
    QStringList out;
    for (int i = 0; i < combo->count(); ++i)
        out << combo->itemText(i);
    return out;
}

// Where the agent `id` stands on the ground (x, z) in recorded frame 0, if it is there.
std::optional<glm::vec2> startOf(MainWindow& window, sim::AgentId id)
{
    const sim::FrameCache& cache = window.simulation().cache();
    if (cache.frameCount() == 0)
        return std::nullopt;
    for (std::size_t k = 0; k < cache.agentCount(); ++k)
        if (cache.agents()[k].id == id)
            return glm::vec2(cache.at(0, k).position.x, cache.at(0, k).position.z);
    return std::nullopt;
}

// Of `points` on the ground, how many show the selection colour in the shown viewport.
int selectionPixels(MainWindow& window, const std::vector<glm::vec2>& points)
{
    const QImage image = window.viewport().grabFramebuffer();
    int hits = 0;
    for (glm::vec2 p : points)
        hits += sameColour(pixelAt(image, window.viewport(), window.viewport().worldToPixel({p.x, 0.0f, p.y})),
                           palette::kSelection, 40);
    return hits;
}

}  // namespace

class TestTrafficItemsUi : public QObject {
    Q_OBJECT

private:
    QTemporaryDir m_dir;

private slots:
    void aCrosswalkPickedInTheViewportTakesItsEndsAndWidth()
    {
        MainWindow window;
        QVERIFY(showWithYaml(window, m_dir, "walk.yaml", trafficScene()));
        const QByteArray before = sceneYaml(window);
        QCOMPARE(window.outliner().kindRow(ItemKind::Crosswalk)->text(0), QString("Crosswalks (2)"));
        QVERIFY(clickToolButton(window, "select"));
        clickOnGround(window, {12, 24.5f});  // the middle of "zebra"
        QVERIFY(window.document().selection() == (Selection{{ItemKind::Crosswalk, 0}}));
        QVERIFY(window.outliner().kindRow(ItemKind::Crosswalk)->child(0)->isSelected());
        QCOMPARE(field<QLineEdit>(window, "name")->text(), QString("zebra"));
        QCOMPARE(field<QDoubleSpinBox>(window, "toZ")->value(), 29.0);

        typeInto(field<QDoubleSpinBox>(window, "width"), "5");
        typeInto(field<QDoubleSpinBox>(window, "toX"), "16");
        const sim::Scene& scene = window.document().scene();
        QCOMPARE(scene.crosswalks[0].widthM, 5.0f);
        QCOMPARE(scene.crosswalks[0].to, glm::vec2(16, 29));
        QCOMPARE(scene.crosswalks[1].widthM, 2.0f);
        QCOMPARE(window.document().undoStack()->count(), 2);

        // Both ends on one point is refused, with a reason, and nothing changes.
        typeInto(field<QDoubleSpinBox>(window, "fromX"), "16");
        typeInto(field<QDoubleSpinBox>(window, "fromZ"), "29");
        QCOMPARE(scene.crosswalks[0].from, glm::vec2(16, 20));
        QCOMPARE(window.document().undoStack()->count(), 3);
        QVERIFY2(lastMessage(window).contains("cannot be the same point"), qPrintable(lastMessage(window)));
        QVERIFY(field<QDoubleSpinBox>(window, "fromZ")->toolTip().contains("same point"));
        QCOMPARE(field<QDoubleSpinBox>(window, "fromZ")->value(), 20.0);

        // Renamed: the light's stop line follows, and the outliner shows the new name.
        typeInto(field<QLineEdit>(window, "name"), "stripes");
        QCOMPARE(scene.crosswalks[0].name, std::string("stripes"));
        QCOMPARE(scene.trafficLights[0].stopLines[1].crosswalk, std::string("stripes"));
        QCOMPARE(window.outliner().kindRow(ItemKind::Crosswalk)->child(0)->text(0), QString("stripes"));
        QCOMPARE(window.document().undoStack()->count(), 4);
        for (int k = 0; k < 4; ++k)
            undo(window);
        QCOMPARE(sceneYaml(window), before);
        QCOMPARE(field<QDoubleSpinBox>(window, "width")->value(), 3.0);
    }

    void twoCrosswalksShowMixedAndTakeOneWidth()
    {
        MainWindow window;
        QVERIFY(showWithYaml(window, m_dir, "walks.yaml", trafficScene()));
        selectInOutliner(window, {{ItemKind::Crosswalk, 0}, {ItemKind::Crosswalk, 1}});
        QCOMPARE(field<QDoubleSpinBox>(window, "width")->text(), QString("(mixed)"));
        QCOMPARE(field<QDoubleSpinBox>(window, "fromX")->text(), QString("(mixed)"));
        QVERIFY(!field<QLineEdit>(window, "name")->isEnabled());
        typeInto(field<QDoubleSpinBox>(window, "width"), "4");
        const sim::Scene& scene = window.document().scene();
        QCOMPARE(scene.crosswalks[0].widthM, 4.0f);
        QCOMPARE(scene.crosswalks[1].widthM, 4.0f);
        QCOMPARE(window.document().undoStack()->count(), 1);
        QCOMPARE(field<QDoubleSpinBox>(window, "width")->value(), 4.0);
        undo(window);
        QCOMPARE(scene.crosswalks[0].widthM, 3.0f);
        QCOMPARE(scene.crosswalks[1].widthM, 2.0f);
    }

    void aVehicleTakesTypeLaneStartAndSpeed()
    {
        MainWindow window;
        QVERIFY(showWithYaml(window, m_dir, "car.yaml", trafficScene()));
        const QByteArray before = sceneYaml(window);
        QCOMPARE(window.outliner().kindRow(ItemKind::Vehicle)->text(0), QString("Vehicles (2)"));
        QTRY_VERIFY(startOf(window, 50).has_value());
        QVERIFY(glm::length(*startOf(window, 50) - glm::vec2(-20, -27)) < 0.01f);

        QVERIFY(clickToolButton(window, "select"));
        clickOnGround(window, {-20, -27});  // car 50, 10 m along lane "side"
        QVERIFY(window.document().selection() == (Selection{{ItemKind::Vehicle, 1}}));
        QCOMPARE(field<QLabel>(window, "id")->text(), QString("50"));
        // Only vehicle types are offered.
        QCOMPARE(comboItems(field<QComboBox>(window, "type")), (QStringList{"car", "bus"}));
        QCOMPARE(field<QDoubleSpinBox>(window, "speed")->value(), 4.0);

        pick(window, "type", "bus");
        pick(window, "lane", "main");
        typeInto(field<QDoubleSpinBox>(window, "at"), "20");
        typeInto(field<QDoubleSpinBox>(window, "speed"), "6");
        const sim::Vehicle& car = window.document().scene().vehicles[1];
        QCOMPARE(car.type, std::string("bus"));
        QCOMPARE(car.lane, std::string("main"));
        QCOMPARE(car.atM, 20.0f);
        QCOMPARE(car.speed, 6.0f);
        QCOMPARE(window.document().undoStack()->count(), 4);
        QCOMPARE(window.outliner().kindRow(ItemKind::Vehicle)->child(1)->text(0), QString("Vehicle 2 (bus on main)"));
        // The run starts over with the car 20 m along "main" (from x = -30 on z = 25).
        QTRY_VERIFY(startOf(window, 50) && glm::length(*startOf(window, 50) - glm::vec2(-10, 25)) < 0.01f);

        for (int k = 0; k < 4; ++k)
            undo(window);
        QCOMPARE(sceneYaml(window), before);
        QTRY_VERIFY(startOf(window, 50) && glm::length(*startOf(window, 50) - glm::vec2(-20, -27)) < 0.01f);

        // Both cars: the lane differs, the type does not.
        selectInOutliner(window, {{ItemKind::Vehicle, 0}, {ItemKind::Vehicle, 1}});
        QCOMPARE(field<QComboBox>(window, "lane")->currentText(), QString("(mixed)"));
        QCOMPARE(field<QComboBox>(window, "type")->currentText(), QString("car"));
        QCOMPARE(field<QLabel>(window, "id")->text(), QString("(mixed)"));
    }

    void deleteRefusesACrosswalkALightStopsAtAndTakesVehicles()
    {
        MainWindow window;
        QVERIFY(showWithYaml(window, m_dir, "del.yaml", trafficScene()));
        const QByteArray before = sceneYaml(window);
        const sim::Scene& scene = window.document().scene();
        selectInOutliner(window, {{ItemKind::Crosswalk, 0}});
        QTest::keyClick(&window.viewport(), Qt::Key_Delete);
        QCOMPARE(scene.crosswalks.size(), std::size_t(2));
        QVERIFY2(lastMessage(window).contains("signal"), qPrintable(lastMessage(window)));
        QCOMPARE(window.document().undoStack()->count(), 0);

        // With the light in the same selection both go.
        selectInOutliner(window, {{ItemKind::Crosswalk, 0}, {ItemKind::TrafficLight, 0}});
        QTest::keyClick(&window.viewport(), Qt::Key_Delete);
        QCOMPARE(scene.crosswalks.size(), std::size_t(1));
        QCOMPARE(scene.crosswalks[0].name, std::string("ladder"));
        QVERIFY(scene.trafficLights.empty());
        QCOMPARE(window.outliner().kindRow(ItemKind::Crosswalk)->text(0), QString("Crosswalks (1)"));
        undo(window);
        QCOMPARE(sceneYaml(window), before);

        // A vehicle can always go; the viewport shows one car fewer.
        const std::size_t shown = window.viewport().agentCount();
        selectInOutliner(window, {{ItemKind::Vehicle, 0}});
        QTest::keyClick(&window.viewport(), Qt::Key_Delete);
        QCOMPARE(scene.vehicles.size(), std::size_t(1));
        QCOMPARE(scene.vehicles[0].id, 50u);
        QTRY_COMPARE(window.viewport().agentCount(), shown - 1);
        undo(window);
        QCOMPARE(sceneYaml(window), before);
        QTRY_COMPARE(window.viewport().agentCount(), shown);
    }

    void aSelectedCrosswalkAndVehicleAreOutlined()
    {
        MainWindow window;
        QVERIFY(showWithYaml(window, m_dir, "outline.yaml", trafficScene()));
        // Zebra's band is 3 m wide round x = 12: the outline runs 0.25 m outside, at x = 13.75.
        std::vector<glm::vec2> edge;
        for (float z = 21.0f; z <= 28.0f; z += 1.0f)
            edge.emplace_back(13.75f, z);
        // Car 50 (radius 1.1) starts at (-20, -27): its ring has a radius of 1.35 m.
        std::vector<glm::vec2> ring;
        for (int k = 0; k < 24; ++k)
            ring.push_back(glm::vec2(-20, -27) + 1.35f * glm::vec2(std::cos(k * 0.2618f), std::sin(k * 0.2618f)));
        QTest::qWait(50);
        QCOMPARE(selectionPixels(window, edge), 0);
        QCOMPARE(selectionPixels(window, ring), 0);
        selectInOutliner(window, {{ItemKind::Crosswalk, 0}, {ItemKind::Vehicle, 1}});
        QTest::qWait(50);
        QVERIFY2(selectionPixels(window, edge) >= 6, qPrintable(QString::number(selectionPixels(window, edge))));
        // The car (4.2 m long) is drawn over the ring's front and back.
        QVERIFY2(selectionPixels(window, ring) >= 10, qPrintable(QString::number(selectionPixels(window, ring))));
    }

    void messagesAboutCrosswalksAndVehiclesSelectThem()
    {
        MainWindow window;
        QVERIFY(showWithYaml(window, m_dir, "keys.yaml", trafficScene()));
        const std::pair<const char*, SceneItem> cases[] = {{"crosswalks[1].width", {ItemKind::Crosswalk, 1}},
                                                           {"vehicles[1].lane", {ItemKind::Vehicle, 1}}};
        for (const auto& [key, item] : cases) {
            sim::Diagnostic about{sim::Severity::Warning, "keys.yaml", 40, 5, key, "a note"};
            window.messages().showDiagnostics("Checked.", {about});
            QListWidgetItem* row = window.messages().item(1);
            QVERIFY(row);
            const QPoint at = window.messages().visualItemRect(row).center();
            QTest::mouseClick(window.messages().viewport(), Qt::LeftButton, Qt::NoModifier, at);
            QTest::mouseDClick(window.messages().viewport(), Qt::LeftButton, Qt::NoModifier, at);
            QVERIFY2(window.document().selection() == (Selection{item}), key);
            QVERIFY(window.outliner().kindRow(item.kind)->child(int(item.index))->isSelected());
        }
    }

    // The crossroads' knobs: a lane's and a vehicle type's car following from their
    // combo boxes (a walker type has none), the scene's default model and delays in the
    // settings; a minimum above its maximum is refused; all of it undoes to the same bytes.
    void carFollowingAndCrossingKnobsFromThePanel()
    {
        MainWindow window;
        QVERIFY(showWithYaml(window, m_dir, "knobs.yaml", trafficScene()));
        const QByteArray before = sceneYaml(window);
        const sim::Scene& scene = window.document().scene();

        selectInOutliner(window, {{ItemKind::Lane, 0}});
        QCOMPARE(comboItems(field<QComboBox>(window, "carFollowing")),
                 (QStringList{"Inherit", "IDM", "Gap time", "Fuzzy rules"}));
        QCOMPARE(field<QComboBox>(window, "carFollowing")->currentText(), QString("Inherit"));
        pick(window, "carFollowing", "Gap time", Scroll::ToWidget);
        QVERIFY(scene.lanes[0].carFollowing == sim::CarFollowing::GapTime);
        QVERIFY(scene.lanes[1].carFollowing == sim::CarFollowing::Inherit);

        selectInOutliner(window, {{ItemKind::AgentType, 3}});  // bus
        QCOMPARE(QString::fromStdString(scene.agentTypes[3].name), QString("bus"));
        pick(window, "carFollowing", "Fuzzy rules", Scroll::ToWidget);
        QVERIFY(scene.agentTypes[3].carFollowing == sim::CarFollowing::Fuzzy);
        selectInOutliner(window, {{ItemKind::AgentType, 0}});  // walker: no car following
        QCoreApplication::processEvents();
        QVERIFY(!field<QComboBox>(window, "carFollowing")->isVisible());

        QTreeWidgetItem* settings = window.outliner().kindRow(ItemKind::Settings);
        QTest::mouseClick(window.outliner().viewport(), Qt::LeftButton, Qt::NoModifier,
                          window.outliner().visualItemRect(settings).center());
        QCOMPARE(window.document().selection(), (Selection{{ItemKind::Settings, 0}}));
        QCOMPARE(comboItems(field<QComboBox>(window, "carFollowing")), (QStringList{"IDM", "Gap time", "Fuzzy rules"}));
        pick(window, "carFollowing", "Fuzzy rules", Scroll::ToWidget);
        QVERIFY(scene.traffic.carFollowing == sim::CarFollowing::Fuzzy);
        const int steps = window.document().undoStack()->count();
        typeInto(window, field<QDoubleSpinBox>(window, "walkerDelayMin"), "3");  // above the maximum, 2
        QCOMPARE(scene.traffic.walkerStartDelayS, glm::vec2(0.0f, 2.0f));
        QCOMPARE(window.document().undoStack()->count(), steps);
        QVERIFY2(lastMessage(window).contains("minimum cannot exceed its maximum"), qPrintable(lastMessage(window)));
        typeInto(window, field<QDoubleSpinBox>(window, "walkerDelayMax"), "4");
        typeInto(window, field<QDoubleSpinBox>(window, "walkerDelayMin"), "3");
        typeInto(window, field<QDoubleSpinBox>(window, "crossingMargin"), "1.5");
        QCOMPARE(scene.traffic.walkerStartDelayS, glm::vec2(3.0f, 4.0f));
        QCOMPARE(scene.traffic.crossingMarginM, 1.5f);
        QCOMPARE(window.document().undoStack()->count(), steps + 3);
        const std::string saved = sim::sceneToYaml(scene);
        for (const char* key : {"car_following: gap_time", "car_following: fuzzy", "walker_start_delay: [3, 4]",
                                "crossing_margin: 1.5"})
            QVERIFY2(saved.find(key) != std::string::npos, key);

        // Back in the viewport (the spin box keeps Ctrl+Z for its own text while it has the
        // focus): a click on empty ground, then an undo for each edit.
        QVERIFY(clickToolButton(window, "select"));
        clickOnGround(window, {20, 10});
        QCOMPARE(window.document().undoStack()->count(), steps + 3);
        for (int k = 0; k < steps + 3; ++k)
            undo(window);
        QCOMPARE(sceneYaml(window), before);
    }
};

THRONG_REGISTER_TEST(TestTrafficItemsUi)
#include "TestTrafficItemsUi.moc"
