// Sizes that would exhaust memory are errors at the key that asks for them, with the
// estimate, before anything is allocated; repeated and far-away walls and obstacles are
// warned about and cost nothing per step. What a user saw before: `nav_cell: 0.001` and
// two groups of 6,000,000 aborted `throng-cli run` with std::bad_alloc after `check` had
// called them valid; 50,000 pasted copies of one wall took over 5 minutes for 24 frames,
// and one wall point at -1e30 made every step 50 times slower.
#include "TestRegistry.h"

#include "simcore/io/SceneIO.h"
#include "simcore/io/SceneLimits.h"
#include "simcore/world/FrameCache.h"
#include "simcore/base/SegmentGrid.h"
#include "simcore/world/World.h"

#include <QTest>

#include <cstring>
#include <string>

using namespace throng::sim;

namespace {

const Diagnostic* find(const LoadResult& r, Severity s, const std::string& key)
{
    for (const Diagnostic& d : r.diagnostics)
        if (d.severity == s && d.key == key)
            return &d;
    return nullptr;
}

std::string walkers(const std::string& settings, const std::string& navigation, const std::string& groups)
{
    return "throng: 1\n"
           "settings:\n" + settings +
           "agent_types:\n  - {name: walker, navigation: " + navigation + "}\n"
           "goals:\n  - {name: exit, position: [40, 0], radius: 2}\n"
           "groups:\n" + groups;
}

const std::string kOneGroup = "  - {name: a, type: walker, count: 10, rect: {min: [0, 0], max: [5, 5]}, goal: exit}\n";

// Every frame's state as bytes, to compare two runs exactly.
std::vector<AgentFrame> run(const Scene& s, int frames)
{
    World w(s, WorldOptions{});
    std::vector<AgentFrame> all, frame;
    for (int f = 0; f < frames; ++f) {
        w.step();
        w.snapshot(frame);
        all.insert(all.end(), frame.begin(), frame.end());
    }
    return all;
}

}  // namespace

class TestSceneLimits : public QObject {
    Q_OBJECT
private slots:
    void aNavigationGridPastTheLimitIsAnErrorAtNavCell()
    {
        // 100 x 100 m at 1 mm: 10^10 cells, about 300 GB.
        const LoadResult r = parseScene(
            walkers("  nav_cell: 0.001\n  bounds: {min: [-50, -50], max: [50, 50]}\n", "astar", kOneGroup), "tiny.yaml", "");
        const Diagnostic* d = find(r, Severity::Error, "settings.nav_cell");
        QVERIFY(d);
        QCOMPARE(d->line, 3);
        QCOMPARE(d->column, 13);
        QVERIFY2(d->message.find("10,000,000,000 cells") != std::string::npos, d->message.c_str());
        QVERIFY2(d->message.find("100 x 100 m") != std::string::npos, d->message.c_str());
        // Huge bounds at the default cell say so at the bounds.
        const LoadResult wide = parseScene(walkers("  bounds: {min: [-1e6, -1e6], max: [1e6, 1e6]}\n", "flow_field", kOneGroup),
                                           "wide.yaml", "");
        QVERIFY(find(wide, Severity::Error, "settings.bounds"));
        // Nothing navigates: no grid is built, so the same cell is no error (run agrees).
        const LoadResult direct = parseScene(walkers("  nav_cell: 0.001\n", "direct", kOneGroup), "direct.yaml", "");
        QVERIFY(direct.ok());
        // At the limit's scale but under it: a 2 km square at 0.5 m is fine.
        const LoadResult big = parseScene(
            walkers("  bounds: {min: [-1000, -1000], max: [1000, 1000]}\n  nav_cell: 0.5\n", "astar", kOneGroup), "big.yaml", "");
        QVERIFY(big.ok());
    }

