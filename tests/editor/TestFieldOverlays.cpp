// The viewport's field overlays without GL: the sketched field's arrows follow a stroke and
// keep out of walls, a goal's arrows lead down an L-shaped corridor and round its corner,
// the arrow count stays under its cap on a 1 km set, and the density heatmap gives persons
// per m² (LocalDensity's kernel) on a colour scale that starts transparent. And the
// steering overlay draws the field a watched agent follows: an arrow from each sample
// along its direction, none where the field gives none.
#include "TestRegistry.h"

#include "editor/viewport/DensityHeatmap.h"
#include "editor/viewport/FieldArrows.h"
#include "editor/viewport/ShapeMesh.h"
#include "editor/viewport/SteeringOverlay.h"
#include "editor/viewport/ViewportPalette.h"
#include "simcore/world/LocalDensity.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <QElapsedTimer>
#include <QTest>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

using namespace throng;
using namespace throng::editor;

namespace {

constexpr float kInflateM = 0.45f;  // a default walker's body plus clearance (no navigating walkers)

float angleDeg(glm::vec2 a, glm::vec2 b)
{
    return glm::degrees(std::acos(std::clamp(glm::dot(glm::normalize(a), glm::normalize(b)), -1.0f, 1.0f)));
}

float distanceToSegment(glm::vec2 p, glm::vec2 a, glm::vec2 b)
{
    const glm::vec2 ab = b - a;
    const float t = std::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.0f, 1.0f);
    return glm::distance(p, a + t * ab);
}

float distanceToWalls(glm::vec2 p, const sim::Scene& scene)
{
    float best = INFINITY;
    for (const sim::Wall& w : scene.walls)
        for (std::size_t i = 0; i + 1 < w.points.size(); ++i)
            best = std::min(best, distanceToSegment(p, w.points[i], w.points[i + 1]));
    return best;
}

// A stroke along +x through the middle of a 30 m set, with a wall beside it.
sim::Scene strokeScene()
{
    sim::Scene s;
    s.settings.boundsMin = glm::vec2(-15.0f);
    s.settings.boundsMax = glm::vec2(15.0f);
    s.settings.navCellM = 0.5f;
    s.flowStrokes.push_back({{{-10.0f, 0.0f}, {10.0f, 0.0f}}, 2.0f});
    s.walls.push_back({"side", {{-4.0f, 2.0f}, {4.0f, 2.0f}}});
    return s;
}

// A corridor 4 m wide, closed at both ends: west to east along z = 0, then south (+z) to
// a goal near its far end.
sim::Scene corridorScene()
{
    sim::Scene s;
    s.settings.boundsMin = glm::vec2(-16.0f);
    s.settings.boundsMax = glm::vec2(16.0f);
    s.settings.navCellM = 0.5f;
    s.walls.push_back({"corridor", {{-15.0f, -2.0f}, {5.0f, -2.0f}, {5.0f, 15.0f}, {1.0f, 15.0f}, {1.0f, 2.0f},
                                    {-15.0f, 2.0f}, {-15.0f, -2.0f}}});
    s.goals.push_back({"end", {3.0f, 13.0f}, 1.0f, false});
    return s;
}

bool inCorridor(glm::vec2 p)
{
    const bool westEast = p.x > -15.0f && p.x < 5.0f && p.y > -2.0f && p.y < 2.0f;
    const bool south = p.x > 1.0f && p.x < 5.0f && p.y > -2.0f && p.y < 15.0f;
    return westEast || south;
}

}  // namespace

