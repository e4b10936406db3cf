// The set stands up in the 3D view: walls reach their height, obstacles are solids (a
// box turned by its angle), a traffic light's lamp of the shown phase is lit, crosswalks
// keep their zebra stripes, and a flier is a bird (wider than tall) near, mid-way and far.
#include "EditorTestSupport.h"
#include "ShowInitialState.h"
#include "TestRegistry.h"

#include "export/set/SetSolids.h"
#include "editor/viewport/ViewportPalette.h"

#include <QTest>

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>

using namespace throng;
using namespace throng::editor;
using namespace throng::editor::test;

namespace {

const QSize kSize{480, 480};

// A scene framed on the square of half side `halfM` round the origin: two short walls
// in its far corners set the extent, whatever else the scene holds.
sim::Scene framedScene(float halfM)
{
    sim::Scene s;
    s.settings.boundsMin = glm::vec2(-halfM - 1.0f);
    s.settings.boundsMax = glm::vec2(halfM + 1.0f);
    for (float sign : {-1.0f, 1.0f}) {
        sim::Wall corner;
        corner.points = {sign * glm::vec2(halfM), sign * glm::vec2(halfM - 0.3f, halfM)};
        corner.heightM = 0.1f;
        s.walls.push_back(corner);
    }
    return s;
}

// True when `pixel` is `colour` shaded by the light (factor 0.4 to 1, as a lit face of
// any direction is), not some other colour of about the same brightness.
bool isShadeOf(QRgb pixel, glm::vec4 colour)
{
    const float k = float(qRed(pixel)) / (255.0f * colour.r);
    if (k < 0.4f || k > 1.02f)
        return false;
    return std::abs(float(qGreen(pixel)) - 255.0f * k * colour.g) <= 6.0f &&
           std::abs(float(qBlue(pixel)) - 255.0f * k * colour.b) <= 6.0f;
}

QImage render3D(Viewport& viewport, const sim::Scene& scene)
{
    showInitialState(viewport, scene);
    viewport.setViewMode(ViewMode::Orbit);
    return renderOffscreen(viewport, kSize);
}

// A flier's pixel: its type's orange, lit or shaded (ground and grid are grey).
bool isBird(QRgb p)
{
    const int hi = std::max({qRed(p), qGreen(p), qBlue(p)}), lo = std::min({qRed(p), qGreen(p), qBlue(p)});
    return hi - lo >= 30 && qRed(p) > qBlue(p);
}

// The bounding box of bird pixels within `reach` pixels of `centre`.
QRect birdBox(const QImage& image, const Viewport& viewport, QPointF centre, int reach)
{
    QRect box;
    for (int dy = -reach; dy <= reach; ++dy)
        for (int dx = -reach; dx <= reach; ++dx) {
            const QPointF at = centre + QPointF(dx, dy);
            if (isBird(pixelAt(image, viewport, at)))
                box |= QRect(int(std::lround(at.x())), int(std::lround(at.y())), 1, 1);
        }
    return box;
}

}  // namespace

class TestSet3D : public QObject {
    Q_OBJECT

private slots:
    void wallsStandAtTheirHeight()
    {
        Viewport tall, low;
        sim::Scene scene = framedScene(6.0f);
        sim::Wall wall;
        wall.points = {{-5.0f, 0.0f}, {5.0f, 0.0f}};
        wall.heightM = 3.0f;
        scene.walls.push_back(wall);
        const QImage a = render3D(tall, scene);
        QVERIFY2(tall.isGlReady(), qPrintable(tall.glProblem()));
        scene.walls.back().heightM = 1.0f;
        const QImage b = render3D(low, scene);
        const QPointF top = tall.worldToPixel({0.0f, 2.9f, 0.0f});
        QCOMPARE(low.worldToPixel({0.0f, 2.9f, 0.0f}), top);  // framed alike
        QVERIFY2(isShadeOf(pixelAt(a, tall, top), palette::kWall), qPrintable(describe(pixelAt(a, tall, top))));
        QVERIFY2(!isShadeOf(pixelAt(b, low, top), palette::kWall), qPrintable(describe(pixelAt(b, low, top))));
        // The low wall stands too, up to its own top.
        const QPointF lowTop = low.worldToPixel({0.0f, 0.9f, 0.0f});
        QVERIFY2(isShadeOf(pixelAt(b, low, lowTop), palette::kWall), qPrintable(describe(pixelAt(b, low, lowTop))));
        // And the wall has thickness: a point 0.08 m in front of its middle line is inside it.
        const QPointF front = tall.worldToPixel({2.0f, 1.5f, 0.08f});
        QVERIFY2(isShadeOf(pixelAt(a, tall, front), palette::kWall), qPrintable(describe(pixelAt(a, tall, front))));
    }

