// The viewport's shown crowd without GL: each agent of a frame drawn once, in its kind's
// batch, with its type's size; absent agents and those gone through an exit drawn by none;
// the HUD's counts and the framed extent from the drawn agents; picking's ShownAgents for
// all of them; and the kept frame coloured again when the colouring changes.
#include "TestRegistry.h"

#include "editor/viewport/ShownCrowd.h"

#include <QTest>

#include <vector>

using namespace throng;
using namespace throng::editor;

namespace {

sim::Scene threeKinds()
{
    sim::Scene scene;
    sim::AgentType walker;
    walker.name = "walker";
    walker.radiusM = 0.25f;
    walker.maxSpeed = 2.0f;
    sim::AgentType car = walker;
    car.name = "car";
    car.kind = sim::AgentKind::Vehicle;
    car.radiusM = 1.0f;
    sim::AgentType bird = walker;
    bird.name = "bird";
    bird.kind = sim::AgentKind::Flier;
    bird.radiusM = 0.2f;
    scene.agentTypes = {walker, car, bird};
    return scene;
}

sim::AgentFrame at(float x, float z, float speed = 1.0f)
{
    sim::AgentFrame f;
    f.position = {x, 0.0f, z};
    f.speed = speed;
    return f;
}

sim::AgentInfo agent(sim::AgentId id, std::uint16_t type)
{
    sim::AgentInfo a;
    a.id = id;
    a.typeIndex = type;
    return a;
}

}  // namespace

class TestShownCrowd : public QObject {
    Q_OBJECT

private slots:
    void eachDrawnAgentOnceInItsKind()
    {
        ShownCrowd crowd;
        crowd.setScene(threeKinds(), "");
        std::vector<sim::AgentFrame> frames{at(0, 0, 0.5f), at(2, 0, 1.5f), at(4, 0), at(10, 5), at(-3, 8),
                                            at(50, 50), at(-6, -1)};
        frames[1].arrived = true;
        frames[2].arrived = frames[2].out = true;  // left through an exit
        frames[5].present = false;                 // not there on this frame
        const std::vector<sim::AgentInfo> agents{agent(1, 0), agent(2, 0), agent(3, 0), agent(4, 1),
                                                 agent(5, 2), agent(6, 0), agent(7, 9)};  // 7: a type the scene lacks
        crowd.keep(frames, agents);
        crowd.build({}, 0.0, nullptr, 0);

        QCOMPARE(crowd.batch(ShownCrowd::Walkers).glyphs.size(), std::size_t(3));  // 1, 2 and 7
        QCOMPARE(crowd.batch(ShownCrowd::Vehicles).glyphs.size(), std::size_t(1));
        QCOMPARE(crowd.batch(ShownCrowd::Fliers).glyphs.size(), std::size_t(1));
        QCOMPARE(crowd.glyphCount(), std::size_t(5));
        for (std::size_t k = 0; k < ShownCrowd::kKinds; ++k)
            QCOMPARE(crowd.batch(ShownCrowd::Kind(k)).poses.size(), crowd.batch(ShownCrowd::Kind(k)).glyphs.size());
        const AgentBatch walkers = crowd.batch(ShownCrowd::Walkers);
        QCOMPARE(walkers.glyphs[0].position, frames[0].position);
        QCOMPARE(walkers.glyphs[0].radiusM, 0.25f);
        QCOMPARE(walkers.glyphs[2].position, frames[6].position);
        QCOMPARE(walkers.glyphs[2].radiusM, 0.3f);  // the fallback for an unknown type
        QCOMPARE(crowd.batch(ShownCrowd::Vehicles).glyphs[0].radiusM, 1.0f);
        QCOMPARE(crowd.batch(ShownCrowd::Fliers).glyphs[0].position, frames[4].position);

        const ShownCrowd::Counts& counts = crowd.counts();
        QCOMPARE(counts.shown, std::size_t(5));
        QCOMPARE(counts.arrived, std::size_t(2));
        QCOMPARE(counts.out, std::size_t(1));
        using Row = std::pair<std::string, std::size_t>;
        const std::vector<Row> perType{{"walker", 2}, {"car", 1}, {"bird", 1}};
        QCOMPARE(counts.perType, perType);

        // The extent holds the drawn bodies only: not the absent one at (50, 50).
        const GroundBox& box = crowd.extent();
        QVERIFY(!box.empty);
        QCOMPARE(box.min.x, -6.3f);
        QCOMPARE(box.max.x, 11.0f);
        QCOMPARE(box.min.y, -1.3f);
        QCOMPARE(box.max.y, 8.2f);

        const ShownAgents& shown = crowd.shown();
        QCOMPARE(shown.size(), std::size_t(7));
        for (std::size_t i = 0; i < 7; ++i) {
            QCOMPARE(shown.id(i), agents[i].id);
            QCOMPARE(shown.drawn(i), i != 2 && i != 5);
        }
        QCOMPARE(shown.radiusM(3), 1.0f);
    }

    void keptFrameColouredAgain()
    {
        ShownCrowd crowd;
        crowd.setScene(threeKinds(), "");
        const std::vector<sim::AgentFrame> frames{at(0, 0, 0.2f), at(2, 0, 1.8f), at(4, 0, 1.0f)};
        const std::vector<sim::AgentInfo> agents{agent(1, 0), agent(2, 0), agent(3, 1)};
        crowd.setColourBy(ColourBy::Type);
        crowd.keep(frames, agents);
        crowd.build({}, 0.0, nullptr, 0);
        QVERIFY(crowd.takeChanged().glyphs);
        QVERIFY(!crowd.takeChanged().glyphs);
        // By type: the two walkers alike, the car not.
        const glm::vec3 walkerColour = crowd.batch(ShownCrowd::Walkers).glyphs[0].colour;
        QCOMPARE(crowd.batch(ShownCrowd::Walkers).glyphs[1].colour, walkerColour);
        QVERIFY(crowd.batch(ShownCrowd::Vehicles).glyphs[0].colour != walkerColour);

        // The kept frame given again, as the viewport does when the colouring changes.
        crowd.setColourBy(ColourBy::Speed);
        crowd.keep(crowd.frames(), crowd.agents());
        QCOMPARE(crowd.frames().size(), std::size_t(3));
        crowd.build({}, 0.0, nullptr, 0);
        QVERIFY(crowd.takeChanged().glyphs);
        QVERIFY(crowd.batch(ShownCrowd::Walkers).glyphs[0].colour != crowd.batch(ShownCrowd::Walkers).glyphs[1].colour);
        QCOMPARE(crowd.batch(ShownCrowd::Walkers).glyphs[1].position, frames[1].position);

        // More frames than agents: only as many as both hold.
        crowd.keep(frames, std::vector<sim::AgentInfo>{agents[0]});
        crowd.build({}, 0.0, nullptr, 0);
        QCOMPARE(crowd.glyphCount(), std::size_t(1));
        QCOMPARE(crowd.shown().size(), std::size_t(1));
        // Nobody: nothing drawn, an empty extent.
        crowd.keep({}, {});
        crowd.build({}, 0.0, nullptr, 0);
        QCOMPARE(crowd.glyphCount(), std::size_t(0));
        QVERIFY(crowd.extent().empty);
        QCOMPARE(crowd.counts().shown, std::size_t(0));
    }
};

THRONG_REGISTER_TEST(TestShownCrowd)
#include "TestShownCrowd.moc"
