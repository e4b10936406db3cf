// Level of detail without GL: every agent sorted into exactly one cell, and the plan for
// a view draws every agent that shows (none dropped), leaves out only cells outside the
// view, and never draws an agent coarser than its size on screen calls for.
#include "TestRegistry.h"

#include "editor/viewport/AgentCells.h"
#include "editor/viewport/AgentRenderer.h"
#include "editor/viewport/OrbitCamera.h"
#include "editor/viewport/TopCamera.h"

#include <glm/vec4.hpp>

#include <QTest>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace throng;
using namespace throng::editor;

namespace {

// `side` x `side` agents `spacingM` apart around the origin; radius and colour vary so
// that each glyph is told apart by its fields.
std::vector<AgentGlyph> grid(int side, float spacingM)
{
    std::vector<AgentGlyph> out;
    const float half = 0.5f * float(side - 1) * spacingM;
    for (int z = 0; z < side; ++z)
        for (int x = 0; x < side; ++x) {
            AgentGlyph g;
            g.position = {float(x) * spacingM - half, 0.0f, float(z) * spacingM - half};
            g.headingRad = float(x + z);
            g.radiusM = 0.25f + 0.01f * float((x * 7 + z) % 10);
            g.colour = {float(x) / float(side), float(z) / float(side), 0.5f};
            out.push_back(g);
        }
    return out;
}

GroundBox boxOf(const std::vector<AgentGlyph>& glyphs)
{
    GroundBox box;
    for (const AgentGlyph& g : glyphs)
        box.include({g.position.x, g.position.z}, g.radiusM);
    return box;
}

bool sameGlyph(const AgentGlyph& a, const AgentGlyph& b)
{
    return a.position == b.position && a.headingRad == b.headingRad && a.radiusM == b.radiusM &&
           a.colour == b.colour;
}

// The level each sorted agent is drawn at, -1 where it is left out.
std::vector<int> levelOf(const AgentDrawPlan& plan, std::size_t count)
{
    std::vector<int> level(count, -1);
    for (int d = 0; d < kAgentDetailLevels; ++d)
        for (const InstanceRange& r : plan.ranges[std::size_t(d)])
            for (int i = r.first; i < r.first + r.count; ++i) {
                if (level[std::size_t(i)] != -1)
                    qFatal("agent %d drawn twice", i);
                level[std::size_t(i)] = d;
            }
    return level;
}

}  // namespace

class TestAgentCells : public QObject {
    Q_OBJECT

private slots:
    void everyAgentLandsInExactlyOneCell()
    {
        const std::vector<AgentGlyph> glyphs = grid(317, 1.0f);  // 100,489 agents
        AgentCells cells;
        cells.build(glyphs);
        QCOMPARE(cells.sorted().size(), glyphs.size());
        QVERIFY(cells.cellCount() > 1000);
        QVERIFY(cells.cellCount() <= AgentCells::kMaxCellsPerSide * AgentCells::kMaxCellsPerSide);
        // A permutation: sorted by position, both lists hold the same glyphs.
        auto byPosition = [](const AgentGlyph& a, const AgentGlyph& b) {
            return std::tie(a.position.x, a.position.z) < std::tie(b.position.x, b.position.z);
        };
        std::vector<AgentGlyph> a(glyphs), b(cells.sorted().begin(), cells.sorted().end());
        std::sort(a.begin(), a.end(), byPosition);
        std::sort(b.begin(), b.end(), byPosition);
        for (std::size_t i = 0; i < a.size(); ++i)
            QVERIFY2(sameGlyph(a[i], b[i]), qPrintable(QString("glyph %1 differs").arg(i)));

        // The same input sorts to the same order.
        AgentCells again;
        again.build(glyphs);
        for (std::size_t i = 0; i < glyphs.size(); ++i)
            QVERIFY(sameGlyph(cells.sorted()[i], again.sorted()[i]));
    }

