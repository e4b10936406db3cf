// The demo scenes run the shipped brains: crossroads cars the car brain, crossroads walkers
// (the sidewalk and crossing walkers, and the shortest-path errand walkers) the pedestrian
// brain, cavalry riders the rider brain, murmuration starlings the boid brain.
// Each type names its brain, the World compiles and runs it, and taking the brain away
// changes how those agents move (so the brain is not a passenger).
#include "DemoRuns.h"
#include "TestRegistry.h"

#include "simcore/brain/BrainEvaluator.h"

#include <QTest>

#include <cmath>
#include <cstring>

using namespace throng::sim;
using namespace throng::test::demos;

namespace {

std::size_t typeIndex(const Scene& s, const std::string& name)
{
    for (std::size_t t = 0; t < s.agentTypes.size(); ++t)
        if (s.agentTypes[t].name == name)
            return t;
    qFatal("no agent type %s", name.c_str());
    return 0;
}

// The demo with its big groups cut to 500 agents (a circle spawn shrinks to keep its
// density) so the test is quick.
Scene reduced(const std::string& file)
{
    Scene s = demo(file);
    for (SpawnGroup& g : s.groups)
        if (g.count > 500) {
            const float keep = 500.0f / float(g.count);
            g.radiusM *= std::sqrt(keep);
            g.count = 500;
        }
    return s;
}

// Hash of the positions of `type`'s agents over `steps` steps.
std::uint64_t typeHash(const Scene& s, std::size_t type, int steps)
{
    World world(s, threads(1));
    std::uint64_t h = 1469598103934665603ull;
    for (int k = 0; k < steps; ++k) {
        world.step();
        for (std::size_t i = 0; i < world.agentCount(); ++i) {
            if (world.agentInfo()[i].typeIndex != type)
                continue;
            std::uint32_t bits[3];
            std::memcpy(bits, &world.positions()[i], sizeof bits);
            for (std::uint32_t b : bits)
                h = (h ^ b) * 1099511628211ull;
        }
    }
    return h;
}

}  // namespace

class TestDemoBrains : public QObject {
    Q_OBJECT
private slots:
    void demoTypesRunTheirBrain_data()
    {
        QTest::addColumn<QString>("file");
        QTest::addColumn<QString>("type");
        QTest::addColumn<QString>("brain");
        QTest::addColumn<int>("steps");
        QTest::newRow("crossroads cars") << "crossroads.yaml" << "car" << "car" << 480;
        QTest::newRow("crossroads walkers") << "crossroads.yaml" << "pedestrian" << "pedestrian" << 240;
        QTest::newRow("crossroads errand walkers") << "crossroads.yaml" << "errand" << "pedestrian" << 240;
        QTest::newRow("cavalry riders") << "cavalry.yaml" << "rider" << "rider" << 48;
        QTest::newRow("murmuration starlings") << "murmuration.yaml" << "starling" << "boid" << 48;
    }

    void demoTypesRunTheirBrain()
    {
        QFETCH(QString, file);
        QFETCH(QString, type);
        QFETCH(QString, brain);
        QFETCH(int, steps);
        const Scene s = reduced(file.toStdString());
        const std::size_t t = typeIndex(s, type.toStdString());
        QCOMPARE(QString::fromStdString(s.agentTypes[t].brain), brain);
        const BrainGraph* graph = s.findBrain(brain.toStdString());
        QVERIFY(graph);
        QVERIFY2(graph->nodes.size() >= 20, qPrintable(QString::number(graph->nodes.size())));  // the shipped graph, not a stub
        {
            World world(s, threads(1));
            QVERIFY(world.brainErrors().empty());
            const BrainEvaluator* eval = world.brainEvaluator(t);
            QVERIFY(eval);
            QVERIFY(eval->agentCount() > 0);
        }
        // Without the brain the same agents move differently.
        Scene without = s;
        without.agentTypes[t].brain.clear();
        QVERIFY(typeHash(s, t, steps) != typeHash(without, t, steps));
    }
};

THRONG_REGISTER_TEST(TestDemoBrains)
#include "TestDemoBrains.moc"