class TestFieldOverlays : public QObject {
    Q_OBJECT

private slots:
    void sketchArrowsFollowTheStrokeAndKeepOutOfWalls()
    {
        const sim::Scene scene = strokeScene();
        FieldArrows fields;
        QVERIFY(fields.setScene(scene));
        QVERIFY2(fields.hasSketch(), fields.sketchError().c_str());
        QVERIFY(fields.sketchError().empty());

        const float spacing = 0.5f;
        const std::vector<FieldArrow> arrows = fields.sketchArrows(spacing);
        int nearStroke = 0, besideWall = 0;
        for (const FieldArrow& a : arrows) {
            QVERIFY(std::abs(glm::length(a.direction) - 1.0f) < 1e-4f);
            QVERIFY(a.lengthM > 0.0f && a.lengthM <= 0.8f * spacing + 1e-6f);
            // Nothing in a blocked cell: by the grid, and by the geometry itself.
            QVERIFY(fields.grid().walkable(fields.grid().cellOf(a.centre)));
            const float fromWall = distanceToWalls(a.centre, scene);
            QVERIFY2(fromWall > kInflateM, qPrintable(QString("arrow at (%1, %2), %3 m from the wall")
                                                          .arg(a.centre.x).arg(a.centre.y).arg(fromWall)));
            besideWall += fromWall < 1.0f ? 1 : 0;
            if (std::abs(a.centre.y) < 1.0f && std::abs(a.centre.x) < 8.0f) {
                ++nearStroke;
                QVERIFY2(angleDeg(a.direction, {1.0f, 0.0f}) < 15.0f,
                         qPrintable(QString("arrow at (%1, %2) points (%3, %4)")
                                        .arg(a.centre.x).arg(a.centre.y).arg(a.direction.x).arg(a.direction.y)));
                // On the stroke the field is about as strong as a stroke sample (1).
                QVERIFY(a.lengthM >= 0.6f * spacing);
            }
        }
        // 32 columns by 4 rows of grid points lie within 1 m of the stroke's middle 16 m.
        QCOMPARE(nearStroke, 32 * 4);
        // The wall's margin is not left out because the field is absent there.
        QVERIFY(besideWall >= 16);

        ShapeMesh mesh;
        fields.addSketchArrows(mesh, spacing);
        QCOMPARE(mesh.vertices().size(), 9 * arrows.size());
        for (const ShapeVertex& v : mesh.vertices())
            QCOMPARE(v.colour, FieldArrows::kSketchColour);
    }

    void sketchErrorIsReportedNotThrown()
    {
        sim::Scene scene = strokeScene();
        scene.flowStrokes = {{{{1.0f, 1.0f}, {1.0f, 1.0f}}, 2.0f}};  // no length: no sample
        FieldArrows fields;
        QVERIFY(fields.setScene(scene));
        QVERIFY(!fields.hasSketch());
        QVERIFY(!fields.sketchError().empty());
        QVERIFY(fields.sketchArrows(1.0f).empty());
        ShapeMesh mesh;
        fields.addSketchArrows(mesh, 1.0f);
        QVERIFY(mesh.empty());

        scene.flowStrokes.clear();
        QVERIFY(fields.setScene(scene));
        QVERIFY(!fields.hasSketch());
        QVERIFY(fields.sketchError().empty());
    }

    // The viewport keeps only partsOf(scene): a wide flow-field walker placed there (among
    // many) still widens the walls' margins as in the whole scene.
    void partsBuildWhatTheWholeSceneBuilds()
    {
        sim::Scene scene = strokeScene();
        // The wall 0.6 m from the centres of the cells north of it (z 2.5 to 3): within the
        // wide walker's margin (0.5 + 0.15 m), beyond the default walker's (0.3 + 0.15 m).
        scene.walls[0].points = {{-4.0f, 2.15f}, {4.0f, 2.15f}};
        sim::AgentType wide;
        wide.name = "wide";
        wide.radiusM = 0.5f;
        wide.navigation = sim::Navigation::FlowField;
        scene.agentTypes.push_back(wide);
        for (std::uint32_t id = 1; id <= 50; ++id) {
            sim::Agent a;
            a.id = id;
            a.type = "wide";
            a.position = {-10.0f + 0.3f * float(id), 0.0f, -8.0f};
            scene.agents.push_back(a);
        }
        const sim::Scene parts = FieldArrows::partsOf(scene);
        QCOMPARE(parts.agents.size(), std::size_t(1));
        FieldArrows whole, kept;
        QVERIFY(whole.setScene(scene));
        QVERIFY(kept.setScene(parts));
        QVERIFY(!whole.setScene(parts));  // the same fields: nothing to build again
        const sim::NavCell nearWall = whole.grid().cellOf({0.0f, 2.6f});
        QCOMPARE(kept.grid().walkable(nearWall), whole.grid().walkable(nearWall));
        QVERIFY(!kept.grid().walkable(nearWall));  // inside the wide walker's margin
        // Without its walkers the same set leaves that cell walkable: the check tells.
        sim::Scene bare = parts;
        bare.agents.clear();
        FieldArrows thin;
        QVERIFY(thin.setScene(bare));
        QVERIFY(thin.grid().walkable(nearWall));
        QCOMPARE(kept.sketchArrows(1.0f).size(), whole.sketchArrows(1.0f).size());
    }

