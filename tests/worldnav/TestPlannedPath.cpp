// Paths marked `plan: astar`: the route between the waypoints is planned round walls and
// obstacles at load. The cavalry leader's route never comes within the cones' inflated
// radius, is as short as the grid's A* optimum allows, and keeps its waypoints; a small
// planned path goes round a wall a straight one would cross; the key reads, writes back
// and is checked.
#include "NavRig.h"
#include "TestRegistry.h"

#include "simcore/nav/PathPlanning.h"

#include <glm/geometric.hpp>

#include <QTest>

#include <algorithm>

using namespace throng::sim;
using throng::test::parse;

namespace {

float pointSegmentDistance(glm::vec2 p, glm::vec2 a, glm::vec2 b)
{
    const glm::vec2 d = b - a;
    const float t = std::clamp(glm::dot(p - a, d) / std::max(glm::dot(d, d), 1e-12f), 0.0f, 1.0f);
    return glm::distance(p, a + t * d);
}

float length(const std::vector<glm::vec2>& points)
{
    float l = 0.0f;
    for (std::size_t k = 1; k < points.size(); ++k)
        l += glm::distance(points[k - 1], points[k]);
    return l;
}

bool segmentsCross(glm::vec2 a, glm::vec2 b, glm::vec2 c, glm::vec2 d)
{
    auto side = [](glm::vec2 p, glm::vec2 q, glm::vec2 r) { return (q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x); };
    return side(a, b, c) * side(a, b, d) < 0.0f && side(c, d, a) * side(c, d, b) < 0.0f;
}

}  // namespace

class TestPlannedPath : public QObject {
    Q_OBJECT
private slots:
    void cavalryRouteKeepsClearOfEveryCone()
    {
        const Scene scene = throng::test::loadDemo("cavalry.yaml");
        const auto route = std::find_if(scene.paths.begin(), scene.paths.end(), [](const Path& p) { return p.name == "route"; });
        QVERIFY(route != scene.paths.end());
        QVERIFY(route->planned);
        QCOMPARE(route->clearanceM, 3.0f);
        QVERIFY(scene.obstacles.size() > 800);

        const PlannedPath planned = planPath(scene, *route);
        QVERIFY2(planned.ok(), planned.error.c_str());
        // The waypoints are kept, in order, and the way bends round cones between them.
        QCOMPARE(planned.points.front(), route->points.front());
        QCOMPARE(planned.points.back(), route->points.back());
        std::size_t next = 0;
        for (glm::vec2 p : planned.points)
            if (next < route->points.size() && p == route->points[next])
                ++next;
        QCOMPARE(next, route->points.size());
        QVERIFY2(planned.points.size() > route->points.size() + 5, qPrintable(QString::number(planned.points.size())));

        // Never within a cone's radius plus the clearance, anywhere along the way.
        float closest = 1e9f;
        for (const Obstacle& cone : scene.obstacles)
            for (std::size_t k = 1; k < planned.points.size(); ++k)
                closest = std::min(closest, pointSegmentDistance(cone.center, planned.points[k - 1], planned.points[k]) - cone.radiusM);
        // Short: within a few % of the A* optimum on the 8-connected grid (string pulling
        // only ever shortens it), and no shorter than the straight line through the waypoints.
        const float straight = length(route->points);
        qInfo("route: %zu points, %.1f m (straight through the waypoints %.1f m, grid A* %.1f m), closest to a cone "
              "surface %.2f m",
              planned.points.size(), double(planned.lengthM), double(straight), double(planned.gridLengthM), double(closest));
        QVERIFY2(closest > route->clearanceM, qPrintable(QString::number(double(closest))));
        QCOMPARE(planned.lengthM, length(planned.points));
        QVERIFY(planned.lengthM >= straight);
        QVERIFY(planned.lengthM <= planned.gridLengthM + 1.0f);
        QVERIFY(planned.lengthM >= 0.95f * planned.gridLengthM);

        // The World rides the planned way, not the waypoints' straight lines.
        const std::vector<Path> paths = plannedPaths(scene);
        QCOMPARE(paths[std::size_t(route - scene.paths.begin())].points, planned.points);
    }

    void plannedPathGoesRoundAWall()
    {
        const Scene scene = parse(R"(throng: 1
settings: {fps: 24, bounds: {min: [-10, -10], max: [10, 10]}, nav_cell: 0.25}
walls:
  - {points: [[0, -4], [0, 4]]}
paths:
  - {name: round, radius: 1, plan: astar, clearance: 0.5, points: [[-5, 0], [5, 0]]}
  - {name: straight, radius: 1, points: [[-5, 0], [5, 0]]}
)");
        QVERIFY(scene.paths[0].planned && !scene.paths[1].planned);
        const std::vector<Path> paths = plannedPaths(scene);
        QCOMPARE(paths[1].points, scene.paths[1].points);  // unplanned paths stay as written
        const std::vector<glm::vec2>& way = paths[0].points;
        QVERIFY(way.size() >= 3);
        for (std::size_t k = 1; k < way.size(); ++k) {
            QVERIFY(!segmentsCross(way[k - 1], way[k], {0.0f, -4.0f}, {0.0f, 4.0f}));
            QVERIFY(pointSegmentDistance({0.0f, 4.0f}, way[k - 1], way[k]) > 0.5f || pointSegmentDistance({0.0f, -4.0f}, way[k - 1], way[k]) > 0.5f);
        }
        // Round one end of the wall: the shortest way is about 2 * sqrt(5^2 + 4.5^2) = 13.5 m.
        const float l = length(way);
        QVERIFY2(l > 13.4f && l < 14.2f, qPrintable(QString::number(double(l))));
        // A walled-in waypoint cannot be reached: the leg stays straight and says so.
        Scene shut = scene;
        shut.walls.push_back({"box", {{4, -1}, {6, -1}, {6, 1}, {4, 1}, {4, -1}}});
        std::vector<std::string> errors;
        plannedPaths(shut, &errors);
        QCOMPARE(errors.size(), std::size_t(1));
        QVERIFY2(errors[0].find("path 'round'") != std::string::npos, errors[0].c_str());
    }

    void planKeyRoundTripsAndBadValuesAreLocated()
    {
        const Scene scene = parse(R"(throng: 1
paths:
  - {name: round, radius: 1, plan: astar, clearance: 0.75, points: [[-5, 0], [5, 0]]}
)");
        const LoadResult again = parseScene(sceneToYaml(scene), "again.yaml", ".");
        QVERIFY(again.ok());
        QCOMPARE(again.scene.paths, scene.paths);
        QCOMPARE(again.scene.paths[0].clearanceM, 0.75f);

        const LoadResult bad = parseScene("throng: 1\npaths:\n  - {name: p, plan: dijkstra, points: [[0, 0], [1, 0]]}\n",
                                          "bad.yaml", ".");
        QVERIFY(!bad.ok());
        const std::string message = bad.diagnostics[0].format();
        QVERIFY2(message.find("bad.yaml:3:") != std::string::npos && message.find("dijkstra") != std::string::npos,
                 message.c_str());
    }
};

THRONG_REGISTER_TEST(TestPlannedPath)
#include "TestPlannedPath.moc"
