// The viewport as a user sees it: agents where they stand in their type's colour and
// facing their heading, walls along their lines, lights in their current colour, recorded
// frames and the 3D view.
#include "EditorTestSupport.h"
#include "ShowInitialState.h"
#include "TestRegistry.h"

#include "editor/viewport/ViewportPalette.h"
#include "simcore/io/SceneIO.h"
#include "simcore/world/World.h"

#include <QTest>

#include <cmath>

using namespace throng;
using namespace throng::editor;
using namespace throng::editor::test;

namespace {

const QSize kSize{400, 300};

// Two walls and one agent at the origin: the set is symmetric about the origin, so
// framing it puts the agent at the image centre.
QByteArray plazaYaml(int headingDeg)
{
    return QStringLiteral("throng: 1\n"
                          "settings: {bounds: {min: [-10, -10], max: [10, 10]}}\n"
                          "agent_types: [{name: walker, radius: 0.4}, {name: runner, radius: 0.4}]\n"
                          "agents:\n"
                          "  - {type: walker, position: [0, 0], heading: %1}\n"
                          "  - {type: runner, position: [2, 1.5]}\n"
                          // Low walls: in 3D they must hide no ground nor agent.
                          "walls:\n"
                          "  - {points: [[-4, -3], [4, -3]], height: 0.1}\n"
                          "  - {points: [[-4, 3], [4, 3]], height: 0.1}\n")
        .arg(headingDeg)
        .toUtf8();
}

}  // namespace

class TestViewportRendering : public QObject {
    Q_OBJECT

private:
    sim::Scene loadScene(const QByteArray& yaml) { return loadTestScene(m_dir, yaml); }

    QTemporaryDir m_dir;

private slots:
    void agentStandsInItsTypeColourOnTheGround()
    {
        Viewport viewport;
        showInitialState(viewport, loadScene(plazaYaml(0)));
        const QImage image = renderOffscreen(viewport, kSize);
        QVERIFY2(viewport.isGlReady(), qPrintable(viewport.glProblem()));
        QCOMPARE(viewport.agentCount(), std::size_t(2));

        // The image centre: no camera maths of the viewport's own involved.
        const QRgb centre = image.pixel(image.width() / 2, image.height() / 2);
        QVERIFY2(sameColour(centre, palette::agentColour(0)),
                 qPrintable(describe(centre) + " at the walker, expected " + describe(palette::agentColour(0))));
        const QRgb runner = pixelAt(image, viewport, viewport.worldToPixel({2.0f, 0.0f, 1.5f}));
        QVERIFY2(sameColour(runner, palette::agentColour(1)), qPrintable(describe(runner) + " at the runner"));
        QVERIFY(!sameColour(runner, palette::agentColour(0), 30));

        // Mid-cell of the metre grid, far from agents and walls: plain ground.
        for (glm::vec3 empty : {glm::vec3(-2.5f, 0.0f, 1.5f), glm::vec3(3.5f, 0.0f, -1.5f)}) {
            const QRgb ground = pixelAt(image, viewport, viewport.worldToPixel(empty));
            QVERIFY2(sameColour(ground, palette::kGround, 4), qPrintable(describe(ground) + " on empty ground"));
        }
    }

    void noseShowsTheHeading_data()
    {
        QTest::addColumn<int>("headingDeg");
        QTest::addColumn<QPointF>("screenDirection");  // where the nose should be on screen
        QTest::newRow("east") << 0 << QPointF(1, 0);
        QTest::newRow("north is up") << 90 << QPointF(0, -1);
        QTest::newRow("west") << 180 << QPointF(-1, 0);
        QTest::newRow("south") << 270 << QPointF(0, 1);
    }

    void noseShowsTheHeading()
    {
        QFETCH(int, headingDeg);
        QFETCH(QPointF, screenDirection);
        Viewport viewport;
        showInitialState(viewport, loadScene(plazaYaml(headingDeg)));
        const QImage image = renderOffscreen(viewport, kSize);
        const QPointF centre = viewport.worldToPixel({0.0f, 0.0f, 0.0f});
        const double radiusPx = std::abs(viewport.worldToPixel({0.4f, 0.0f, 0.0f}).x() - centre.x());
        QVERIFY(radiusPx > 8.0);
        const QRgb front = pixelAt(image, viewport, centre + screenDirection * (0.65 * radiusPx));
        const QRgb back = pixelAt(image, viewport, centre - screenDirection * (0.6 * radiusPx));
        QVERIFY2(sameColour(front, palette::kAgentNose), qPrintable(describe(front) + " in front of the agent"));
        QVERIFY2(sameColour(back, palette::agentColour(0)), qPrintable(describe(back) + " behind the agent"));
    }

