// Resuming a scene whose walkers need no navigation grid (direct goals, a path, a car on
// a lane, a hero; no A* or flow-field walkers), as most small editor scenes are. Such a
// World keeps no per-agent navigation columns; adopting an edit must neither read them
// nor crash (it did, on undoing a behaviour-weight edit in the properties panel).
#include "../editor/PanelTestScene.h"
#include "StateScenes.h"
#include "TestRegistry.h"

#include "simcore/io/SceneIO.h"
#include "simcore/world/WorldState.h"

#include <QTest>

using namespace throng::sim;
using namespace throng::test::state;

namespace {

// The properties panel test's scene (the one that crashed), its walkers' arrival weight
// and navigation set as an edit would.
Scene directScene(float arrivalWeight, Navigation navigation = Navigation::Direct)
{
    LoadResult loaded = parseScene(throng::editor::test::panelScene().toStdString(), "panel.yaml", ".");
    if (!loaded.ok())
        qFatal("panel.yaml does not load: %s", loaded.diagnostics.front().message.c_str());
    AgentType& walker = loaded.scene.agentTypes.front();
    walker.behaviours.front().weight = arrivalWeight;  // arrival
    walker.navigation = navigation;
    return loaded.scene;
}

constexpr std::size_t kEditStep = 24;

}  // namespace

class TestWorldStateDirect : public QObject {
    Q_OBJECT

private slots:
    void unchangedSceneResumesBitIdentical()
    {
        const Scene scene = directScene(1.0f);
        World straight(scene);
        for (std::size_t s = 0; s < kEditStep; ++s)
            straight.step();
        const WorldState state = straight.saveState();
        const FrameCache reference = record(straight, 48);
        World resumed(scene);
        QVERIFY(resumed.adoptState(state, scene, scene));
        QCOMPARE(record(resumed, 48).hash(), reference.hash());
    }

    void weightEditResumesWhereTheRunStood()
    {
        // Walk with a weak arrival weight, then undo it to 1 at step 24: the walkers go on
        // from where they stood, now at their old pace.
        const Scene weak = directScene(0.1f), full = directScene(1.0f);
        World before(weak);
        for (std::size_t s = 0; s < kEditStep; ++s)
            before.step();
        const WorldState state = before.saveState();
        World edited(full);
        QVERIFY(edited.adoptState(state, weak, full));
        for (std::size_t i = 0; i < edited.agentCount(); ++i)
            QCOMPARE(edited.positions()[i], before.positions()[i]);
        World fresh(full);
        for (std::size_t s = 0; s < kEditStep; ++s) {
            edited.step();
            fresh.step();
        }
        // Placed walker 0 walks east at the edited pace: over the next second it covers
        // about what a fresh full-weight walker covers in its first second, and more than
        // the weak one did.
        const float weakWalked = before.positions()[0].x - (-10.0f);
        const float editedWalked = edited.positions()[0].x - before.positions()[0].x;
        QVERIFY2(editedWalked > 2.0f * weakWalked, qPrintable(QString("%1 vs %2").arg(editedWalked).arg(weakWalked)));
        const float freshWalked = fresh.positions()[0].x - (-10.0f);
        QVERIFY2(editedWalked > 0.9f * freshWalked, qPrintable(QString("%1 vs %2").arg(editedWalked).arg(freshWalked)));
    }

    void editGivingWalkersAStarPlansFromWhereTheyStand()
    {
        // The first A* walkers of a scene arrive with the edit: the resumed World builds
        // their navigation afresh (the checkpoint has none) and they walk on to the goal.
        const Scene direct = directScene(1.0f), planned = directScene(1.0f, Navigation::AStar);
        World before(direct);
        for (std::size_t s = 0; s < kEditStep; ++s)
            before.step();
        World edited(planned);
        QVERIFY(edited.adoptState(before.saveState(), direct, planned));
        const float startX = edited.positions()[0].x;
        for (std::size_t s = 0; s < 5 * kEditStep; ++s)
            edited.step();
        QVERIFY2(edited.positions()[0].x > startX + 4.0f, qPrintable(QString::number(edited.positions()[0].x - startX)));
    }
};

THRONG_REGISTER_TEST(TestWorldStateDirect)
#include "TestWorldStateDirect.moc"