    void theTopViewKeepsFlatWalls()
    {
        Viewport viewport;
        sim::Scene scene = framedScene(6.0f);
        sim::Wall wall;
        wall.points = {{-5.0f, 0.0f}, {5.0f, 0.0f}};
        wall.heightM = 3.0f;
        scene.walls.push_back(wall);
        showInitialState(viewport, scene);
        const QImage image = renderOffscreen(viewport, kSize);
        QCOMPARE(viewport.viewMode(), ViewMode::Top);
        // The flat line's own colour, unlit: no solid drawn over it.
        const QRgb p = pixelAt(image, viewport, viewport.worldToPixel({1.0f, 0.0f, 0.0f}));
        QVERIFY2(sameColour(p, palette::kWall, 3), qPrintable(describe(p)));
    }

    void obstaclesAreSolidsAMetreHigh()
    {
        Viewport viewport;
        sim::Scene scene = framedScene(8.0f);
        sim::Obstacle box;
        box.shape = sim::ObstacleShape::Box;
        box.size = {4.0f, 0.6f};
        box.angleDeg = 90.0f;  // its 4 m width along z
        scene.obstacles.push_back(box);
        sim::Obstacle post;
        post.center = {5.0f, 0.0f};
        post.radiusM = 0.8f;
        scene.obstacles.push_back(post);
        const QImage image = render3D(viewport, scene);
        QVERIFY2(viewport.isGlReady(), qPrintable(viewport.glProblem()));
        auto at = [&](glm::vec3 p) { return pixelAt(image, viewport, viewport.worldToPixel(p)); };
        // Points inside the solids whose pixels, without them, would show the ground
        // beyond the obstacles' outlines: the solid's top face covers them.
        for (glm::vec3 p : {glm::vec3(0.0f, 0.9f, -1.5f), glm::vec3(0.0f, 0.5f, -1.8f), glm::vec3(5.0f, 0.9f, -0.5f)})
            QVERIFY2(isShadeOf(at(p), palette::kObstacleSolid),
                     qPrintable(describe(at(p)) + QString(" at %1, %2, %3").arg(p.x).arg(p.y).arg(p.z)));
        // The box is 0.6 m across x, and nothing stands 2.5 m high.
        for (glm::vec3 p : {glm::vec3(1.5f, 0.9f, 0.0f), glm::vec3(5.0f, 2.5f, 0.0f), glm::vec3(0.0f, 2.5f, -1.5f)})
            QVERIFY2(!isShadeOf(at(p), palette::kObstacleSolid) && !isShadeOf(at(p), palette::kObstacleFill),
                     qPrintable(describe(at(p)) + QString(" at %1, %2, %3").arg(p.x).arg(p.y).arg(p.z)));
    }

    void trafficLightLampsShowThePhase_data()
    {
        QTest::addColumn<float>("offsetS");
        QTest::addColumn<int>("lit");
        // 10 s green, 3 s yellow, 10 s red; shown at time 0, which the offset moves.
        QTest::newRow("green") << 0.0f << int(sim::LightPhase::Green);
        QTest::newRow("yellow") << 11.0f << int(sim::LightPhase::Yellow);
        QTest::newRow("red") << 15.0f << int(sim::LightPhase::Red);
    }

