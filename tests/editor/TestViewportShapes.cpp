// What the viewport draws beyond bodies and walls: a car as a 4.2 m box along its lane
// (not a disc), the selection outlined in the selection colour, and flow strokes as
// arrows on a coarse grid within their width.
#include "EditorTestSupport.h"
#include "ShowInitialState.h"
#include "TestRegistry.h"

#include "editor/viewport/ViewportPalette.h"
#include "simcore/io/SceneIO.h"

#include <QTest>

using namespace throng;
using namespace throng::editor;
using namespace throng::editor::test;

namespace {

const QSize kSize{480, 480};

// One car at the origin heading east on a lane, inside 24 m square bounds.
const QByteArray kCarYaml = R"(throng: 1
settings: {bounds: {min: [-12, -12], max: [12, 12]}}
agent_types:
  - {name: car, kind: vehicle, radius: 1.1, max_speed: 10, max_force: 5000, mass: 1200}
lanes:
  - {name: east, points: [[-12, 0], [12, 0]], width: 3.5, speed_limit: 10}
vehicles:
  - {type: car, lane: east, at: 12}
)";

QByteArray flowYaml(bool withStroke)
{
    QByteArray yaml = "throng: 1\nsettings: {bounds: {min: [-10, -10], max: [10, 10]}}\n"
                      "obstacles:\n  - {shape: circle, center: [4, -6], radius: 1}\n"
                      // Two short walls in far corners: both scenes frame alike.
                      "walls:\n  - {points: [[-12, -12], [-11, -12]]}\n  - {points: [[11, 12], [12, 12]]}\n";
    if (withStroke)
        yaml += "flow_strokes:\n  - {points: [[-8, 0], [8, 0]], width: 6}\n";
    return yaml;
}

}  // namespace

class TestViewportShapes : public QObject {
    Q_OBJECT

private:
    sim::Scene loadScene(const QByteArray& yaml) { return loadTestScene(m_dir, yaml); }

    QTemporaryDir m_dir;

private slots:
    void aCarIsALongBoxAlongItsLane()
    {
        Viewport viewport;
        showInitialState(viewport, loadScene(kCarYaml));
        const QImage image = renderOffscreen(viewport, kSize);
        QVERIFY2(viewport.isGlReady(), qPrintable(viewport.glProblem()));
        QCOMPARE(viewport.agentCount(), std::size_t(1));
        const glm::vec4 body = palette::agentColour(0);
        auto at = [&](float x, float z) { return pixelAt(image, viewport, viewport.worldToPixel({x, 0.0f, z})); };
        // 4.2 m long and 1.76 m wide: bonnet and boot reach 1.6 m ahead and behind, beyond
        // the 1.1 m radius a disc would have; the sides stop short of it.
        for (glm::vec2 p : {glm::vec2(1.6f, 0.0f), glm::vec2(-1.8f, 0.0f), glm::vec2(0.0f, 0.7f), glm::vec2(0.0f, -0.7f)})
            QVERIFY2(sameColour(at(p.x, p.y), body), qPrintable(describe(at(p.x, p.y)) + QString(" at %1, %2").arg(p.x).arg(p.y)));
        for (glm::vec2 p : {glm::vec2(0.0f, 1.05f), glm::vec2(0.0f, -1.05f), glm::vec2(2.6f, 0.0f)})
            QVERIFY2(!sameColour(at(p.x, p.y), body, 30), qPrintable(describe(at(p.x, p.y)) + QString(" at %1, %2").arg(p.x).arg(p.y)));
        // The windscreen is darker than the body, ahead of the middle.
        QVERIFY(qGreen(at(0.75f, 0.0f)) < qGreen(at(-0.3f, 0.0f)) - 20);
    }

    void theSelectionIsOutlined()
    {
        Viewport viewport;
        const sim::Scene scene = loadScene(flowYaml(false));
        showInitialState(viewport, scene);
        renderOffscreen(viewport, kSize);
        // The obstacle's radius 1 m; the outline stands 0.25 m outside it.
        const QPointF ring = viewport.worldToPixel({4.0f + 1.25f, 0.0f, -6.0f});
        QVERIFY(!sameColour(pixelAt(viewport.grabFramebuffer(), viewport, ring), palette::kSelection, 30));
        viewport.setHighlight(scene, {{ItemKind::Obstacle, 0}});
        QRgb outlined = pixelAt(viewport.grabFramebuffer(), viewport, ring);
        QVERIFY2(sameColour(outlined, palette::kSelection, 12), qPrintable(describe(outlined)));
        viewport.setHighlight(scene, {});
        outlined = pixelAt(viewport.grabFramebuffer(), viewport, ring);
        QVERIFY(!sameColour(outlined, palette::kSelection, 30));
    }

    void flowStrokesShowArrowsWithinTheirWidth()
    {
        Viewport plain, flowing;
        showInitialState(plain, loadScene(flowYaml(false)));
        showInitialState(flowing, loadScene(flowYaml(true)));
        const QImage a = renderOffscreen(plain, kSize), b = renderOffscreen(flowing, kSize);
        QCOMPARE(plain.worldToPixel({-7, 0, -7}), flowing.worldToPixel({-7, 0, -7}));  // framed alike
        auto differs = [&](float x, float z) {
            const QPointF p = plain.worldToPixel({x, 0.0f, z});
            return pixelAt(a, plain, p) != pixelAt(b, flowing, p);
        };
        // Arrows sit on the 2 m grid's cell centres (odd metres) within 3 m of the stroke.
        int arrows = 0;
        for (float x : {-7.0f, -5.0f, -3.0f, 3.0f, 5.0f})
            for (float z : {-1.0f, 1.0f})
                arrows += differs(x, z);
        QVERIFY2(arrows == 10, qPrintable(QString("%1 of 10 cells show an arrow").arg(arrows)));
        for (float x : {-7.0f, -3.0f, 5.0f})
            for (float z : {-7.0f, 5.0f, 9.0f})
                QVERIFY2(!differs(x, z), qPrintable(QString("an arrow at %1, %2, outside the stroke's width").arg(x).arg(z)));
    }
};

THRONG_REGISTER_TEST(TestViewportShapes)
#include "TestViewportShapes.moc"
