// The headway rule (`time_gap`, issue 26's single file, RiMEA test 16), checked from the
// positions: the gap ahead is the distance to contact; a walker closing on one who stands
// never walks faster than its gap over the time gap, and comes to rest touching nothing
// (without the rule it does not slow so); one who follows a slower walker settles at the
// spacing Seyfried's relation gives for that speed, alike at 24 and 60 fps; one and two
// threads step a crowd that keeps time gaps alike; a walker follows a closed path round a
// corridor 0.8 m wide lap after lap (its bends drawn as segments once braked it to a stand);
// the file keeps the key and refuses what cannot be, with its line.
#include "TestRegistry.h"

#include "simcore/io/SceneIO.h"
#include "simcore/steering/Headway.h"
#include "simcore/world/World.h"

#include <QTest>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>

using namespace throng;
using namespace throng::sim;

namespace {

constexpr float kTimeGapS = 1.06f;

Scene parseHeadway(const std::string& yaml)
{
    const LoadResult r = parseScene(yaml, "headway.yaml", "");
    if (!r.ok())
        qFatal("%s\n%s", r.diagnostics[0].format().c_str(), yaml.c_str());
    return r.scene;
}

// A corridor 0.8 m wide along x from -1 to 200, too narrow to pass in; a walker type that
// keeps `timeGap` (none when empty), a slow type and a post that never moves; `agents` placed.
std::string corridorScene(const std::string& agents, double fps, const std::string& timeGap)
{
    std::ostringstream y;
    y << "throng: 1\nsettings: {fps: " << fps << ", seed: 3, duration: 90, bounds: {min: [-5, -5], max: [205, 5]}}\n"
      << "agent_types:\n"
      << "  - {name: walker, radius: 0.18, max_speed: 1.34" << (timeGap.empty() ? "" : ", time_gap: " + timeGap)
      << ", variation: {speed: [1, 1]}}\n"
      << "  - {name: slow, radius: 0.18, max_speed: 0.6, variation: {speed: [1, 1]}}\n"
      << "  - {name: post, radius: 0.18, max_speed: 0}\n"
      << "walls:\n  - {name: north, points: [[-1, -0.4], [200, -0.4]]}\n"
      << "  - {name: south, points: [[-1, 0.4], [200, 0.4]]}\n"
      << "goals:\n  - {name: east, position: [198, 0], radius: 1}\n"
      << "agents:\n" << agents;
    return y.str();
}

// How far agent i's body can go toward j's along i's ground heading `way` before touching.
float contactGap(glm::vec3 i, glm::vec3 j, float radii, glm::vec2 way)
{
    const glm::vec2 d(j.x - i.x, j.z - i.z);
    const float along = glm::dot(d, way), across = way.x * d.y - way.y * d.x;
    return along - std::sqrt(std::max(radii * radii - across * across, 0.0f));
}

}  // namespace

