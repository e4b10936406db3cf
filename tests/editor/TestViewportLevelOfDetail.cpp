// The viewport with level of detail, as a user sees it: a sparse crowd seen close up in
// 3D, near agents as glyphs and far ones as impostors, shows every agent where it stands
// and as many as the full-detail drawing does; a crowd of 100,000 shows agents near and
// far in 3D and the top view, every one drawn, covering what full detail covers.
#include "EditorTestSupport.h"
#include "ShowInitialState.h"
#include "TestRegistry.h"

#include "editor/viewport/ViewportPalette.h"

#include <QApplication>
#include <QTest>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace throng;
using namespace throng::editor;
using namespace throng::editor::test;

namespace {

const QSize kSize{640, 400};

// `nx` x `nz` walkers `spacingM` apart around the origin, headings varied.
sim::Scene crowd(int nx, int nz, float spacingM)
{
    sim::Scene s;
    sim::AgentType walker;
    walker.name = "walker";
    s.agentTypes.push_back(walker);
    const glm::vec2 half = 0.5f * spacingM * glm::vec2(float(nx - 1), float(nz - 1));
    s.settings.boundsMin = -half - glm::vec2(2.0f);
    s.settings.boundsMax = half + glm::vec2(2.0f);
    for (int z = 0; z < nz; ++z)
        for (int x = 0; x < nx; ++x) {
            sim::Agent a;
            a.id = std::uint32_t(s.agents.size() + 1);
            a.type = "walker";
            a.position = {float(x) * spacingM - half.x, 0.0f, float(z) * spacingM - half.y};
            a.headingDeg = float((x * 37 + z * 11) % 360);
            s.agents.push_back(a);
        }
    return s;
}

// An agent's pixel: saturated orange, lit or not (ground, grid and noses are grey).
bool isAgent(QRgb p)
{
    const int hi = std::max({qRed(p), qGreen(p), qBlue(p)}), lo = std::min({qRed(p), qGreen(p), qBlue(p)});
    return hi - lo >= 50 && qRed(p) > qBlue(p);
}

// Blobs of agent pixels (8-connected, at least 3 pixels) that do not touch the border.
int interiorBlobs(const QImage& image)
{
    const int w = image.width(), h = image.height();
    std::vector<int> label(std::size_t(w * h), 0);
    std::vector<int> stack;
    int blobs = 0;
    for (int start = 0; start < w * h; ++start) {
        if (label[std::size_t(start)] || !isAgent(image.pixel(start % w, start / w)))
            continue;
        int size = 0;
        bool border = false;
        stack.push_back(start);
        label[std::size_t(start)] = 1;
        while (!stack.empty()) {
            const int at = stack.back();
            stack.pop_back();
            const int x = at % w, y = at / w;
            ++size;
            border = border || x == 0 || y == 0 || x == w - 1 || y == h - 1;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int nx = x + dx, ny = y + dy;
                    if (nx < 0 || ny < 0 || nx >= w || ny >= h || label[std::size_t(ny * w + nx)])
                        continue;
                    if (!isAgent(image.pixel(nx, ny)))
                        continue;
                    label[std::size_t(ny * w + nx)] = 1;
                    stack.push_back(ny * w + nx);
                }
        }
        blobs += !border && size >= 3;
    }
    return blobs;
}

// True when an agent pixel lies within `reach` pixels of `pos`.
bool agentNear(const QImage& image, const Viewport& viewport, QPointF pos, int reach = 2)
{
    for (int dy = -reach; dy <= reach; ++dy)
        for (int dx = -reach; dx <= reach; ++dx)
            if (isAgent(pixelAt(image, viewport, pos + QPointF(dx, dy))))
                return true;
    return false;
}

// An agent's body or its nose (darker than the ground and the background).
bool isCovered(QRgb p)
{
    return isAgent(p) || std::max({qRed(p), qGreen(p), qBlue(p)}) <= 30;
}

// Share of pixels where both images agree on "agent here or not".
double agreement(const QImage& a, const QImage& b)
{
    int same = 0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x)
            same += isCovered(a.pixel(x, y)) == isCovered(b.pixel(x, y));
    return double(same) / double(a.width() * a.height());
}