    void setSceneRebuildsOnlyWhenTheFieldsChange()
    {
        sim::Scene scene = strokeScene();
        FieldArrows fields;
        QVERIFY(fields.setScene(scene));
        QVERIFY(!fields.setScene(scene));
        scene.paths.push_back({"p", {{0.0f, 0.0f}, {5.0f, 5.0f}}});
        scene.agentTypes.push_back({});
        scene.agentTypes.back().name = "direct";
        scene.agents.push_back({});
        scene.agents.back().id = 1;
        scene.agents.back().type = "direct";
        QVERIFY(!fields.setScene(scene));  // a path and a direct walker change no field

        const sim::NavCell inMargin = fields.grid().cellOf({0.0f, 2.0f});
        QVERIFY(!fields.grid().walkable(inMargin));
        scene.walls[0].points = {{-4.0f, 5.85f}, {4.0f, 5.85f}};
        QVERIFY(fields.setScene(scene));
        QVERIFY(fields.grid().walkable(inMargin));

        // A walker that navigates by a flow field widens every wall's margin: the cell whose
        // centre lies 0.6 m from the wall is in the wide walker's (0.5 + 0.15 m), not in the
        // default walker's (0.3 + 0.15 m).
        const sim::NavCell nextToMargin = fields.grid().cellOf({0.0f, 5.4f});
        QVERIFY(fields.grid().walkable(nextToMargin));
        scene.agentTypes.back().navigation = sim::Navigation::FlowField;
        scene.agentTypes.back().radiusM = 0.5f;
        QVERIFY(fields.setScene(scene));
        QVERIFY(!fields.grid().walkable(nextToMargin));
    }

    void kerbsAndCrosswalkSidesBlockAsWalkersMeetThem()
    {
        // A road 4 m wide: its kerbs are walls to walkers (World::appendKerbs), except
        // where a crosswalk crosses it; the crosswalk's sides are walls too.
        sim::Scene scene;
        scene.settings.boundsMin = glm::vec2(-15.0f);
        scene.settings.boundsMax = glm::vec2(15.0f);
        sim::Lane road;
        road.name = "road";
        road.points = {{-10.0f, 0.0f}, {10.0f, 0.0f}};
        road.widthM = 4.0f;
        road.loop = false;
        scene.lanes.push_back(road);
        FieldArrows fields;
        fields.setScene(scene);
        auto walkable = [&](glm::vec2 p) { return fields.grid().walkable(fields.grid().cellOf(p)); };
        QVERIFY(walkable({0.1f, 3.0f}) && walkable({0.1f, 0.0f}));
        QVERIFY(!walkable({0.1f, 2.0f}) && !walkable({0.1f, -2.0f}));

        scene.crosswalks.push_back({"zebra", {0.0f, -4.0f}, {0.0f, 4.0f}, 3.0f});
        QVERIFY(fields.setScene(scene));
        QVERIFY(walkable({0.1f, 2.0f}) && walkable({0.1f, -2.0f}));
        QVERIFY(!walkable({1.2f, 0.0f}) && !walkable({1.2f, 3.0f}));
        QVERIFY(walkable({3.0f, 0.0f}));
    }

