// The neighbour grid finds every agent within a radius, exactly as a brute-force scan does.
#include "TestRegistry.h"

#include "simcore/world/NeighbourGrid.h"

#include <QTest>

#include <algorithm>
#include <iterator>
#include <optional>
#include <numeric>
#include <random>
#include <set>
#include <tuple>
#include <vector>

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

    // forEachLaterNear (the overlap count's pairs): from the agents in the grid's order,
    // every pair within r of each other is offered exactly once. forEachLaterNearRun, over
    // runs of the order (one per thread), offers the same pairs, or declines (walkers, or
    // a reach longer than a cell). Reaches that differ from agent to agent (as bodies'
    // radii do) move its windows down as well as up.
    void laterNearOffersEveryClosePairOnce_data()
    {
        QTest::addColumn<bool>("byHeight");
        QTest::addColumn<float>("radius");
        QTest::addColumn<bool>("inRuns");
        QTest::addColumn<bool>("mixedReach");  // every third agent's reach half the radius
        QTest::newRow("walkers") << false << 0.8f << false << false;
        QTest::newRow("walkers, in runs") << false << 0.8f << true << false;
        QTest::newRow("walkers, mixed reaches") << false << 0.8f << false << true;
        QTest::newRow("fliers") << true << 0.8f << false << false;
        QTest::newRow("fliers, in runs") << true << 0.8f << true << false;
        QTest::newRow("fliers, mixed reaches, in runs") << true << 0.8f << true << true;
        QTest::newRow("fliers, radius above cell") << true << 2.5f << false << false;
        QTest::newRow("fliers, radius above cell, in runs") << true << 2.5f << true << false;
    }

    void laterNearOffersEveryClosePairOnce()
    {
        QFETCH(bool, byHeight);
        QFETCH(float, radius);
        QFETCH(bool, inRuns);
        QFETCH(bool, mixedReach);
        std::mt19937 gen(23);
        std::uniform_real_distribution<float> u(-12.0f, 12.0f), h(0.0f, 6.0f);
        std::vector<glm::vec3> pos(2500);
        for (glm::vec3& p : pos)
            p = {u(gen), byHeight ? h(gen) : 0.0f, u(gen)};
        pos[7] = {40.0f, pos[7].y, -40.0f};  // outside the bounds: clamped into a border cell
        pos[8] = {39.8f, pos[7].y, -39.7f};  // near it, at the same height
        for (std::size_t i = 20; i < 40; ++i)  // a stack at one point, some at one height
            pos[i] = {2.0f, byHeight ? 0.05f * float(i % 5) : 0.0f, 2.0f};
        NeighbourGrid grid;
        grid.configure({-10.0f, -10.0f}, {10.0f, 10.0f}, 2.0f);
        grid.rebuild(pos, byHeight);
        const auto order = grid.order();
        auto reachOf = [&](std::uint32_t i) { return mixedReach && i % 3 == 0 ? 0.5f * radius : radius; };
        auto reach = [&](std::size_t k) { return reachOf(order[k]); };
        // Every (k, j) offered, one by one or in runs (cut mid-cell, one empty).
        auto offersOf = [&](bool runs) {
            std::multiset<std::pair<std::uint32_t, std::uint32_t>> offers;
            auto offer = [&](std::size_t k, std::uint32_t j, const glm::vec3& q) {
                QVERIFY(j != order[k]);
                QCOMPARE(q, pos[j]);
                offers.insert({order[k], j});
            };
            if (runs) {
                const std::size_t cuts[] = {0, 701, 701, 1903, order.size()};
                for (std::size_t r = 0; r + 1 < std::size(cuts); ++r)
                    if (!grid.forEachLaterNearRun(cuts[r], cuts[r + 1], radius, reach, offer))
                        return std::optional<decltype(offers)>();
                return std::optional(offers);
            }
            for (std::size_t k = 0; k < order.size(); ++k)
                grid.forEachLaterNear(k, reach(k), [&](std::uint32_t j, const glm::vec3& q) { offer(k, j, q); });
            return std::optional(offers);
        };
        for (std::size_t k = 0; k < order.size(); ++k)
            QCOMPARE(grid.orderedPosition(k), pos[order[k]]);
        const auto offers = offersOf(inRuns);
        if (inRuns) {
            const bool runs = byHeight && radius < 2.0f;  // sorted by height, and a reach within a cell
            QCOMPARE(offers.has_value(), runs);
            if (!runs)
                return;
            QVERIFY2(*offers == *offersOf(false), "not the pairs forEachLaterNear offers");
        }
        std::set<std::pair<std::uint32_t, std::uint32_t>> offered;
        for (const auto& [i, j] : *offers)
            offered.insert({std::min(i, j), std::max(i, j)});
        QCOMPARE(offers->size(), offered.size());  // no pair twice
        std::size_t close = 0;
        for (std::uint32_t a = 0; a < pos.size(); ++a)
            for (std::uint32_t b = a + 1; b < pos.size(); ++b) {
                const glm::vec3 d = pos[a] - pos[b];
                const float within = std::min(reachOf(a), reachOf(b));  // the earlier one's reach
                if (d.x * d.x + d.y * d.y + d.z * d.z <= within * within) {
                    ++close;
                    QVERIFY2(offered.count({a, b}), qPrintable(QString("pair %1, %2 not offered").arg(a).arg(b)));
                }
            }
        QVERIFY(close > 100);
        QVERIFY(offered.count({7, 8}));
    }

    // A grid allowed cells of 1, 2 and 4 m picks them by how many others share an agent's
    // cell: 4 m from the start while the agents stand 4 m apart (alone in their cells); at
    // the first choice after they close up to 1 m apart (15 others in a 4 m cell, 3 in a
    // 2 m one), 2 m; once packed 0.5 m apart, 1 m; 4 m again once spread. The choice comes
    // every kChooseEvery-th rebuild, not before. A grid told Fine or Coarse keeps its
    // cells. Whatever the cells, a query visits every agent within its radius, once.
    void cellsFollowTheCrowd()
    {
        auto lattice = [](float spacing) {
            std::vector<glm::vec3> pos;
            for (int x = 0; x < 40; ++x)
                for (int z = 0; z < 40; ++z)
                    pos.push_back({-78.0f + spacing * float(x), 0.0f, -78.0f + spacing * float(z)});
            return pos;
        };
        const std::vector<glm::vec3> spread = lattice(4.0f), close = lattice(1.0f), packed = lattice(0.5f);
        auto visitsAll = [](const NeighbourGrid& grid, const std::vector<glm::vec3>& pos) {
            for (std::size_t q = 0; q < pos.size(); q += 37) {
                const glm::vec2 p(pos[q].x, pos[q].z);
                std::set<std::uint32_t> found;
                bool twice = false;
                grid.forEachNear(p, 3.0f, [&](std::uint32_t j) { twice = twice || !found.insert(j).second; });
                if (twice)
                    return false;
                for (std::uint32_t j = 0; j < pos.size(); ++j) {
                    const float dx = pos[j].x - p.x, dz = pos[j].z - p.y;
                    if (dx * dx + dz * dz <= 9.0f && !found.count(j))
                        return false;
                }
            }
            return true;
        };
        NeighbourGrid grid;
        grid.configure({-80.0f, -80.0f}, {80.0f, 80.0f}, 1.0f, 4.0f, GridCells::ByCrowd);
        QCOMPARE(grid.fineCellM(), 1.0f);
        grid.rebuild(spread);
        QCOMPARE(grid.cellM(), 4.0f);
        QVERIFY(visitsAll(grid, spread));
        // The crowd closes up: the cells stay until the next choice.
        for (int k = 1; k < NeighbourGrid::kChooseEvery; ++k) {
            grid.rebuild(close);
            QCOMPARE(grid.cellM(), 4.0f);
        }
        QVERIFY(visitsAll(grid, close));
        grid.rebuild(close);
        QCOMPARE(grid.cellM(), 2.0f);
        QVERIFY(visitsAll(grid, close));
        for (int k = 0; k < NeighbourGrid::kChooseEvery; ++k)
            grid.rebuild(packed);
        QCOMPARE(grid.cellM(), 1.0f);
        QVERIFY(visitsAll(grid, packed));
        for (int k = 0; k < NeighbourGrid::kChooseEvery; ++k)
            grid.rebuild(spread);
        QCOMPARE(grid.cellM(), 4.0f);
        QVERIFY(visitsAll(grid, spread));
        for (const GridCells fixed : {GridCells::Fine, GridCells::Coarse}) {
            NeighbourGrid kept;
            kept.configure({-80.0f, -80.0f}, {80.0f, 80.0f}, 1.0f, 4.0f, fixed);
            const float edge = fixed == GridCells::Fine ? 1.0f : 4.0f;
            for (int k = 0; k <= 2 * NeighbourGrid::kChooseEvery; ++k) {
                kept.rebuild(k % 2 ? spread : packed);
                QCOMPARE(kept.cellM(), edge);
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

    // A cell of more than the insertion sort takes is sorted by height, ties by index,
    // whether its agents come already in that order (a flock stored from the ground up:
    // the sort is skipped), the other way up, with equal heights, or with one out of place.
    void crowdedCellsSortByHeightWhateverTheirOrder_data()
    {
        QTest::addColumn<QString>("arrangement");
        for (const char* a : {"ground up", "top down", "equal heights", "one out of place", "ground up, one tie"})
            QTest::newRow(a) << QString(a);
    }

    void crowdedCellsSortByHeightWhateverTheirOrder()
    {
        QFETCH(QString, arrangement);
        constexpr std::size_t kColumn = 200;  // in one 3 m cell
        std::vector<glm::vec3> pos;
        for (std::size_t i = 0; i < kColumn; ++i) {
            float y = float(i) * 0.5f;
            if (arrangement == "top down")
                y = float(kColumn - i) * 0.5f;
            else if (arrangement == "equal heights")
                y = float(i / 10);
            else if (arrangement == "one out of place" && i == 120)
                y = 3.25f;
            else if (arrangement == "ground up, one tie" && i == 121)
                y = float(i - 1) * 0.5f;
            pos.push_back({1.0f + 0.001f * float(i % 7), y, 1.0f});
        }
        pos.push_back({10.0f, 5.0f, 1.0f});  // and an agent in a cell of its own
        NeighbourGrid grid;
        grid.configure({0.0f, 0.0f}, {30.0f, 30.0f}, 3.0f);
        grid.rebuild(pos, true);
        std::vector<std::uint32_t> expected(kColumn);
        std::iota(expected.begin(), expected.end(), 0u);
        std::sort(expected.begin(), expected.end(),
                  [&](std::uint32_t a, std::uint32_t b) { return std::pair(pos[a].y, a) < std::pair(pos[b].y, b); });
        expected.push_back(std::uint32_t(kColumn));
        const std::span<const std::uint32_t> order = grid.order();
        QVERIFY(std::vector<std::uint32_t>(order.begin(), order.end()) == expected);
        for (std::size_t k = 0; k < order.size(); ++k)
            QCOMPARE(grid.orderedPosition(k), pos[order[k]]);
        // And the heights a query reads are the sorted ones: a slice finds exactly its agents.
        std::vector<std::uint32_t> slice;
        grid.forEachNear3D({1.0f, 40.0f, 1.0f}, 1.0f, [&](std::uint32_t j, const glm::vec3&) { slice.push_back(j); });
        std::vector<std::uint32_t> within;
        for (std::uint32_t j = 0; j < kColumn; ++j)
            if (pos[j].y >= 39.0f && pos[j].y <= 41.0f)
                within.push_back(j);
        std::sort(slice.begin(), slice.end());
        QVERIFY(slice == within);
    }

    // The parallel rebuild leaves the serial one's order (so every neighbour sum, and with
    // it the simulation, is bit-identical for any thread count): same agents, same order,
    // by cell and by height within a cell, exits left out.
    void rebuildOrderIsTheSameForAnyThreadCount_data()
    {
        QTest::addColumn<bool>("byHeight");
        QTest::newRow("walkers") << false;
        QTest::newRow("fliers, by height") << true;
    }

    void rebuildOrderIsTheSameForAnyThreadCount()
    {
        QFETCH(bool, byHeight);
        std::mt19937 gen(5);
        std::uniform_real_distribution<float> u(-40.0f, 40.0f), h(0.0f, 30.0f);
        std::vector<glm::vec3> pos(20000);
        std::vector<std::uint8_t> skip(pos.size(), 0);
        for (std::size_t i = 0; i < pos.size(); ++i) {
            pos[i] = {u(gen), byHeight ? h(gen) : 0.0f, u(gen)};
            skip[i] = i % 97 == 3 ? 1 : 0;
        }
        for (std::size_t i = 0; i < 300; ++i)  // a crowded cell (more than the insertion sort takes)
            pos[i] = {1.0f + 0.001f * float(i), h(gen), 1.0f};
        auto order = [&](int threads) {
            NeighbourGrid grid;
            grid.configure({-40.0f, -40.0f}, {40.0f, 40.0f}, 2.5f);
            const ThreadTeam team(threads);
            grid.rebuild(pos, byHeight, skip, &team);
            std::vector<std::uint32_t> seen;
            if (byHeight)
                grid.forEachNear3D({0.0f, 15.0f, 0.0f}, 45.0f, [&](std::uint32_t j, const glm::vec3&) { seen.push_back(j); });
            else
                grid.forEachNear({0.0f, 0.0f}, 45.0f, [&](std::uint32_t j) { seen.push_back(j); });
            return seen;
        };
        // Expected: rows, then cells along the row (32 x 32 cells of 2.5 m), then height
        // (fliers), then index.
        auto cell = [](float v) { return int(std::min((v + 40.0f) * (1.0f / 2.5f), 31.5f)); };
        std::vector<std::uint32_t> expected;
        for (std::uint32_t j = 0; j < pos.size(); ++j)
            if (!skip[j])
                expected.push_back(j);
        std::sort(expected.begin(), expected.end(), [&](std::uint32_t a, std::uint32_t b) {
            const float ya = byHeight ? pos[a].y : 0.0f, yb = byHeight ? pos[b].y : 0.0f;
            return std::tuple(cell(pos[a].z), cell(pos[a].x), ya, a) < std::tuple(cell(pos[b].z), cell(pos[b].x), yb, b);
        });
        const std::vector<std::uint32_t> one = order(1);
        QCOMPARE(one.size(), pos.size() - std::size_t(std::count(skip.begin(), skip.end(), 1)));
        QVERIFY2(one == expected, "one thread: not by cell, height and index");
        for (int threads : {2, 3, 4, 8})
            QVERIFY2(order(threads) == one, qPrintable(QString("%1 threads: another order").arg(threads)));
    }
};

THRONG_REGISTER_TEST(TestNeighbourGrid)
#include "TestNeighbourGrid.moc"