    void topViewOfTheWholeCrowdDrawsEveryAgentAsADot()
    {
        const std::vector<AgentGlyph> glyphs = grid(317, 1.0f);
        AgentCells cells;
        cells.build(glyphs);
        TopCamera camera;
        camera.setViewportSize({1280, 720});
        camera.frame(boxOf(glyphs), 24.0f);
        AgentDrawPlan plan;
        cells.plan(camera.renderView(), AgentRenderer::kTopDetail, plan);
        QCOMPARE(plan.culledAgents, 0);
        QCOMPARE(plan.agents[std::size_t(AgentDetail::Impostor)], int(glyphs.size()));
        // Adjacent cells merge: a handful of draw calls, not one per cell.
        QCOMPARE(plan.at(AgentDetail::Impostor).size(), std::size_t(1));
        const std::vector<int> level = levelOf(plan, glyphs.size());
        QVERIFY(std::count(level.begin(), level.end(), -1) == 0);

        // Zoomed in 12x on the centre: most cells are outside, every agent in view is
        // drawn, and at 25 px per metre (radius 6 px and more) with the detailed glyph.
        camera.zoomAt({640, 360}, 12.0f);
        cells.plan(camera.renderView(), AgentRenderer::kTopDetail, plan);
        const std::vector<int> zoomed = levelOf(plan, glyphs.size());
        int inView = 0;
        for (std::size_t i = 0; i < glyphs.size(); ++i) {
            const AgentGlyph& g = cells.sorted()[i];
            const QPointF px = camera.groundToPixel({g.position.x, g.position.z});
            const double r = g.radiusM * camera.pixelsPerMetre();
            if (px.x() + r < 0 || px.x() - r > 1280 || px.y() + r < 0 || px.y() - r > 720)
                continue;
            ++inView;
            QVERIFY2(zoomed[i] == int(AgentDetail::Detailed),
                     qPrintable(QString("agent at %1, %2 px is drawn at level %3").arg(px.x()).arg(px.y()).arg(zoomed[i])));
        }
        QVERIFY2(inView > 1000, qPrintable(QString::number(inView)));
        QVERIFY2(plan.culledAgents > 80000, qPrintable(QString::number(plan.culledAgents)));
        QCOMPARE(plan.culledAgents + plan.agents[0] + plan.agents[1] + plan.agents[2], int(glyphs.size()));
    }

    void perspectiveDrawsNearAgentsAsGlyphsAndFarOnesAsImpostors()
    {
        const std::vector<AgentGlyph> glyphs = grid(317, 1.0f);
        AgentCells cells;
        cells.build(glyphs);
        OrbitCamera camera;
        camera.setViewportSize({1280, 720});
        camera.frame(boxOf(glyphs));
        camera.zoom(4.0f);  // about 90 m from the centre of a 316 m crowd
        const RenderView view = camera.renderView();
        const DetailThresholds thresholds = AgentRenderer::kPerspectiveDetail;
        AgentDrawPlan plan;
        cells.plan(view, thresholds, plan);
        const std::vector<int> level = levelOf(plan, glyphs.size());
        int inView = 0, glyphsInView = 0;
        for (std::size_t i = 0; i < glyphs.size(); ++i) {
            const AgentGlyph& g = cells.sorted()[i];
            const glm::vec4 clip = view.viewProjection * glm::vec4(g.position + glm::vec3(0, 0.8f, 0), 1.0f);
            if (clip.w <= 0.0f || std::abs(clip.x) > clip.w || std::abs(clip.y) > clip.w)
                continue;  // behind the eye or off screen
            ++inView;
            QVERIFY2(level[i] != -1, qPrintable(QString("agent %1 in view is not drawn").arg(i)));
            // Its radius on screen: what a level must be at least as detailed as.
            const float radiusPx = g.radiusM / (clip.w * view.metresPerPixel);
            const int needed = radiusPx >= thresholds.detailedFromPx ? int(AgentDetail::Detailed)
                               : radiusPx >= thresholds.coarseFromPx ? int(AgentDetail::Coarse)
                                                                     : int(AgentDetail::Impostor);
            QVERIFY2(level[i] <= needed, qPrintable(QString("agent %1 at %2 px drawn at level %3")
                                                        .arg(i)
                                                        .arg(double(radiusPx))
                                                        .arg(level[i])));
            glyphsInView += level[i] != int(AgentDetail::Impostor);
        }
        QVERIFY2(inView > 2000, qPrintable(QString::number(inView)));
        QVERIFY2(glyphsInView > 100, qPrintable(QString::number(glyphsInView)));
        QVERIFY2(plan.agents[std::size_t(AgentDetail::Impostor)] > 10000,
                 qPrintable(QString::number(plan.agents[2])));
        // The cells behind the camera and beside the view are left out.
        QVERIFY2(plan.culledAgents > 20000, qPrintable(QString::number(plan.culledAgents)));
    }

    void emptyCrowdPlansNothing()
    {
        AgentCells cells;
        cells.build({});
        QCOMPARE(cells.cellCount(), 0);
        AgentDrawPlan plan;
        cells.plan(OrbitCamera().renderView(), AgentRenderer::kPerspectiveDetail, plan);
        QCOMPARE(plan.agents[0] + plan.agents[1] + plan.agents[2] + plan.culledAgents, 0);
    }
};

THRONG_REGISTER_TEST(TestAgentCells)
#include "TestAgentCells.moc"