    void goalArrowsLeadRoundTheCorridorCorner()
    {
        const sim::Scene scene = corridorScene();
        FieldArrows fields;
        fields.setScene(scene);
        QCOMPARE(fields.goalCount(), std::size_t(1));
        QVERIFY(fields.goalArrows(1, 0.5f).empty());

        const std::vector<FieldArrow> arrows = fields.goalArrows(0, 0.5f);
        const glm::vec2 kInnerCorner(1.5f, 1.5f), goal = scene.goals[0].position;
        int westEast = 0, corner = 0, turned = 0, south = 0;
        for (const FieldArrow& a : arrows) {
            const glm::vec2 p = a.centre, d = a.direction;
            const QString where = QString("arrow at (%1, %2) points (%3, %4)").arg(p.x).arg(p.y).arg(d.x).arg(d.y);
            // Outside the corridor nothing reaches the goal; inside, nothing in a wall's margin.
            QVERIFY2(inCorridor(p), qPrintable(where));
            QVERIFY2(distanceToWalls(p, scene) > kInflateM, qPrintable(where));
            QVERIFY(fields.grid().walkable(fields.grid().cellOf(p)));
            if (p.x < -5.0f) {
                // Along the west-east leg: the shortest way leads straight at the inner
                // corner (its wall margin ends at about (1.5, 1.5)), up to 22 degrees off
                // the leg's axis here, never back west.
                ++westEast;
                QVERIFY2(angleDeg(d, kInnerCorner - p) < 10.0f, qPrintable(where));
            } else if (p.x <= 1.0f) {
                QVERIFY2(d.x > 0.0f, qPrintable(where));  // cutting towards the corner, still eastwards
            } else if (p.y < 2.0f) {
                // The corner square: south or east, never back (the goal lies at most 5
                // degrees west of south from here); most already straight at the goal, the
                // rest still bending round the inner wall's margin.
                ++corner;
                QVERIFY2(d.y >= 0.0f && d.x > -0.2f, qPrintable(where));
                turned += angleDeg(d, goal - p) < 10.0f ? 1 : 0;
            } else if (p.y > 4.0f && p.y < 11.0f) {
                // Down the south leg, in sight of the goal: straight at it.
                ++south;
                QVERIFY2(angleDeg(d, goal - p) < 10.0f, qPrintable(where));
            }
        }
        qInfo("corridor arrows: %d west-east, %d in the corner, %d south", westEast, corner, south);
        QVERIFY(westEast >= 100);
        QVERIFY(corner >= 10);
        qInfo("corner square: %d of %d arrows straight at the goal", turned, corner);
        QVERIFY(turned >= corner * 3 / 4);
        QVERIFY(south >= 30);

        ShapeMesh mesh;
        fields.addGoalArrows(0, mesh, 0.5f);
        QCOMPARE(mesh.vertices().size(), 9 * arrows.size());
        for (const ShapeVertex& v : mesh.vertices())
            QCOMPARE(v.colour, FieldArrows::kGoalColour);
        QVERIFY(FieldArrows::kGoalColour != FieldArrows::kSketchColour);
    }

    void spacingKeepsTheArrowCountUnderTheCap()
    {
        const glm::vec2 lo(-500.0f), hi(500.0f);
        const float spacing = FieldArrows::spacingFor(lo, hi, 0.5f);
        const std::size_t points = FieldArrows::gridPointCount(lo, hi, spacing);
        qInfo("1 km bounds: spacing %.2f m, %zu grid points", double(spacing), points);
        QVERIFY(points <= FieldArrows::kMaxArrows);
        QVERIFY(points > FieldArrows::kMaxArrows * 9 / 10);  // no coarser than the cap needs
        // Small bounds keep the spacing asked for.
        QCOMPARE(FieldArrows::spacingFor(glm::vec2(-10.0f), glm::vec2(10.0f), 1.0f), 1.0f);

        // A far-too-fine spacing asked of a 1 km set is raised, not drawn.
        sim::Scene scene;
        scene.settings.boundsMin = lo;
        scene.settings.boundsMax = hi;
        scene.settings.navCellM = 2.0f;
        scene.goals.push_back({"centre", {0.0f, 0.0f}, 1.0f, false});
        FieldArrows fields;
        fields.setScene(scene);
        const std::vector<FieldArrow> arrows = fields.goalArrows(0, 0.1f);
        qInfo("1 km open set: %zu goal arrows", arrows.size());
        QVERIFY(arrows.size() <= FieldArrows::kMaxArrows);
        QVERIFY(arrows.size() > FieldArrows::kMaxArrows * 9 / 10);
    }

    void uniformCrowdGivesItsDensity()
    {
        // 100 agents on a jittered 1 m lattice over the square [0, 10]².
        std::vector<glm::vec3> agents;
        for (int z = 0; z < 10; ++z)
            for (int x = 0; x < 10; ++x) {
                // (Not multiples of 0.5 m: no agent on the kernel's rim, where rounding decides.)
                const float jx = 0.13f * float((x * 7 + z * 3) % 5 - 2), jz = 0.13f * float((x * 3 + z * 5) % 5 - 2);
                agents.push_back({float(x) + 0.5f + jx, 0.0f, float(z) + 0.5f + jz});
            }
        DensityHeatmap map;
        map.build(agents, glm::vec2(-50.0f), glm::vec2(50.0f));
        QCOMPARE(map.cellM(), 1.0f);
        QCOMPARE(map.sigmaM(), sim::kDensitySigmaM);

        const float middle = map.densityAt({5.2f, 5.2f});
        qInfo("uniform 1/m^2: %.3f in the middle, max %.3f", double(middle), double(map.maxDensity()));
        QVERIFY(std::abs(middle - 1.0f) < 0.25f);
        QCOMPARE(map.densityAt({30.0f, 30.0f}), 0.0f);
        QCOMPARE(map.densityAt({-60.0f, 0.0f}), 0.0f);
        QVERIFY(map.maxDensity() >= middle);

        // The value is LocalDensity's at the cell's centre.
        float expected = 0.0f;
        for (const glm::vec3& a : agents) {
            const glm::vec2 d = glm::vec2(a.x, a.z) - glm::vec2(5.5f, 5.5f);
            expected += sim::densityWeight(glm::dot(d, d));
        }
        QVERIFY(std::abs(middle - expected) < 1e-4f * expected);
    }