    void aCrowdPastTheLimitIsAnErrorAtTheGroupThatPassesIt()
    {
        const std::string groups = kOneGroup +
                                   "  - {name: b, type: walker, count: 6000000, rect: {min: [-2000, -2000], max: [2000, 2000]}}\n"
                                   "  - {name: c, type: walker, count: 6000000, rect: {min: [-2000, -2000], max: [2000, 2000]}}\n";
        const LoadResult r = parseScene(walkers("  fps: 24\n", "direct", groups), "crowd.yaml", "");
        const Diagnostic* d = find(r, Severity::Error, "groups[2].count");
        QVERIFY(d);
        QCOMPARE(d->line, 11);
        QVERIFY2(d->message.find("12,000,010 agents") != std::string::npos, d->message.c_str());
        QVERIFY(!find(r, Severity::Error, "groups[1].count"));
    }

    void aGroupPackedPastItsBodiesIsAnError()
    {
        // 10,000,000 walkers on a 100 m square (1,000 a square metre) ran for hours: each
        // had thousands of neighbours in reach. Bodies of 0.3 m fit about 32,000 there.
        const std::string crammed = "  - {name: a, type: walker, count: 10000000, rect: {min: [-50, -50], max: [50, 50]}}\n";
        const LoadResult r = parseScene(walkers("  fps: 24\n", "direct", crammed), "crammed.yaml", "");
        const Diagnostic* d = find(r, Severity::Error, "groups[0].count");
        QVERIFY(d);
        QVERIFY2(d->message.find("312 times as tight") != std::string::npos, d->message.c_str());
        // Four times the packing is still a start (overlaps part in the first steps).
        const std::string tight = "  - {name: a, type: walker, count: 120000, rect: {min: [-50, -50], max: [50, 50]}}\n";
        QVERIFY(parseScene(walkers("  fps: 24\n", "direct", tight), "tight.yaml", "").ok());
    }

    void flowStrokesPastTheLimitAreAnError()
    {
        const std::string scene = "throng: 1\nflow_strokes:\n  - {points: [[0, 0], [10, 0]]}\n"
                                  "  - {points: [[0, 0], [300000, 0]]}\n";
        const LoadResult r = parseScene(scene, "strokes.yaml", "");
        const Diagnostic* d = find(r, Severity::Error, "flow_strokes[1]");
        QVERIFY(d);
        QCOMPARE(d->line, 4);
        QVERIFY2(d->message.find("300,010 m") != std::string::npos, d->message.c_str());
    }

    void repeatedAndFarWallsAreWarnedAbout()
    {
        std::string scene = "throng: 1\nwalls:\n  - {name: a, points: [[0, 0], [10, 0], [10, 10]]}\n"
                            "  - {name: b, points: [[10, 10], [10, 0]]}\n"  // the second segment of a, reversed
                            "  - {name: c, points: [[0, 5], [-1e8, 5]]}\n"
                            "obstacles:\n  - {name: p, shape: circle, center: [3, 3], radius: 1}\n"
                            "  - {name: q, shape: circle, center: [3, 3], radius: 1}\n";
        const LoadResult r = parseScene(scene, "repeats.yaml", "");
        QVERIFY(r.ok());
        const Diagnostic* wall = find(r, Severity::Warning, "walls[1]");
        QVERIFY(wall);
        QCOMPARE(wall->line, 4);
        QVERIFY2(wall->message.find("1 wall segments repeat") != std::string::npos, wall->message.c_str());
        const Diagnostic* far = find(r, Severity::Warning, "walls[2]");
        QVERIFY(far);
        QVERIFY2(far->message.find("outside the scene bounds") != std::string::npos, far->message.c_str());
        QVERIFY(find(r, Severity::Warning, "obstacles[1]"));
        // 1e30 m is no place: its square overflows a float. An error at the number.
        const LoadResult typo = parseScene("throng: 1\nwalls:\n  - {name: c, points: [[0, 5], [-1e30, 5]]}\n", "typo.yaml", "");
        const Diagnostic* e = find(typo, Severity::Error, "walls[0].points[1][0]");
        QVERIFY(e);
        QCOMPARE(e->line, 3);
        QCOMPARE(e->column, 33);
        QVERIFY2(e->message.find("-1e+30 is beyond 1e+09 m") != std::string::npos, e->message.c_str());
        // An obstacle that would swallow any set is an error too.
        const LoadResult huge = parseScene("throng: 1\nobstacles:\n  - {name: p, shape: circle, center: [0, 0], radius: 5e4}\n",
                                           "huge.yaml", "");
        QVERIFY(find(huge, Severity::Error, "obstacles[0].radius"));
    }