class TestHeadway : public QObject {
    Q_OBJECT
private slots:
    void theGapAheadIsTheDistanceToContact()
    {
        const glm::vec2 p(0.0f), east(1.0f, 0.0f);
        auto at = [](float x, float z, float r) {
            Neighbour n;
            n.position = glm::vec3(x, 0.0f, z);
            n.radius = r;
            return n;
        };
        // Straight ahead: the centres' distance less both radii.
        const Neighbour ahead[] = {at(2.0f, 0.0f, 0.2f)};
        QCOMPARE(freeGapAhead(p, 0.18f, east, ahead, 10.0f), 2.0f - 0.38f);
        // Aslant, 0.3 m to the side: contact where the discs first meet, 2 - sqrt(0.38² - 0.3²).
        const Neighbour aslant[] = {at(2.0f, 0.3f, 0.2f)};
        QVERIFY(std::abs(freeGapAhead(p, 0.18f, east, aslant, 10.0f) - (2.0f - std::sqrt(0.38f * 0.38f - 0.09f))) <
                1e-5f);
        // Beside the strip the body sweeps, behind, or beyond the reach: nothing in the way.
        const Neighbour clear[] = {at(1.0f, 0.39f, 0.2f), at(-1.0f, 0.0f, 0.2f), at(0.0f, 0.1f, 0.2f)};
        QCOMPARE(freeGapAhead(p, 0.18f, east, clear, 10.0f), 10.0f);
        // The nearest of several; one already touching leaves no gap at all.
        const Neighbour several[] = {at(5.0f, 0.0f, 0.2f), at(1.0f, -0.1f, 0.2f), at(3.0f, 0.0f, 0.2f)};
        QVERIFY(std::abs(freeGapAhead(p, 0.18f, east, several, 10.0f) - (1.0f - std::sqrt(0.38f * 0.38f - 0.01f))) <
                1e-5f);
        const Neighbour touching[] = {at(0.3f, 0.0f, 0.2f)};
        QCOMPARE(freeGapAhead(p, 0.18f, east, touching, 10.0f), 0.0f);
        QCOMPARE(headwaySpeed(1.06f, 1.06f, 1.34f), 1.0f);
        QCOMPARE(headwaySpeed(5.0f, 1.06f, 1.34f), 1.34f);
    }

    // A walker 20 m behind a post, in a corridor too narrow to pass, bound for the far end.
    void aWalkerStopsBehindOneStanding()
    {
        const std::string agents = "  - {id: 1, type: walker, position: [0, 0, 0], heading: 0, goal: east}\n"
                                   "  - {id: 2, type: post, position: [20, 0, 0], heading: 0}\n";
        auto closeIn = [&](const std::string& timeGap, float& worstExcessMps, float& lastGapM, float& minGapM) {
            World w(parseHeadway(corridorScene(agents, 24, timeGap)));
            worstExcessMps = -1e9f;
            minGapM = 1e9f;
            const float dt = 1.0f / 24.0f;
            while (w.timeS() < 60.0) {
                const glm::vec3 before = w.positions()[0], post = w.positions()[1];
                const float gap = contactGap(before, post, 0.36f, {1.0f, 0.0f});
                w.step();
                const float speed = glm::distance(w.positions()[0], before) / dt;
                worstExcessMps = std::max(worstExcessMps, speed - gap / kTimeGapS);
                minGapM = std::min(minGapM, contactGap(w.positions()[0], post, 0.36f, {1.0f, 0.0f}));
            }
            lastGapM = contactGap(w.positions()[0], w.positions()[1], 0.36f, {1.0f, 0.0f});
        };
        float excess = 0.0f, last = 0.0f, least = 0.0f;
        closeIn("1.06", excess, last, least);
        qInfo("with a time gap: at most %.4f m/s over gap / T; %.3f m left; nearest %.3f m", double(excess),
              double(last), double(least));
        QVERIFY2(excess <= 1e-3f, qPrintable(QString::number(excess)));
        QVERIFY2(least >= 0.0f && last < 0.05f, qPrintable(QString("%1 %2").arg(least).arg(last)));
        // Without the rule the walker comes on at full speed until its avoidance stops it.
        closeIn("", excess, last, least);
        qInfo("without: up to %.2f m/s over gap / T", double(excess));
        QVERIFY2(excess > 0.2f, qPrintable(QString::number(excess)));
    }