    void packedSquareGivesFourPerSquareMetre()
    {
        // 16 agents 0.5 m apart filling the 2 x 2 m square centred on the cell centre (10.5, 10.5).
        std::vector<glm::vec3> agents;
        for (int z = 0; z < 4; ++z)
            for (int x = 0; x < 4; ++x)
                agents.push_back({9.75f + 0.5f * float(x), 0.0f, 9.75f + 0.5f * float(z)});
        DensityHeatmap map;
        map.build(agents, glm::vec2(-50.0f), glm::vec2(50.0f));
        const float centre = map.densityAt({10.5f, 10.5f});
        qInfo("packed 4/m^2: %.3f at the centre", double(centre));
        QVERIFY(std::abs(centre - 4.0f) < 0.25f * 4.0f);
        QCOMPARE(map.maxDensity(), centre);
        QVERIFY(map.densityAt({10.5f, 14.5f}) < 0.1f);
    }

    void cachedFrameLeavesOutAgentsNotInTheShot()
    {
        std::vector<sim::AgentFrame> frame(3);
        for (sim::AgentFrame& a : frame)
            a.position = {0.5f, 0.0f, 0.5f};
        frame[1].out = true;
        frame[2].present = false;
        DensityHeatmap map;
        map.build(frame, glm::vec2(-10.0f), glm::vec2(10.0f));
        QCOMPARE(map.densityAt({0.5f, 0.5f}), sim::densityWeight(0.0f));
    }

    void bigBoundsGetFewerBiggerCellsThatStillCountEveryone()
    {
        const std::vector<glm::vec3> one{{12.3f, 0.0f, -45.6f}};
        DensityHeatmap map;
        map.build(one, glm::vec2(-500.0f), glm::vec2(500.0f));
        qInfo("1 km bounds: %d x %d cells of %.2f m, sigma %.2f m", map.cols(), map.rows(), double(map.cellM()),
              double(map.sigmaM()));
        QVERIFY(std::size_t(map.cols()) * std::size_t(map.rows()) <= DensityHeatmap::kMaxCells);
        QVERIFY(map.cellM() >= 5.0f);
        // One person spread over the cells still sums to about one person.
        float persons = 0.0f;
        for (int z = 0; z < map.rows(); ++z)
            for (int x = 0; x < map.cols(); ++x)
                persons += map.densityAt(glm::vec2(-500.0f) + (glm::vec2(float(x), float(z)) + 0.5f) * map.cellM()) *
                           map.cellM() * map.cellM();
        QVERIFY(std::abs(persons - 1.0f) < 0.05f);
        QVERIFY(map.densityAt({12.3f, -45.6f}) > 0.0f);
    }

    void colourScaleStartsTransparentAndRisesInRed()
    {
        QCOMPARE(DensityHeatmap::colourFor(0.0f).a, 0.0f);
        QCOMPARE(DensityHeatmap::colourFor(-1.0f).a, 0.0f);
        QVERIFY(DensityHeatmap::colourFor(0.5f).a > 0.0f);
        float red = DensityHeatmap::colourFor(0.0f).r;
        for (float d = 0.01f; d <= 10.0f; d += 0.01f) {
            const float r = DensityHeatmap::colourFor(d).r;
            QVERIFY2(r >= red, qPrintable(QString("red falls at %1/m^2").arg(d)));
            red = r;
        }
        QVERIFY(DensityHeatmap::colourFor(6.0f).r > DensityHeatmap::colourFor(1.0f).r + 0.5f);
        QCOMPARE(DensityHeatmap::colourFor(100.0f), DensityHeatmap::colourFor(6.0f));
        // The legend's stops: 0, 1, 2, 4, 6 per m², each colour the scale gives there.
        const std::span<const DensityHeatmap::ScaleStop> stops = DensityHeatmap::scale();
        QCOMPARE(stops.size(), std::size_t(5));
        for (std::size_t i = 0; i < stops.size(); ++i) {
            QVERIFY(i == 0 || stops[i].density > stops[i - 1].density);
            QCOMPARE(DensityHeatmap::colourFor(stops[i].density), stops[i].colour);
        }

        // Nobody: nothing drawn. One agent: a few cells, two triangles each.
        DensityHeatmap map;
        ShapeMesh mesh;
        map.build(std::span<const glm::vec3>(), glm::vec2(-10.0f), glm::vec2(10.0f));
        map.addCells(mesh);
        QVERIFY(mesh.empty());
        const std::vector<glm::vec3> one{{0.5f, 0.0f, 0.5f}};
        map.build(one, glm::vec2(-10.0f), glm::vec2(10.0f));
        map.addCells(mesh);
        QVERIFY(!mesh.empty());
        QCOMPARE(mesh.vertices().size() % 6, std::size_t(0));
        QVERIFY(mesh.vertices().size() <= 6 * 9);
    }