// Share of 8 x 8 pixel blocks where both images agree on "mostly agents or not": where
// the crowd is, at the scale of a few agents (a dense far crowd mixes agents, noses and
// ground in each pixel differently at each level of detail).
double blockAgreement(const QImage& a, const QImage& b)
{
    int same = 0, blocks = 0;
    for (int by = 0; by + 8 <= a.height(); by += 8)
        for (int bx = 0; bx + 8 <= a.width(); bx += 8) {
            int inA = 0, inB = 0;
            for (int y = by; y < by + 8; ++y)
                for (int x = bx; x < bx + 8; ++x) {
                    inA += isCovered(a.pixel(x, y));
                    inB += isCovered(b.pixel(x, y));
                }
            same += (inA >= 32) == (inB >= 32);
            ++blocks;
        }
    return double(same) / double(blocks);
}

void zoomIn(Viewport& viewport, int angleDelta)
{
    const QPointF centre(viewport.width() / 2.0, viewport.height() / 2.0);
    QWheelEvent event(centre, viewport.mapToGlobal(centre), QPoint(), QPoint(0, angleDelta), Qt::NoButton,
                      Qt::NoModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(&viewport, &event);
}

int sum(const std::array<int, kAgentDetailLevels>& drawn)
{
    return drawn[0] + drawn[1] + drawn[2];
}

QImage renderWithDetail(Viewport& viewport, bool levelOfDetail)
{
    viewport.setAgentLevelOfDetail(levelOfDetail);
    return viewport.grabFramebuffer();
}

}  // namespace

class TestViewportLevelOfDetail : public QObject {
    Q_OBJECT

private slots:
    void sparseCrowdCloseUpKeepsEveryAgentAcrossTheSwitch()
    {
        const sim::Scene scene = crowd(24, 16, 6.0f);
        Viewport viewport;
        showInitialState(viewport, scene);
        viewport.setViewMode(ViewMode::Orbit);
        renderOffscreen(viewport, kSize);
        QVERIFY2(viewport.isGlReady(), qPrintable(viewport.glProblem()));
        viewport.frameAll();
        zoomIn(viewport, 1000);  // about 3.5x closer: near agents glyphs, far ones impostors

        const QImage lod = renderWithDetail(viewport, true);
        const std::array<int, kAgentDetailLevels> drawn = viewport.agentsDrawnByDetail();
        QVERIFY2(drawn[0] + drawn[1] > 0, "no agent near enough for a glyph: the view does not test the switch");
        QVERIFY2(drawn[2] > 0, "no agent far enough for an impostor: the view does not test the switch");
        const QImage full = renderWithDetail(viewport, false);

        // Every agent whose body's middle projects inside the image shows there, both ways.
        int inside = 0;
        for (const sim::Agent& a : scene.agents) {
            const QPointF pos = viewport.worldToPixel(a.position + glm::vec3(0.0f, 0.8f, 0.0f));
            if (pos.x() < 4 || pos.y() < 4 || pos.x() > kSize.width() - 5 || pos.y() > kSize.height() - 5)
                continue;
            ++inside;
            QVERIFY2(agentNear(lod, viewport, pos),
                     qPrintable(QString("no agent at (%1, %2) with level of detail").arg(pos.x()).arg(pos.y())));
            QVERIFY2(agentNear(full, viewport, pos),
                     qPrintable(QString("no agent at (%1, %2) in full detail").arg(pos.x()).arg(pos.y())));
        }
        QVERIFY2(inside > 80, qPrintable(QString::number(inside)));
        // As many separate agents as full detail shows: none dropped, none merged.
        const int lodBlobs = interiorBlobs(lod), fullBlobs = interiorBlobs(full);
        QVERIFY2(std::abs(lodBlobs - fullBlobs) <= 1,
                 qPrintable(QString("%1 agents with level of detail, %2 in full detail").arg(lodBlobs).arg(fullBlobs)));
        QVERIFY2(lodBlobs >= inside - inside / 20,
                 qPrintable(QString("%1 agents seen, %2 stand inside the image").arg(lodBlobs).arg(inside)));
        QVERIFY2(agreement(lod, full) > 0.99, qPrintable(QString::number(agreement(lod, full))));
    }

