// Every demo scene Throng ships loads without an error or a warning, its brains compile,
// and it simulates headless with finite values throughout.
#include "DemoRuns.h"
#include "TestRegistry.h"

#include <QTest>

#include <filesystem>

using namespace throng::sim;
using namespace throng::test::demos;

class TestDemoScenes : public QObject {
    Q_OBJECT
private slots:
    void everyDemoLoadsAndRuns_data()
    {
        QTest::addColumn<QString>("file");
        QTest::addColumn<int>("minAgents");
        // Agents a user expects from the README's demo list; a shipped scene not listed
        // here still runs, with no minimum.
        const std::map<std::string, int> expected{
            {"crossroads.yaml", 200}, {"cavalry.yaml", 5001}, {"murmuration.yaml", 50001}};
        for (const auto& entry : std::filesystem::directory_iterator(THRONG_SOURCE_DIR "/resources/scenes")) {
            const std::string name = entry.path().filename().string();
            if (entry.path().extension() != ".yaml")
                continue;
            const auto it = expected.find(name);
            QTest::newRow(name.c_str()) << QString::fromStdString(name) << (it == expected.end() ? 1 : it->second);
        }
    }

    void everyDemoLoadsAndRuns()
    {
        QFETCH(QString, file);
        QFETCH(int, minAgents);
        const Scene scene = demo(file.toStdString());
        for (const Diagnostic& d : checkSceneBrains(scene))
            QFAIL(d.format().c_str());
        World world(scene, threads(2));
        QVERIFY(world.brainErrors().empty());
        QVERIFY2(world.agentCount() >= std::size_t(minAgents), qPrintable(QString::number(world.agentCount())));
        for (int s = 0; s < 12; ++s)
            world.step();
        QCOMPARE(world.counters().nonFiniteValues, std::uint64_t(0));
        QCOMPARE(world.counters().wallPenetrations, std::uint64_t(0));
        QCOMPARE(world.counters().obstaclePenetrations, std::uint64_t(0));
    }
};

THRONG_REGISTER_TEST(TestDemoScenes)
#include "TestDemoScenes.moc"