    // A walker 10 m behind a slower one (0.6 m/s, no rule of its own) closes up to the
    // spacing d = 0.36 m + 1.06 s x 0.6 m/s = 0.996 m and walks on at 0.6 m/s, at 24 fps
    // and at 60.
    void aFollowerKeepsItsTimeGapBehindASlowerWalker()
    {
        const std::string agents = "  - {id: 1, type: walker, position: [0, 0, 0], heading: 0, goal: east}\n"
                                   "  - {id: 2, type: slow, position: [10, 0, 0], heading: 0, goal: east}\n";
        float spacing[2] = {0.0f, 0.0f};
        int k = 0;
        for (const double fps : {24.0, 60.0}) {
            World w(parseHeadway(corridorScene(agents, fps, "1.06")));
            while (w.timeS() < 80.0)
                w.step();
            const glm::vec3 before = w.positions()[0];
            w.step();
            const float speed = glm::distance(w.positions()[0], before) * float(fps);
            spacing[k] = glm::distance(w.positions()[1], w.positions()[0]);
            qInfo("%.0f fps: spacing %.3f m at %.3f m/s", fps, double(spacing[k]), double(speed));
            QVERIFY2(std::abs(spacing[k] - (0.36f + kTimeGapS * 0.6f)) < 0.05f,
                     qPrintable(QString::number(spacing[k])));
            QVERIFY2(std::abs(speed - 0.6f) < 0.02f, qPrintable(QString::number(speed)));
            ++k;
        }
        QVERIFY2(std::abs(spacing[0] - spacing[1]) < 0.02f,
                 qPrintable(QString("%1 %2").arg(spacing[0]).arg(spacing[1])));
    }

    void oneAndTwoThreadsStepACrowdThatKeepsTimeGapsAlike()
    {
        std::ostringstream y;
        y << "throng: 1\nsettings: {fps: 24, seed: 5, duration: 60, bounds: {min: [-10, -60], max: [120, 60]}}\n"
             "agent_types:\n  - {name: walker, radius: 0.2, max_speed: 1.34, time_gap: 1.06}\n"
             "goals:\n  - {name: far, position: [110, 0], radius: 10}\n"
             "groups:\n  - {name: crowd, type: walker, count: 2400, rect: {min: [0, -50], max: [40, 50]}, goal: far}\n";
        const Scene s = parseHeadway(y.str());
        World one(s, WorldOptions{0, false, 1}), two(s, WorldOptions{0, false, 2});
        for (int k = 0; k < 5 * 24; ++k) {
            one.step();
            two.step();
        }
        for (const std::uint64_t chunks : two.team().chunksRun())
            QVERIFY2(chunks > 0, "a thread ran no chunk");
        for (std::size_t i = 0; i < one.agentCount(); ++i)
            QCOMPARE(two.positions()[i], one.positions()[i]);
    }