    void wallShowsAlongItsLine()
    {
        Viewport viewport;
        showInitialState(viewport, loadScene(plazaYaml(0)));
        const QImage image = renderOffscreen(viewport, kSize);
        for (float x : {-3.5f, -1.5f, 0.5f, 2.0f, 3.5f}) {
            const QRgb onWall = pixelAt(image, viewport, viewport.worldToPixel({x, 0.0f, -3.0f}));
            QVERIFY2(sameColour(onWall, palette::kWall),
                     qPrintable(describe(onWall) + QString(" on the wall at x = %1").arg(x)));
            const QRgb beside = pixelAt(image, viewport, viewport.worldToPixel({x, 0.0f, -2.5f}));
            QVERIFY2(!sameColour(beside, palette::kWall, 40),
                     qPrintable(describe(beside) + " half a metre off the wall"));
        }
        // North (-z) is up: the wall at z = -3 is in the upper half of the picture.
        QVERIFY(viewport.worldToPixel({0.0f, 0.0f, -3.0f}).y() < kSize.height() / 2.0);
    }

    void trafficLightShowsItsCurrentPhase_data()
    {
        QTest::addColumn<int>("frame");
        QTest::addColumn<QString>("expected");
        // 10 fps, a 1 s green, 1 s yellow, 1 s red cycle.
        QTest::newRow("0.0 s") << 0 << "green";
        QTest::newRow("1.5 s") << 15 << "yellow";
        QTest::newRow("2.5 s") << 25 << "red";
        QTest::newRow("3.5 s, next cycle") << 35 << "green";
    }

    void trafficLightShowsItsCurrentPhase()
    {
        QFETCH(int, frame);
        QFETCH(QString, expected);
        const sim::Scene scene = loadScene("throng: 1\n"
                                           "settings: {fps: 10}\n"
                                           "traffic_lights:\n"
                                           "  - {name: signal, position: [0, 0], green: 1, yellow: 1, red: 1}\n");
        sim::World world(scene);
        for (int i = 0; i < frame; ++i)
            world.step();
        Viewport viewport;
        viewport.setScene(scene, world);
        const QImage image = renderOffscreen(viewport, kSize);
        const glm::vec4 colour = expected == "green"    ? palette::kLightGreen
                                 : expected == "yellow" ? palette::kLightYellow
                                                        : palette::kLightRed;
        const QRgb lamp = image.pixel(image.width() / 2, image.height() / 2);
        QVERIFY2(sameColour(lamp, colour), qPrintable(describe(lamp) + " at the light, expected " + expected));
        QCOMPARE(viewport.frameIndex(), std::size_t(frame));
    }

    void recordedFrameShowsItsAgentPositions()
    {
        const sim::Scene scene = loadScene(plazaYaml(0));
        Viewport viewport;
        showInitialState(viewport, scene);
        sim::FrameCache cache;
        cache.reset({{1, 0}, {2, 1}}, 24.0f);
        sim::AgentFrame a, b;
        a.position = {0.5f, 0.0f, 0.5f};
        b.position = {2.0f, 0.0f, 1.5f};
        cache.append(std::vector<sim::AgentFrame>{a, b});
        a.position = {-2.5f, 0.0f, -1.5f};
        cache.append(std::vector<sim::AgentFrame>{a, b});
        viewport.showFrame(cache, 1);
        QCOMPARE(viewport.frameIndex(), std::size_t(1));
        const QImage image = renderOffscreen(viewport, kSize);
        // Both points are mid-cell of the metre grid, so empty ground shows plain.
        const QRgb moved = pixelAt(image, viewport, viewport.worldToPixel({-2.5f, 0.0f, -1.5f}));
        const QRgb left = pixelAt(image, viewport, viewport.worldToPixel({0.5f, 0.0f, 0.5f}));
        QVERIFY2(sameColour(moved, palette::agentColour(0)),
                 qPrintable(describe(moved) + " where frame 1 puts the walker"));
        QVERIFY2(sameColour(left, palette::kGround, 4),
                 qPrintable(describe(left) + " where the walker was in frame 0"));
    }

    void orbitViewShowsAgentsStandingUp()
    {
        Viewport viewport;
        showInitialState(viewport, loadScene(plazaYaml(0)));
        viewport.setViewMode(ViewMode::Orbit);
        const QImage image = renderOffscreen(viewport, kSize);
        // Half-way up the walker's prism: lit orange, neither ground nor background.
        const QRgb body = pixelAt(image, viewport, viewport.worldToPixel({0.0f, 0.9f, 0.0f}));
        QVERIFY2(qRed(body) > qBlue(body) + 60 && qRed(body) > 100, qPrintable(describe(body) + " on the walker"));
        const QRgb ground = pixelAt(image, viewport, viewport.worldToPixel({-2.5f, 0.0f, 1.5f}));
        QVERIFY2(sameColour(ground, palette::kGround, 4), qPrintable(describe(ground) + " on empty ground in 3D"));
    }
};

THRONG_REGISTER_TEST(TestViewportRendering)
#include "TestViewportRendering.moc"