    void trafficLightLampsShowThePhase()
    {
        QFETCH(float, offsetS);
        QFETCH(int, lit);
        sim::Scene scene = framedScene(4.0f);
        sim::TrafficLight light;
        light.name = "signal";
        light.greenS = 10.0f;
        light.yellowS = 3.0f;
        light.redS = 10.0f;
        light.offsetS = offsetS;
        light.position = {0.5f, -1.0f};
        scene.trafficLights.push_back(light);
        Viewport viewport;
        const QImage image = render3D(viewport, scene);
        QVERIFY2(viewport.isGlReady(), qPrintable(viewport.glProblem()));
        QVERIFY(viewport.timeS().has_value());
        QCOMPARE(int(sim::lightPhaseAt(light, *viewport.timeS())), lit);
        // Each lamp's face towards the camera.
        const glm::vec3 eye = viewport.renderView().eye;
        const glm::vec2 toEye = glm::normalize(glm::vec2(eye.x, eye.z) - light.position);
        const glm::vec2 face = light.position + toEye * (0.9f * exporting::SetSolids::kLampRadiusM);
        const std::pair<sim::LightPhase, glm::vec4> lamps[] = {{sim::LightPhase::Red, palette::kLightRed},
                                                               {sim::LightPhase::Yellow, palette::kLightYellow},
                                                               {sim::LightPhase::Green, palette::kLightGreen}};
        for (const auto& [lamp, colour] : lamps) {
            const QRgb p = pixelAt(image, viewport,
                                   viewport.worldToPixel({face.x, exporting::SetSolids::lampHeightM(lamp), face.y}));
            const QString what = describe(p) + QString(" for lamp %1").arg(int(lamp));
            if (int(lamp) == lit) {
                QVERIFY2(sameColour(p, colour, 10), qPrintable(what));
            } else {
                // Dark: well under half the lit lamp's brightness in every channel.
                QVERIFY2(std::max({qRed(p), qGreen(p), qBlue(p)}) < 100, qPrintable(what));
            }
        }
    }

    void crosswalksShowZebraStripesInBothViews_data()
    {
        QTest::addColumn<int>("mode");
        QTest::newRow("top") << int(ViewMode::Top);
        QTest::newRow("3D") << int(ViewMode::Orbit);
    }

    void crosswalksShowZebraStripesInBothViews()
    {
        QFETCH(int, mode);
        sim::Scene scene = framedScene(4.0f);
        sim::Crosswalk crosswalk;
        crosswalk.name = "zebra";
        crosswalk.from = {0.0f, 3.0f};
        crosswalk.to = {0.0f, -3.0f};
        crosswalk.widthM = 3.0f;
        scene.crosswalks.push_back(crosswalk);
        Viewport viewport;
        showInitialState(viewport, scene);
        viewport.setViewMode(ViewMode(mode));
        const QImage image = renderOffscreen(viewport, kSize);
        QVERIFY2(viewport.isGlReady(), qPrintable(viewport.glProblem()));
        // Three 0.5 m bars along the walking direction, 0.5 m apart across the 3 m width.
        for (float z : {-2.0f, 0.0f, 2.0f}) {
            for (float x : {-1.0f, 0.0f, 1.0f}) {
                const QRgb p = pixelAt(image, viewport, viewport.worldToPixel({x, 0.0f, z}));
                QVERIFY2(sameColour(p, palette::kCrosswalkStripe, 6),
                         qPrintable(describe(p) + QString(" on a stripe at %1, %2").arg(x).arg(z)));
            }
            for (float x : {-0.5f, 0.5f, 1.9f}) {
                const QRgb p = pixelAt(image, viewport, viewport.worldToPixel({x, 0.0f, z}));
                QVERIFY2(!sameColour(p, palette::kCrosswalkStripe, 40),
                         qPrintable(describe(p) + QString(" between stripes at %1, %2").arg(x).arg(z)));
            }
        }
    }