    // One walker on a closed path round a ring corridor 0.8 m wide (the RiMEA 16 scene's
    // shape: straights of 20 m, bends of 4 m radius drawn as 24 segments each, 65.1 m round)
    // goes round and round at about its speed, and never through a wall.
    void aWalkerGoesRoundANarrowRing()
    {
        auto stadium = [](float r) {
            std::vector<glm::vec2> pts{{0.0f, -r}, {20.0f, -r}};
            for (int k = 1; k < 24; ++k) {
                const float a = -1.5707963f + 3.14159265f * float(k) / 24.0f;
                pts.push_back({20.0f + r * std::cos(a), r * std::sin(a)});
            }
            pts.push_back({20.0f, r});
            pts.push_back({0.0f, r});
            for (int k = 1; k < 24; ++k) {
                const float a = 1.5707963f + 3.14159265f * float(k) / 24.0f;
                pts.push_back({r * std::cos(a), r * std::sin(a)});
            }
            return pts;
        };
        auto list = [](const std::vector<glm::vec2>& pts, bool close) {
            std::ostringstream o;
            o << "[";
            for (std::size_t k = 0; k < pts.size(); ++k)
                o << (k ? ", " : "") << "[" << pts[k].x << ", " << pts[k].y << "]";
            if (close)
                o << ", [" << pts[0].x << ", " << pts[0].y << "]";
            o << "]";
            return o.str();
        };
        std::ostringstream y;
        y << "throng: 1\nsettings: {fps: 24, seed: 16, duration: 120, bounds: {min: [-6, -6], max: [26, 6]}}\n"
          << "agent_types:\n  - {name: walker, radius: 0.18, max_speed: 1.34, time_gap: 1.06}\n"
          << "walls:\n  - {name: outer, points: " << list(stadium(4.4f), true) << "}\n"
          << "  - {name: inner, points: " << list(stadium(3.6f), true) << "}\n"
          << "paths:\n  - {name: ring, radius: 0.2, closed: true, points: " << list(stadium(4.0f), false) << "}\n"
          << "agents:\n  - {id: 1, type: walker, position: [0, 0, -4], heading: 0, path: ring}\n";
        World w(parseHeadway(y.str()));
        double walkedM = 0.0, stoodS = 0.0;
        int laps = 0;
        while (w.timeS() < 120.0) {
            const glm::vec3 before = w.positions()[0];
            w.step();
            const glm::vec3 after = w.positions()[0];
            walkedM += double(glm::distance(before, after));
            stoodS += glm::distance(before, after) < 0.2f / 24.0f ? 1.0 / 24.0 : 0.0;
            laps += before.z < 0.0f && before.x < 10.0f && after.x >= 10.0f ? 1 : 0;  // mid-way along the near straight
            const float fromCentre = after.x < 0.0f    ? glm::length(glm::vec2(after.x, after.z))
                                     : after.x > 20.0f ? glm::length(glm::vec2(after.x - 20.0f, after.z))
                                                       : std::abs(after.z);
            QVERIFY2(fromCentre > 3.6f + 0.1f && fromCentre < 4.4f - 0.1f,
                     qPrintable(QString("at (%1, %2)").arg(after.x).arg(after.z)));
        }
        qInfo("%d laps, %.1f m in 120 s, %.1f s standing", laps, walkedM, stoodS);
        // 120 s at 1.2 to 1.34 m/s is 144 to 161 m: over two laps of 65.1 m.
        QVERIFY2(laps >= 2 && walkedM > 140.0 && stoodS < 1.0, qPrintable(QString::number(walkedM)));
    }

    void theFileKeepsTheTimeGapAndRefusesWhatCannotBe()
    {
        const std::string agents = "  - {id: 1, type: walker, position: [0, 0, 0], heading: 0, goal: east}\n";
        const Scene kept = parseHeadway(corridorScene(agents, 24, "1.06"));
        QCOMPARE(kept.agentTypes[0].timeGapS, 1.06f);
        QCOMPARE(kept.agentTypes[1].timeGapS, 0.0f);
        const std::string yaml = sceneToYaml(kept);
        QVERIFY(yaml.find("time_gap: 1.06") != std::string::npos);
        QVERIFY(parseHeadway(yaml) == kept);
        QVERIFY(sceneToYaml(parseHeadway(corridorScene(agents, 24, ""))).find("time_gap") == std::string::npos);

        const LoadResult negative = parseScene(corridorScene(agents, 24, "-1"), "bad.yaml", "");
        QVERIFY(!negative.ok());
        QVERIFY2(negative.diagnostics[0].format().find("bad.yaml:4") != std::string::npos &&
                     negative.diagnostics[0].format().find("time_gap") != std::string::npos,
                 negative.diagnostics[0].format().c_str());
        // A vehicle keeps no time gap (lanes' car following does that): a warning, and none kept.
        std::string vehicle = corridorScene(agents, 24, "");
        vehicle.replace(vehicle.find("max_speed: 0}"), 13, "max_speed: 0, kind: vehicle, time_gap: 2}");
        const LoadResult v = parseScene(vehicle, "vehicle.yaml", "");
        QVERIFY(v.ok());
        QVERIFY(!v.diagnostics.empty() && v.diagnostics[0].format().find("warning") != std::string::npos &&
                v.diagnostics[0].format().find("time_gap") != std::string::npos);
        QCOMPARE(v.scene.agentTypes[2].timeGapS, 0.0f);
    }
};

THRONG_REGISTER_TEST(TestHeadway)
#include "TestHeadway.moc"
