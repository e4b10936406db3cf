// Where a crowd-brush dab puts agents, checked as an artist would: about the density
// asked for, never two closer than the spacing, none inside a wall or obstacle or out of
// bounds, facing along the stroke when asked, and the same dab twice gives the same crowd.
#include "TestRegistry.h"

#include "editor/tools/CrowdBrushPlacement.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <QTest>

#include <cmath>
#include <numbers>

using namespace throng;
using namespace throng::editor;

namespace {

sim::Scene openGround()
{
    sim::Scene s;
    sim::AgentType walker;
    walker.name = "walker";
    walker.radiusM = 0.3f;
    sim::AgentType cart = walker;
    cart.name = "cart";
    cart.kind = sim::AgentKind::Vehicle;
    s.agentTypes = {walker, cart};
    return s;
}

glm::vec2 ground(const sim::Agent& a)
{
    return {a.position.x, a.position.z};
}

}  // namespace

class TestCrowdBrushPlacement : public QObject {
    Q_OBJECT

private slots:
    void fillsTheDiskToTheDensityWithTheSpacingKept()
    {
        const sim::Scene scene = openGround();
        CrowdBrushSettings settings;
        settings.radiusM = 5.0f;
        settings.densityPerM2 = 0.4f;
        settings.minSpacingM = 0.8f;
        const std::vector<sim::Agent> placed = placeDab(scene, {}, {10, -4}, {}, settings, 42);
        const double wanted = 0.4 * std::numbers::pi * 25.0;  // 31.4
        QVERIFY2(placed.size() >= std::size_t(wanted * 0.9) && placed.size() <= std::size_t(wanted + 1),
                 qPrintable(QString::number(placed.size())));
        for (std::size_t i = 0; i < placed.size(); ++i) {
            QVERIFY(glm::length(ground(placed[i]) - glm::vec2(10, -4)) <= 5.0f + 1e-4f);
            QCOMPARE(placed[i].type, std::string("walker"));  // the first pedestrian type by default
            for (std::size_t j = i + 1; j < placed.size(); ++j)
                QVERIFY(glm::length(ground(placed[i]) - ground(placed[j])) >= 0.8f - 1e-4f);
        }
        // A second dab on the same spot adds nothing: the disk is already at density.
        sim::Scene filled = scene;
        filled.agents = placed;
        QVERIFY(placeDab(filled, {}, {10, -4}, {}, settings, 43).size() <= 1);
        // The same seed gives the same agents.
        QVERIFY(placeDab(scene, {}, {10, -4}, {}, settings, 42) == placed);
    }

    void neverInsideWallsObstaclesOrOutOfBounds()
    {
        sim::Scene scene = openGround();
        scene.walls.push_back({"w", {{-10, 0}, {10, 0}}});
        scene.obstacles.push_back({"post", sim::ObstacleShape::Circle, {2, 2}, 1.5f, {1, 1}, 0});
        scene.obstacles.push_back({"kiosk", sim::ObstacleShape::Box, {-2, -2}, 0.5f, {3, 2}, 30});
        scene.settings.boundsMin = {-50, -50};
        scene.settings.boundsMax = {50, 3};
        CrowdBrushSettings settings;
        settings.radiusM = 4.0f;
        settings.densityPerM2 = 1.5f;
        settings.minSpacingM = 0.3f;
        const std::vector<sim::Agent> placed = placeDab(scene, {}, {0, 0}, {}, settings, 9);
        QVERIFY(placed.size() > 10);
        for (const sim::Agent& a : placed) {
            const glm::vec2 p = ground(a);
            QVERIFY2(std::abs(p.y) >= 0.3f - 1e-4f, "an agent stands in the wall");
            QVERIFY2(glm::length(p - glm::vec2(2, 2)) >= 1.8f - 1e-4f, "an agent stands in the post");
            QVERIFY2(p.y <= 3.0f - 0.3f + 1e-4f, "an agent stands outside the bounds");
            QVERIFY(!isBlocked(scene, p, 0.3f));
        }
        QVERIFY(isBlocked(scene, {-2, -2}, 0.3f));  // the kiosk's centre
    }

    void facesAlongTheStrokeOrTowardAPoint()
    {
        const sim::Scene scene = openGround();
        CrowdBrushSettings settings;
        settings.heading = HeadingMode::AlongStroke;
        // Stroke toward -z (north): heading 90 degrees, counter-clockwise from +x seen from above.
        for (const sim::Agent& a : placeDab(scene, {}, {0, 0}, {0, -1}, settings, 1))
            QVERIFY2(std::abs(a.headingDeg - 90.0f) < 0.01f, qPrintable(QString::number(a.headingDeg)));
        settings.heading = HeadingMode::TowardPoint;
        settings.towardPoint = {20, 0};
        const std::vector<sim::Agent> facing = placeDab(scene, {}, {0, 0}, {}, settings, 2);
        QVERIFY(!facing.empty());
        for (const sim::Agent& a : facing) {
            const float h = glm::radians(a.headingDeg);
            const glm::vec2 forward(std::cos(h), -std::sin(h));
            QVERIFY(glm::dot(forward, glm::normalize(glm::vec2(20, 0) - ground(a))) > 0.9999f);
        }
    }

    void theMixSetsTheShareOfEachType()
    {
        const sim::Scene scene = openGround();
        CrowdBrushSettings settings;
        settings.radiusM = 10.0f;
        settings.densityPerM2 = 0.5f;
        settings.minSpacingM = 0.5f;
        settings.mix = {{"walker", 3.0f}, {"cart", 1.0f}};
        const std::vector<sim::Agent> placed = placeDab(scene, {}, {0, 0}, {}, settings, 5);
        const auto carts = std::count_if(placed.begin(), placed.end(), [](const sim::Agent& a) { return a.type == "cart"; });
        const double share = double(carts) / double(placed.size());
        QVERIFY2(placed.size() > 100 && share > 0.15 && share < 0.35, qPrintable(QString::number(share)));
    }
};

THRONG_REGISTER_TEST(TestCrowdBrushPlacement)
#include "TestCrowdBrushPlacement.moc"