    void pastedWallsAndObstaclesStepAsOne()
    {
        // 20,000 copies of one wall and of one pillar: the run is the run of one of each.
        Scene one;
        one.settings.fps = 24.0f;
        one.agentTypes.push_back(AgentType{});
        one.agentTypes[0].name = "walker";
        one.agentTypes[0].behaviours = {{"seek", 1.0f, {}}, {"wall_following", 2.0f, {}},
                                        {"obstacle_avoidance", 2.0f, {}}, {"separation", 1.0f, {}}};
        one.goals.push_back({"exit", {20.0f, 0.0f}, 2.0f, false});
        for (int k = 0; k < 40; ++k)
        {
            Agent a;
            a.id = std::uint32_t(k + 1);
            a.type = "walker";
            a.position = {-10.0f + 0.7f * float(k % 8), 0.0f, -3.0f + 1.2f * float(k / 8)};
            a.goal = "exit";
            one.agents.push_back(a);
        }
        one.walls.push_back({"w", {{-5.0f, 3.0f}, {5.0f, -1.0f}}});
        one.obstacles.push_back({"p", ObstacleShape::Circle, {6.0f, 1.0f}, 1.0f, {1, 1}, 0.0f});
        Scene pasted = one;
        for (int k = 0; k < 20000; ++k) {
            pasted.walls.push_back(one.walls[0]);
            pasted.obstacles.push_back(one.obstacles[0]);
        }
        const std::vector<AgentFrame> a = run(one, 48), b = run(pasted, 48);
        QCOMPARE(a.size(), b.size());
        QVERIFY(std::memcmp(a.data(), b.data(), a.size() * sizeof(AgentFrame)) == 0);
    }

    void aFarWallPointKeepsTheWallGridFine()
    {
        // 400 short walls on a 20 x 20 m lot, and one running off to -1e30: a query near the
        // lot still sees only the walls near it, and the far wall where it passes.
        std::vector<Segment> walls;
        for (int z = 0; z < 20; ++z)
            for (int x = 0; x < 20; ++x)
                walls.push_back({{float(x), float(z)}, {float(x) + 0.5f, float(z)}});
        walls.push_back({{0.0f, -0.5f}, {-1e30f, -0.5f}});
        SegmentGrid grid;
        grid.build(walls, 4.0f, glm::vec2(-100.0f), glm::vec2(120.0f));
        int seen = 0;
        grid.forEachNear({10.0f, 10.0f}, 1.0f, [&](std::uint32_t) { ++seen; });
        QVERIFY2(seen <= 36, std::to_string(seen).c_str());
        bool far = false;
        grid.forEachNear({-50.0f, -0.5f}, 1.0f, [&](std::uint32_t k) { far = far || k == 400; });
        QVERIFY(far);
        // Beyond the focus, the border cells still hold it.
        far = false;
        grid.forEachNear({-5000.0f, -0.5f}, 1.0f, [&](std::uint32_t k) { far = far || k == 400; });
        QVERIFY(far);
        // Unfocused, far queries find nothing, as before.
        SegmentGrid plain;
        plain.build(std::span<const Segment>(walls.data(), 400), 4.0f);
        int none = 0;
        plain.forEachNear({-5000.0f, 0.0f}, 1.0f, [&](std::uint32_t) { ++none; });
        QCOMPARE(none, 0);
    }
};

THRONG_REGISTER_TEST(TestSceneLimits)
#include "TestSceneLimits.moc"