    void hundredThousandAgentsBuildQuickly()
    {
        std::mt19937 rng(7);
        std::uniform_real_distribution<float> u(-50.0f, 50.0f);
        std::vector<glm::vec3> agents(100000);
        for (glm::vec3& a : agents)
            a = {u(rng), 0.0f, u(rng)};
        DensityHeatmap map;
        map.build(agents, glm::vec2(-50.0f), glm::vec2(50.0f));  // warm the allocations
        // The fastest of five says what the code costs; on a busy machine the slowest says
        // more about the neighbours.
        std::vector<double> ms;
        for (int run = 0; run < 5; ++run) {
            QElapsedTimer timer;
            timer.start();
            map.build(agents, glm::vec2(-50.0f), glm::vec2(50.0f));
            ms.push_back(double(timer.nsecsElapsed()) * 1e-6);
        }
        std::sort(ms.begin(), ms.end());
        qInfo("100,000 agents: heatmap built in %.2f ms (fastest of 5; median %.2f ms)", ms.front(), ms[2]);
        // 10 per m² on average away from the edges.
        double sum = 0.0;
        int cells = 0;
        for (float z = -40.5f; z < 40.0f; z += 1.0f)
            for (float x = -40.5f; x < 40.0f; x += 1.0f, ++cells)
                sum += double(map.densityAt({x, z}));
        QVERIFY(std::abs(sum / double(cells) - 10.0) < 0.5);
    }

    void steeringOverlayDrawsTheFieldAnAgentFollows()
    {
        sim::AgentDebug a;
        a.id = 1;
        // Three samples with a direction, two without (on a wall's cells), far apart.
        const std::vector<sim::AgentDebug::FieldSample> samples{
            {{0.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}},   {{5.0f, 0.0f, 0.0f}, {0.0f, 0.0f, -1.0f}},
            {{10.0f, 0.0f, 0.0f}, {0.6f, 0.0f, 0.8f}},  {{0.0f, 0.0f, 5.0f}, {0.0f, 0.0f, 0.0f}},
            {{5.0f, 0.0f, 5.0f}, {0.0f, 0.0f, 0.0f}}};
        a.field = samples;
        auto fieldVertices = [](const sim::AgentDebug& agent) {
            ShapeMesh mesh;
            SteeringOverlay::add(std::span(&agent, 1), mesh);
            std::vector<glm::vec2> out;
            for (const ShapeVertex& v : mesh.vertices())
                if (v.colour == palette::kFlowArrow)
                    out.emplace_back(v.position.x, v.position.z);
            return out;
        };
        const std::vector<glm::vec2> drawn = fieldVertices(a);
        for (const sim::AgentDebug::FieldSample& f : samples) {
            const glm::vec2 at(f.at.x, f.at.z), dir(f.direction.x, f.direction.z);
            auto near = [&](glm::vec2 q, float within) {
                return std::any_of(drawn.begin(), drawn.end(),
                                   [&](glm::vec2 p) { return glm::distance(p, q) < within; });
            };
            if (dir == glm::vec2(0.0f)) {
                QVERIFY2(!near(at, 1.0f), "an arrow where the field gives no direction");
            } else {
                // From the sample, a third of a metre or so along its direction.
                QVERIFY(near(at, 0.1f));
                QVERIFY2(near(at + dir * 0.35f, 0.1f),
                         qPrintable(QString("no tip along (%1, %2)").arg(dir.x).arg(dir.y)));
                QVERIFY(!near(at - dir * 0.35f, 0.2f));
            }
        }
        a.field.clear();
        QVERIFY(fieldVertices(a).empty());
    }
};

THRONG_REGISTER_TEST(TestFieldOverlays)
#include "TestFieldOverlays.moc"