    void hundredThousandAgentsShowNearAndFar_data()
    {
        QTest::addColumn<int>("mode");
        QTest::addColumn<int>("zoomDelta");
        QTest::newRow("top, all in view") << int(ViewMode::Top) << 0;
        QTest::newRow("3D, all in view") << int(ViewMode::Orbit) << 0;
        QTest::newRow("3D, close up") << int(ViewMode::Orbit) << 1760;  // about 9x closer
    }

    void hundredThousandAgentsShowNearAndFar()
    {
        QFETCH(int, mode);
        QFETCH(int, zoomDelta);
        const sim::Scene scene = crowd(400, 250, 1.0f);
        Viewport viewport;
        showInitialState(viewport, scene);
        viewport.setViewMode(ViewMode(mode));
        renderOffscreen(viewport, kSize);
        QVERIFY2(viewport.isGlReady(), qPrintable(viewport.glProblem()));
        QCOMPARE(viewport.agentCount(), std::size_t(100000));
        viewport.frameAll();
        if (zoomDelta)
            zoomIn(viewport, zoomDelta);

        const QImage lod = renderWithDetail(viewport, true);
        const std::array<int, kAgentDetailLevels> drawn = viewport.agentsDrawnByDetail();
        if (zoomDelta == 0) {
            QCOMPARE(sum(drawn), 100000);  // all in view: none left out
        } else {
            QVERIFY2(drawn[0] + drawn[1] > 0 && drawn[2] > 0 && sum(drawn) < 100000,
                     qPrintable(QString("%1 detailed, %2 coarse, %3 impostors").arg(drawn[0]).arg(drawn[1]).arg(drawn[2])));
        }
        const QImage full = renderWithDetail(viewport, false);

        // Agents near the camera (south), at the centre and far away (north), and the
        // crowd's east and west ends, where they are in view. Close up, the south end is
        // behind the eye: agents from just in front of it to far beyond the centre.
        const std::vector<glm::vec3> allInView{{0.5f, 0.0f, 124.5f}, {0.5f, 0.0f, 0.5f},   {0.5f, 0.0f, -124.5f},
                                               {-199.5f, 0.0f, 0.5f}, {199.5f, 0.0f, 0.5f}, {0.5f, 0.0f, 60.5f}};
        const std::vector<glm::vec3> closeUp{{0.5f, 0.0f, 12.5f},  {0.5f, 0.0f, 0.5f},    {4.5f, 0.0f, -9.5f},
                                             {0.5f, 0.0f, -60.5f}, {-20.5f, 0.0f, -80.5f}, {0.5f, 0.0f, -120.5f}};
        int sampled = 0;
        for (const glm::vec3& at : zoomDelta ? closeUp : allInView) {
            const float lift = mode == int(ViewMode::Top) ? 0.0f : 0.8f;
            const QPointF pos = viewport.worldToPixel(at + glm::vec3(0.0f, lift, 0.0f));
            if (pos.x() < 2 || pos.y() < 2 || pos.x() > kSize.width() - 3 || pos.y() > kSize.height() - 3)
                continue;
            ++sampled;
            QVERIFY2(agentNear(lod, viewport, pos, 1),
                     qPrintable(QString("no agent at (%1, %2) for the one at %3, %4")
                                    .arg(pos.x())
                                    .arg(pos.y())
                                    .arg(double(at.x))
                                    .arg(double(at.z))));
        }
        QVERIFY(sampled >= 3);
        // Off the crowd is ground: the image corner beside the whole crowd.
        if (zoomDelta == 0)
            QVERIFY(!isAgent(lod.pixel(2, 2)));
        QVERIFY2(blockAgreement(lod, full) > 0.98, qPrintable(QString::number(blockAgreement(lod, full))));
    }
};

THRONG_REGISTER_TEST(TestViewportLevelOfDetail)
#include "TestViewportLevelOfDetail.moc"