    void fliersAreBirdsAtEveryDistance_data()
    {
        QTest::addColumn<float>("halfM");
        QTest::addColumn<float>("altitudeM");
        QTest::addColumn<int>("detail");
        // The camera frames the square from about three times its half side.
        QTest::newRow("near") << 2.0f << 1.0f << int(AgentDetail::Detailed);
        QTest::newRow("mid-way") << 10.0f << 3.0f << int(AgentDetail::Coarse);
        QTest::newRow("far") << 24.0f << 5.0f << int(AgentDetail::Impostor);
    }

    void fliersAreBirdsAtEveryDistance()
    {
        QFETCH(float, halfM);
        QFETCH(float, altitudeM);
        QFETCH(int, detail);
        sim::Scene scene = framedScene(halfM);
        sim::AgentType bird;
        bird.name = "starling";
        bird.kind = sim::AgentKind::Flier;
        bird.radiusM = 0.3f;
        scene.agentTypes.push_back(bird);
        sim::Agent a;
        a.id = 1;
        a.type = "starling";
        a.position = {0.0f, altitudeM, 0.0f};
        a.headingDeg = 90.0f;  // nose north, away from the camera: the wings span the screen
        scene.agents.push_back(a);
        Viewport viewport;
        const QImage image = render3D(viewport, scene);
        QVERIFY2(viewport.isGlReady(), qPrintable(viewport.glProblem()));
        QCOMPARE(viewport.agentCount(), std::size_t(1));
        const std::array<int, kAgentDetailLevels> drawn = viewport.agentsDrawnByDetail();
        QVERIFY2(drawn[std::size_t(detail)] == 1,
                 qPrintable(QString("%1 detailed, %2 coarse, %3 far").arg(drawn[0]).arg(drawn[1]).arg(drawn[2])));

        const glm::vec3 at = viewport.shownAgents().feet(0);
        const QPointF centre = viewport.worldToPixel(at);
        const QRect box = birdBox(image, viewport, centre, 60);
        QVERIFY2(!box.isEmpty(), "no bird drawn");
        QVERIFY2(box.contains(centre.toPoint()) || (box.center() - centre.toPoint()).manhattanLength() <= 4,
                 qPrintable(QString("the bird is at %1, %2, its agent at %3, %4")
                                .arg(box.center().x())
                                .arg(box.center().y())
                                .arg(centre.x())
                                .arg(centre.y())));
        // Spread wings: wider than tall (an upright walker's body is three times taller
        // than wide). Far away the bird is a few pixels: wider, by at least a pixel.
        const QString size = QString("%1 x %2 px").arg(box.width()).arg(box.height());
        QVERIFY2(box.width() >= 4, qPrintable(size));
        if (detail == int(AgentDetail::Impostor))
            QVERIFY2(box.width() > box.height(), qPrintable(size));
        else
            QVERIFY2(double(box.width()) >= 1.4 * double(box.height()), qPrintable(size));
    }

    void aBirdsWingsTurnWithItsHeading()
    {
        sim::Scene scene = framedScene(2.0f);
        sim::AgentType bird;
        bird.name = "gull";
        bird.kind = sim::AgentKind::Flier;
        bird.radiusM = 0.3f;
        scene.agentTypes.push_back(bird);
        sim::Agent a;
        a.id = 1;
        a.type = "gull";
        a.position = {0.0f, 1.0f, 0.0f};
        a.headingDeg = 0.0f;  // nose east: the wings now point at and away from the camera
        scene.agents.push_back(a);
        Viewport viewport;
        showInitialState(viewport, scene);
        const QImage image = renderOffscreen(viewport, kSize);  // the top view: the bird seen from above
        const QRect box = birdBox(image, viewport, viewport.worldToPixel(a.position), 60);
        QVERIFY2(!box.isEmpty(), "no bird drawn");
        const QString size = QString("%1 x %2 px").arg(box.width()).arg(box.height());
        QVERIFY2(double(box.height()) >= 1.4 * double(box.width()), qPrintable(size));
    }
};

THRONG_REGISTER_TEST(TestSet3D)
#include "TestSet3D.moc"
