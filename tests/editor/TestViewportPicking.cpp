// The ground point under the mouse, as the brushes and drawing tools receive it: in the
// top view the clicked spot, in the 3D view the point of the terrain the camera ray hits
// (not the flat ground below a hill).
#include "EditorTestSupport.h"
#include "ShowInitialState.h"
#include "TestRegistry.h"

#include "editor/tools/TerrainHeight.h"

#include <glm/geometric.hpp>

#include <QTest>

using namespace throng;
using namespace throng::editor;
using namespace throng::editor::test;

namespace {

// A 40 m square hill rising 0.25 m per metre eastwards (x), from 0 m at x = -20 to 10 m.
sim::Scene hillScene()
{
    sim::Scene s;
    s.settings.boundsMin = {-20, -20};
    s.settings.boundsMax = {20, 20};
    s.terrain.origin = {-20, -20};
    s.terrain.cellM = 2.0f;
    s.terrain.cols = s.terrain.rows = 21;
    for (std::uint32_t r = 0; r < 21; ++r)
        for (std::uint32_t c = 0; c < 21; ++c)
            s.terrain.heights.push_back(0.5f * float(c));
    return s;
}

}  // namespace

class TestViewportPicking : public QObject {
    Q_OBJECT

private slots:
    void theRayHitsTheTerrainIn3D()
    {
        const sim::Scene scene = hillScene();
        Viewport viewport;
        showInitialState(viewport, scene);
        renderOffscreen(viewport, {640, 480});
        viewport.setViewMode(ViewMode::Orbit);
        viewport.frameAll();
        for (const glm::vec2 ground : {glm::vec2(0, 0), glm::vec2(10, 5), glm::vec2(-12, -8)}) {
            const glm::vec3 onHill(ground.x, terrainHeight(scene.terrain, ground.x, ground.y), ground.y);
            QVERIFY(onHill.y > 1.0f);
            const std::optional<glm::vec3> hit = viewport.pixelToGround(viewport.worldToPixel(onHill));
            QVERIFY(hit);
            QVERIFY2(glm::length(*hit - onHill) < 0.3f,
                     qPrintable(QString("hit %1 %2 %3").arg(hit->x).arg(hit->y).arg(hit->z)));
        }
    }

    void theTopViewGivesTheClickedGroundPoint()
    {
        sim::Scene scene = hillScene();
        scene.terrain = {};
        Viewport viewport;
        showInitialState(viewport, scene);
        renderOffscreen(viewport, {640, 480});
        viewport.frameAll();
        const glm::vec3 p(7.5f, 0.0f, -3.25f);
        const std::optional<glm::vec3> hit = viewport.pixelToGround(viewport.worldToPixel(p));
        QVERIFY(hit);
        QVERIFY(glm::length(*hit - p) < 0.1f);
    }
};

THRONG_REGISTER_TEST(TestViewportPicking)
#include "TestViewportPicking.moc"
