// The neighbour grid finds every agent within a radius, exactly as a brute-force scan does.
#include "TestRegistry.h"

#include "simcore/world/NeighbourGrid.h"

#include <QTest>

#include <random>
#include <set>

using namespace throng::sim;

class TestNeighbourGrid : public QObject {
    Q_OBJECT
private slots:
    void matchesBruteForce_data()
    {
        QTest::addColumn<float>("cell");
        QTest::addColumn<float>("radius");
        QTest::newRow("radius below cell") << 2.0f << 1.5f;
        QTest::newRow("radius above cell") << 1.0f << 3.5f;
        QTest::newRow("tiny cells") << 0.3f << 1.0f;
    }

    void matchesBruteForce()
    {
        QFETCH(float, cell);
        QFETCH(float, radius);
        std::mt19937 gen(11);
        std::uniform_real_distribution<float> u(-30.0f, 30.0f);
        std::vector<glm::vec3> pos(3000);
        for (glm::vec3& p : pos)
            p = {u(gen), 0.0f, u(gen)};
        pos[5] = {100.0f, 0.0f, -100.0f};  // outside the bounds: clamped into a border cell
        pos[6] = {99.0f, 0.0f, -99.0f};
        NeighbourGrid grid;
        grid.configure({-25.0f, -25.0f}, {25.0f, 25.0f}, cell);
        grid.rebuild(pos);
        for (std::size_t q = 0; q < pos.size(); q += 7) {
            const glm::vec2 p(pos[q].x, pos[q].z);
            std::set<std::uint32_t> found;
            grid.forEachNear(p, radius, [&](std::uint32_t j) {
                QVERIFY(found.insert(j).second);  // each agent at most once
            });
            for (std::uint32_t j = 0; j < pos.size(); ++j) {
                const float dx = pos[j].x - p.x, dz = pos[j].z - p.y;
                if (dx * dx + dz * dz <= radius * radius)
                    QVERIFY2(found.count(j), "an agent within the radius was not visited");
            }
        }
    }

    void rebuildTracksMovement()
    {
        std::vector<glm::vec3> pos{{0, 0, 0}, {10, 0, 10}};
        NeighbourGrid grid;
        grid.configure({-20, -20}, {20, 20}, 2.0f);
        grid.rebuild(pos);
        int near = 0;
        grid.forEachNear({10, 10}, 1.0f, [&](std::uint32_t j) { near += j == 0; });
        QCOMPARE(near, 0);
        pos[0] = {10.5f, 0, 9.5f};
        grid.rebuild(pos);
        grid.forEachNear({10, 10}, 1.0f, [&](std::uint32_t j) { near += j == 0; });
        QCOMPARE(near, 1);
    }
};

THRONG_REGISTER_TEST(TestNeighbourGrid)
#include "TestNeighbourGrid.moc"
