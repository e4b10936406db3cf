// The end-to-end case: a brain built entirely through the UI (speed 0 when the
// light ahead is red: light_state -> "red" triangle -> NOT -> speed output), assigned to
// the walkers, makes them wait at the red crossing and cross on green; the same walkers
// without it walk onto the crossing on red.
#include "BrainTestScenes.h"
#include "BrainUiDriver.h"
#include "TestRegistry.h"

#include "editor/brain/BrainGraphModel.h"
#include "editor/brain/BrainView.h"
#include "simcore/io/SceneIO.h"
#include "simcore/world/World.h"

#include <glm/geometric.hpp>

#include <QComboBox>
#include <QTest>
#include <QToolButton>

using namespace throng;
using namespace throng::editor;
using namespace throng::editor::test;

class TestBrainBuiltInUi : public QObject {
    Q_OBJECT

private slots:
    void walkersStopAtRedWithABrainBuiltInTheEditor()
    {
        QTemporaryDir dir;
        MainWindow window;
        BrainUi ui(window);
        QVERIFY(ui.open(dir, kCrossingScene));
        QTest::mouseClick(ui.panel().findChild<QToolButton*>("newBrainButton"), Qt::LeftButton);
        QCOMPARE(window.document().scene().brains.size(), std::size_t(1));
        // Room for four nodes in a row: the palette drops each under the mouse.
        ui.panel().view().setTransform(QTransform::fromScale(0.8, 0.8));
        ui.panel().view().centerOn(550, 60);
        const sim::NodeId light = ui.addByTyping({0, 0}, "input");
        QVERIFY(ui.editParam(light, "sensor", "light_state"));
        const sim::NodeId red = ui.addByTyping({300, 0}, "triangle");
        QVERIFY(ui.editParam(red, "points", "0.75 1 1.25"));
        const sim::NodeId notRed = ui.addByTyping({600, 0}, "rule.not");
        const sim::NodeId speed = ui.addByTyping({900, 0}, "output");
        QVERIFY(ui.editParam(speed, "scale", "1.4"));
        ui.dragLink(light, 0, red, 0);
        ui.dragLink(red, 0, notRed, 0);
        ui.dragLink(notRed, 0, speed, 0);
        QCOMPARE(ui.linkCount(), 3);
        QVERIFY(ui.panel().errors().empty());
        auto* types = ui.panel().findChild<QComboBox*>("agentTypeList");
        types->setCurrentIndex(0);
        QTest::mouseClick(ui.panel().findChild<QToolButton*>("assignBrainButton"), Qt::LeftButton);
        const sim::Scene built = window.document().scene();
        QCOMPARE(built.agentTypes[0].brain, built.brains[0].name);

        // Run it as throng-cli would. Red until t = 10 s.
        sim::World world(built, {0, false, 1});
        QVERIFY(world.brainErrors().empty());
        float nearestToZebra = -100.0f, speedAt9 = 1.0f, enteredAt = -1.0f;
        while (world.timeS() < 30.0) {
            world.step();
            const double t = world.timeS();
            const float z = world.positions()[0].z;
            if (t < 10.0)
                nearestToZebra = std::max(nearestToZebra, z);
            if (std::abs(t - 9.5) < 0.5 * world.dt())
                speedAt9 = glm::length(world.velocities()[0]);
            if (enteredAt < 0.0f && z > -6.0f)
                enteredAt = float(t);
        }
        QVERIFY2(nearestToZebra < -6.0f, qPrintable(QString::number(double(nearestToZebra))));
        QVERIFY2(speedAt9 < 0.05f, qPrintable(QString::number(double(speedAt9))));
        QVERIFY2(enteredAt > 10.0f && enteredAt < 20.0f, qPrintable(QString::number(double(enteredAt))));
        QCOMPARE(world.counters().redLightViolations, std::uint64_t(0));

        // Without the brain the same walkers step onto the crossing on red.
        sim::Scene bare = built;
        bare.agentTypes[0].brain.clear();
        sim::World without(bare, {0, false, 1});
        while (without.timeS() < 10.0)
            without.step();
        QVERIFY(without.counters().redLightViolations > 0);

        // Saved and read back, the brain is the one built.
        QVERIFY(window.document().saveAs(dir.filePath("built.yaml")).ok);
        const sim::LoadResult back = sim::loadScene(dir.filePath("built.yaml").toStdString());
        QVERIFY(back.ok());
        QCOMPARE(back.scene.brains[0], built.brains[0]);
    }
};

THRONG_REGISTER_TEST(TestBrainBuiltInUi)
#include "TestBrainBuiltInUi.moc"
