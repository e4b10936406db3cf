// Agents as characters in the 3D view, as a user sees them: a walker stands as a figure
// of its character's height, its top in its tint, differs from its glyph, moves its legs as
// it walks a quarter stride on, raises a hand when its brain waves; a type without a
// character keeps its glyph; a crowd seen close up shows every agent, near ones as
// characters.
#include "EditorTestSupport.h"
#include "ShowInitialState.h"
#include "TestRegistry.h"

#include "editor/viewport/PoseTable.h"
#include "export/character/AgentVariation.h"
#include "export/character/BuiltinCharacters.h"
#include "simcore/world/FrameCache.h"

#include <QAction>
#include <QApplication>
#include <QSettings>
#include <QTest>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>

using namespace throng;
using namespace throng::editor;
using namespace throng::editor::test;

namespace {

const QSize kSize{640, 480};
const glm::vec3 kTint{0.9f, 0.35f, 0.1f};

// One walker at the origin facing east (seen from the side by the default 3D camera, which
// looks north), framed by two walls; its type wears the man in one orange tint at height 1.
QByteArray walkerYaml(const char* character = "man")
{
    return QStringLiteral("throng: 1\n"
                          "settings: {bounds: {min: [-6, -6], max: [6, 6]}}\n"
                          "agent_types:\n"
                          "  - {name: walker, radius: 0.3, character: %1,\n"
                          "     variation: {tints: [[0.9, 0.35, 0.1]], height: [1, 1]}}\n"
                          "agents:\n"
                          "  - {type: walker, position: [0, 0], heading: 0}\n"
                          // Low walls: in 3D they must hide none of the character.
                          "walls:\n"
                          "  - {points: [[-3, -2], [3, -2]], height: 0.1}\n"
                          "  - {points: [[-3, 2], [3, 2]], height: 0.1}\n")
        .arg(character)
        .toUtf8();
}

// A pixel in the walker's tint, lit or in shade (ground, grid, walls and background are
// grey): its glyph, or its character's top.
bool isTinted(QRgb p)
{
    return qRed(p) - qBlue(p) > 60 && qRed(p) > qGreen(p) + 25;
}

// A pixel of the walker, whatever part of it (skin, clothes, hair): one that differs from
// the view without it.
bool isWalker(QRgb p, QRgb background)
{
    return std::abs(qRed(p) - qRed(background)) + std::abs(qGreen(p) - qGreen(background)) +
               std::abs(qBlue(p) - qBlue(background)) > 24;
}

// The view without the agents (a run that recorded nobody), from the same camera.
QImage backgroundOf(Viewport& viewport)
{
    static const sim::FrameCache nobody;
    viewport.showFrame(nobody, 0);
    return viewport.grabFramebuffer();
}

struct Silhouette {
    QRect box;
    int pixels = 0;
    QRgb brightest = 0;
    int legsWidth = 0;  // width of the lowest quarter of the box, px
};

Silhouette silhouetteOf(const QImage& image, const QImage& background)
{
    Silhouette s;
    int left = image.width(), right = -1, top = image.height(), bottom = -1, best = -1;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            const QRgb p = image.pixel(x, y);
            if (!isWalker(p, background.pixel(x, y)))
                continue;
            ++s.pixels;
            left = std::min(left, x);
            right = std::max(right, x);
            top = std::min(top, y);
            bottom = std::max(bottom, y);
            if (isTinted(p) && qRed(p) > best) {
                best = qRed(p);
                s.brightest = p;
            }
        }
    if (s.pixels == 0)
        return s;
    s.box = QRect(QPoint(left, top), QPoint(right, bottom));
    int legsLeft = right, legsRight = left;
    for (int y = bottom - s.box.height() / 4; y <= bottom; ++y)
        for (int x = left; x <= right; ++x)
            if (isWalker(image.pixel(x, y), background.pixel(x, y))) {
                legsLeft = std::min(legsLeft, x);
                legsRight = std::max(legsRight, x);
            }
    s.legsWidth = legsRight - legsLeft + 1;
    return s;
}

// Share of pixels covered by the walker in one image and not the other, of those in either.
double difference(const QImage& a, const QImage& b, const QImage& background)
{
    int either = 0, one = 0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x) {
            const QRgb under = background.pixel(x, y);
            const bool inA = isWalker(a.pixel(x, y), under), inB = isWalker(b.pixel(x, y), under);
            either += inA || inB;
            one += inA != inB;
        }
    return either ? double(one) / double(either) : 0.0;
}

// The man as the view draws agent 1 near the camera: the middle level of detail, and per
// vertex whether the agent wears it (a hat or a backpack only some agents wear).
struct ShownMan {
    PoseTable table;
    std::vector<bool> worn;
};

ShownMan shownMan(std::uint64_t seed)
{
    const exporting::Character man = *exporting::makeBuiltinCharacter("man", exporting::Lod::Mid);
    ShownMan shown{buildPoseTable(man), std::vector<bool>(man.mesh.positions.size(), false)};
    for (const exporting::MeshPart& part : exporting::partsOf(man.mesh))
        if (exporting::wearsPart(part, seed, 1))
            for (std::uint32_t i = part.firstIndex; i < part.firstIndex + part.indexCount; ++i)
                shown.worn[man.mesh.indices[i]] = true;
    return shown;
}

// The man's height standing in his idle pose as agent 1 wears him, m.
float manHeightM(std::uint64_t seed)
{
    const ShownMan man = shownMan(seed);
    float top = 0.0f;
    for (std::size_t v = 0; v < man.table.vertexCount; ++v)
        if (man.worn[v])
            top = std::max(top, man.table.positions[v].y);
    return top;
}

// A recording of the walker: one frame per phase, walking east on the spot.
// One walker heading +x at 1.3 m/s, recorded `walked` m along (one frame each): its legs
// cycle by the distance, as the export's do (the man's walk: 1.29 m a cycle).
constexpr float kManStrideM = 1.29f;
sim::FrameCache walkingFrames(std::initializer_list<float> walked)
{
    sim::FrameCache cache;
    cache.reset({sim::AgentInfo{1, 0}}, 24.0f);
    for (float x : walked) {
        sim::AgentFrame f;
        f.position = glm::vec3(x, 0.0f, 0.0f);
        f.speed = 1.3f;
        f.phase = x / kManStrideM;
        f.clip = sim::Clip::Walk;
        cache.append({&f, 1});
    }
    return cache;
}

void zoomIn(Viewport& viewport, int angleDelta)
{
    const QPointF centre(viewport.width() / 2.0, viewport.height() / 2.0);
    QWheelEvent event(centre, viewport.mapToGlobal(centre), QPoint(), QPoint(0, angleDelta), Qt::NoButton,
                      Qt::NoModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(&viewport, &event);
}

QString describe(const Silhouette& s)
{
    return QString("%1 x %2 px at (%3, %4), %5 pixels, legs %6 px wide")
        .arg(s.box.width())
        .arg(s.box.height())
        .arg(s.box.left())
        .arg(s.box.top())
        .arg(s.pixels)
        .arg(s.legsWidth);
}

}  // namespace

class TestViewportCharacters : public QObject {
    Q_OBJECT

private:
    QTemporaryDir m_dir;

    void saveForInspection(const QImage& image, const QString& name)
    {
        // THRONG_TEST_IMAGES=folder keeps the renders to look at.
        const QString folder = qEnvironmentVariable("THRONG_TEST_IMAGES");
        if (!folder.isEmpty())
            image.save(folder + "/" + name + ".png");
    }

private slots:
    void initTestCase()
    {
        QSettings().remove("viewport/agentsAs");
    }

    void viewMenuChoosesCharactersOrGlyphsAndRemembers()
    {
        {
            MainWindow window;
            QVERIFY(window.viewport().agentsAsCharacters());  // characters unless chosen otherwise
            auto* glyphs = window.findChild<QAction*>("agentsAsGlyphsAction");
            auto* characters = window.findChild<QAction*>("agentsAsCharactersAction");
            QVERIFY(glyphs && characters);
            QVERIFY(characters->isChecked());
            QVERIFY(!glyphs->toolTip().isEmpty() && !characters->toolTip().isEmpty());
            glyphs->trigger();
            QVERIFY(!window.viewport().agentsAsCharacters());
        }
        {
            MainWindow reopened;
            QVERIFY(!reopened.viewport().agentsAsCharacters());
            QVERIFY(reopened.findChild<QAction*>("agentsAsGlyphsAction")->isChecked());
            reopened.findChild<QAction*>("agentsAsCharactersAction")->trigger();
            QVERIFY(reopened.viewport().agentsAsCharacters());
        }
        QCOMPARE(QSettings().value("viewport/agentsAs").toString(), QString("characters"));
    }

    void walkerStandsAsItsCharacterInItsTint()
    {
        Viewport viewport;
        viewport.setAgentsAsCharacters(true);
        viewport.setViewMode(ViewMode::Orbit);
        const sim::Scene scene = loadTestScene(m_dir, walkerYaml());
        showInitialState(viewport, scene);
        const QImage image = renderOffscreen(viewport, kSize);
        QVERIFY2(viewport.isGlReady(), qPrintable(viewport.glProblem()));
        saveForInspection(image, "character");
        QCOMPARE(viewport.charactersDrawn(), 1);
        const Silhouette s = silhouetteOf(image, backgroundOf(viewport));
        QVERIFY2(s.pixels > 200, qPrintable(describe(s)));

        // As tall on screen as the man's height where he stands, feet on the ground.
        const QPointF feet = viewport.worldToPixel({0.0f, 0.0f, 0.0f});
        const QPointF head = viewport.worldToPixel({0.0f, manHeightM(scene.settings.seed), 0.0f});
        const double expected = feet.y() - head.y();
        QVERIFY2(std::abs(s.box.height() - expected) < 0.15 * expected,
                 qPrintable(describe(s) + QString(", expected %1 px tall").arg(expected)));
        QVERIFY2(std::abs(s.box.bottom() - feet.y()) < 0.1 * expected,
                 qPrintable(describe(s) + QString(", feet at y %1").arg(feet.y())));
        // A standing figure: taller than wide.
        QVERIFY2(s.box.height() > 1.5 * s.box.width(), qPrintable(describe(s)));

        // Its top's lit side in the tint, shaded: the channels keep the tint's proportions.
        QVERIFY(s.brightest != 0);
        const double r = qRed(s.brightest);
        QVERIFY2(r > 0.8 * 255 * kTint.r, qPrintable(editor::test::describe(s.brightest)));
        QVERIFY2(std::abs(qGreen(s.brightest) / r - kTint.g / kTint.r) < 0.06 &&
                     std::abs(qBlue(s.brightest) / r - kTint.b / kTint.r) < 0.06,
                 qPrintable(editor::test::describe(s.brightest) + " is not the tint (0.9, 0.35, 0.1) shaded"));
    }

    void glyphsChosenDrawTheGlyphInstead()
    {
        Viewport viewport;
        viewport.setViewMode(ViewMode::Orbit);
        viewport.setAgentsAsCharacters(true);
        const sim::Scene scene = loadTestScene(m_dir, walkerYaml());
        showInitialState(viewport, scene);
        const QImage character = renderOffscreen(viewport, kSize);
        viewport.setAgentsAsCharacters(false);
        const QImage glyph = viewport.grabFramebuffer();
        saveForInspection(glyph, "glyph");
        QCOMPARE(viewport.charactersDrawn(), 0);
        const QImage background = backgroundOf(viewport);
        const Silhouette g = silhouetteOf(glyph, background);
        QVERIFY2(g.pixels > 100 && g.brightest != 0, qPrintable(describe(g)));  // the glyph is there, in the tint too
        const double d = difference(character, glyph, background);
        QVERIFY2(d > 0.3, qPrintable(QString("the character and the glyph differ in %1 of their pixels").arg(d)));
    }

    void legsMoveWithTheDistanceWalked()
    {
        Viewport viewport;
        viewport.setViewMode(ViewMode::Orbit);
        viewport.setAgentsAsCharacters(true);
        const sim::Scene scene = loadTestScene(m_dir, walkerYaml());
        showInitialState(viewport, scene);
        renderOffscreen(viewport, kSize);
        const QImage background = backgroundOf(viewport);
        const sim::FrameCache cache = walkingFrames({0.0f, 0.25f * kManStrideM});  // a quarter cycle on
        viewport.showFrame(cache, 0);
        const QImage stride = viewport.grabFramebuffer();
        viewport.showFrame(cache, 1);
        const QImage passing = viewport.grabFramebuffer();
        saveForInspection(stride, "phase0");
        saveForInspection(passing, "phase25");
        const Silhouette a = silhouetteOf(stride, background), b = silhouetteOf(passing, background);
        QVERIFY2(a.pixels > 200 && b.pixels > 200, qPrintable(describe(a) + " / " + describe(b)));
        // A quarter cycle apart the feet are apart and then together (or the reverse).
        const double wider = std::max(a.legsWidth, b.legsWidth), narrower = std::min(a.legsWidth, b.legsWidth);
        QVERIFY2(wider > 1.3 * narrower, qPrintable(describe(a) + " / " + describe(b)));
        const double d = difference(stride, passing, background);
        QVERIFY2(d > 0.1, qPrintable(QString::number(d)));
    }

    // A brain's action plays in the view: a bystander turned so its right side faces
    // east waves, and the figure on screen is the wave's pose (its top and right edge
    // where the pose's vertices project, a hand's breadth above and beside the standing
    // figure's), then stands again.
    void wavingBystanderRaisesAHand()
    {
        Viewport viewport;
        viewport.setViewMode(ViewMode::Orbit);
        viewport.setAgentsAsCharacters(true);
        const sim::Scene scene = loadTestScene(m_dir, walkerYaml());
        showInitialState(viewport, scene);
        renderOffscreen(viewport, kSize);
        const QImage background = backgroundOf(viewport);
        const float heading = 1.5707963f;  // the nose to -z (north), the right side to +x (east)
        sim::FrameCache cache;
        cache.reset({sim::AgentInfo{1, 0}}, 24.0f);
        for (const sim::Clip clip : {sim::Clip::Idle, sim::Clip::Wave, sim::Clip::Idle}) {
            sim::AgentFrame f;
            f.clip = clip;
            f.headingRad = heading;
            cache.append({&f, 1});
        }
        // Where pose p of the man's table lies on screen: its top and right edge, px.
        const ShownMan man = shownMan(scene.settings.seed);
        const PoseTable& table = man.table;
        auto projected = [&](int pose) {
            double top = 1e9, right = -1e9;
            for (std::size_t v = 0; v < table.vertexCount; ++v) {
                if (!man.worn[v])
                    continue;
                const glm::vec3 p = table.positions[std::size_t(pose) * table.vertexCount + v];
                const glm::vec3 world(p.x * std::cos(heading) + p.z * std::sin(heading), p.y,
                                      -p.x * std::sin(heading) + p.z * std::cos(heading));
                const QPointF q = viewport.worldToPixel(world);
                top = std::min(top, q.y());
                right = std::max(right, q.x());
            }
            return QRectF(QPointF(right - 1.0, top), QPointF(right, top + 1.0));
        };
        const double tenCm =
            viewport.worldToPixel({0.0f, 1.6f, 0.0f}).y() - viewport.worldToPixel({0.0f, 1.7f, 0.0f}).y();
        std::vector<Silhouette> seen;
        std::vector<QRectF> expected;
        for (std::size_t frame = 0; frame < 3; ++frame) {
            viewport.showFrame(cache, frame);
            const QImage image = viewport.grabFramebuffer();
            saveForInspection(image, QString("wave%1").arg(frame));
            seen.push_back(silhouetteOf(image, background));
            QVERIFY2(seen.back().pixels > 200, qPrintable(describe(seen.back())));
            const sim::AgentFrame& f = cache.at(frame, 0);
            const float actionPhase = sim::actionPhase(f.clip, double(frame) / 24.0, 1);
            expected.push_back(projected(table.poseFor(f.clip, f.phase, actionPhase, false)));
            QVERIFY2(std::abs(seen.back().box.top() - expected.back().top()) < 3.0 &&
                         std::abs(seen.back().box.right() - expected.back().right()) < 3.0,
                     qPrintable(QString("frame %1: %2, the pose projects to top %3, right %4")
                                    .arg(frame)
                                    .arg(describe(seen.back()))
                                    .arg(expected.back().top())
                                    .arg(expected.back().right())));
        }
        QVERIFY2(seen[0].box.top() - seen[1].box.top() > tenCm && seen[1].box.right() - seen[0].box.right() > tenCm,
                 qPrintable(describe(seen[0]) + " / " + describe(seen[1]) + QString(", 10 cm = %1 px").arg(tenCm)));
        QCOMPARE(seen[2].box, seen[0].box);
    }

    // A hat shows on the agents that wear one and on no other: with a seed that gives
    // agent 1 a hat the figure's top is the hat's, above the hair; with one that does not,
    // the hair is the top.
    void hatsShowOnlyOnTheAgentsThatWearThem()
    {
        const exporting::Character man = *exporting::makeBuiltinCharacter("man", exporting::Lod::Mid);
        const exporting::MeshPart* hat = nullptr;
        for (const exporting::MeshPart& part : man.mesh.parts)
            if (part.slot == exporting::MaterialSlot::Hat)
                hat = &part;
        QVERIFY(hat && hat->wornShare < 1.0f);
        std::uint64_t seeds[2] = {0, 0};  // [0]: agent 1 wears no hat, [1]: it does
        for (std::uint64_t seed = 1; seed < 500 && (seeds[0] == 0 || seeds[1] == 0); ++seed)
            if (seeds[exporting::wearsPart(*hat, seed, 1) ? 1 : 0] == 0)
                seeds[exporting::wearsPart(*hat, seed, 1) ? 1 : 0] = seed;
        QVERIFY(seeds[0] != 0 && seeds[1] != 0);
        for (const bool wearing : {false, true}) {
            const std::uint64_t seed = seeds[wearing ? 1 : 0];
            QByteArray yaml = walkerYaml();
            yaml.replace("settings: {", "settings: {seed: " + QByteArray::number(qulonglong(seed)) + ", ");
            Viewport viewport;
            viewport.setViewMode(ViewMode::Orbit);
            viewport.setAgentsAsCharacters(true);
            const sim::Scene scene = loadTestScene(m_dir, yaml);
            QCOMPARE(scene.settings.seed, seed);
            showInitialState(viewport, scene);
            const QImage image = renderOffscreen(viewport, kSize);
            saveForInspection(image, wearing ? "hat" : "nohat");
            const Silhouette s = silhouetteOf(image, backgroundOf(viewport));
            const ShownMan shown = shownMan(seed);
            float hair = 0.0f;
            for (std::size_t v = 0; v < shown.table.vertexCount; ++v)
                if (shown.worn[v] && shown.table.materialSlots[v] != std::uint8_t(exporting::MaterialSlot::Hat))
                    hair = std::max(hair, shown.table.positions[v].y);
            const double hairPx = viewport.worldToPixel({0.0f, hair, 0.0f}).y();
            const double tenCm =
                viewport.worldToPixel({0.0f, 1.6f, 0.0f}).y() - viewport.worldToPixel({0.0f, 1.7f, 0.0f}).y();
            const QString what = describe(s) + QString(", hair top at %1 px, 10 cm = %2 px").arg(hairPx).arg(tenCm);
            if (wearing)
                QVERIFY2(hairPx - s.box.top() > 0.3 * tenCm, qPrintable("with a hat: " + what));
            else
                QVERIFY2(std::abs(s.box.top() - hairPx) < 4.0, qPrintable("without: " + what));
        }
    }

    void typeWithoutItsCharacterKeepsTheGlyph()
    {
        // Built in code: a scene file naming a missing character would not load at all.
        sim::Scene scene = loadTestScene(m_dir, walkerYaml());
        scene.agentTypes[0].character = "no_such_character.glb";
        Viewport viewport;
        viewport.setViewMode(ViewMode::Orbit);
        viewport.setAgentsAsCharacters(true);
        showInitialState(viewport, scene);
        const QImage image = renderOffscreen(viewport, kSize);
        QCOMPARE(viewport.charactersDrawn(), 0);
        const QRgb body = pixelAt(image, viewport, viewport.worldToPixel({0.0f, 0.8f, 0.0f}));
        QVERIFY2(isTinted(body), qPrintable(editor::test::describe(body) + " where the walker's glyph should stand"));
    }

    void crowdCloseUpShowsEveryAgentNearOnesAsCharacters()
    {
        QByteArray yaml = "throng: 1\n"
                          "settings: {bounds: {min: [-75, -50], max: [75, 50]}}\n"
                          "agent_types:\n"
                          "  - {name: walker, radius: 0.3, variation: {tints: [[0.9, 0.35, 0.1]]}}\n"
                          "agents:\n";
        std::vector<glm::vec3> at;
        // 24 x 16 walkers 6 m apart: close up, near ones large and far ones a few pixels.
        for (int z = -8; z < 8; ++z)
            for (int x = -12; x < 12; ++x) {
                at.push_back({6.0f * float(x) + 3.0f, 0.0f, 6.0f * float(z) + 3.0f});
                yaml += QStringLiteral("  - {type: walker, position: [%1, %2], heading: %3}\n")
                            .arg(at.back().x)
                            .arg(at.back().z)
                            .arg((x * 37 + z * 11) % 360)
                            .toUtf8();
            }
        Viewport viewport;
        viewport.setViewMode(ViewMode::Orbit);
        viewport.setAgentsAsCharacters(true);
        const sim::Scene scene = loadTestScene(m_dir, yaml);
        showInitialState(viewport, scene);
        renderOffscreen(viewport, kSize);
        viewport.frameAll();
        zoomIn(viewport, 1000);
        const QImage image = viewport.grabFramebuffer();
        saveForInspection(image, "crowd");
        const std::array<int, kAgentDetailLevels> drawn = viewport.agentsDrawnByDetail();
        QVERIFY2(viewport.charactersDrawn() >= 10, qPrintable(QString::number(viewport.charactersDrawn())));
        QVERIFY2(drawn[2] > 0, "no agent far enough for an impostor: the view does not test both");
        QCOMPARE(viewport.charactersDrawn(), drawn[0] + drawn[1]);  // every near agent as its character
        const QImage background = backgroundOf(viewport);

        // Every agent whose waist projects inside the image shows there.
        int inside = 0;
        for (const glm::vec3& p : at) {
            const QPointF pos = viewport.worldToPixel(p + glm::vec3(0.0f, 0.9f, 0.0f));
            if (pos.x() < 4 || pos.y() < 4 || pos.x() > kSize.width() - 5 || pos.y() > kSize.height() - 5)
                continue;
            ++inside;
            bool found = false;
            for (int dy = -2; dy <= 2 && !found; ++dy)
                for (int dx = -2; dx <= 2 && !found; ++dx)
                    found = isWalker(pixelAt(image, viewport, pos + QPointF(dx, dy)),
                                     pixelAt(background, viewport, pos + QPointF(dx, dy)));
            QVERIFY2(found, qPrintable(QString("no agent at (%1, %2)").arg(pos.x()).arg(pos.y())));
        }
        QVERIFY2(inside > 80, qPrintable(QString::number(inside)));
    }
};

THRONG_REGISTER_TEST(TestViewportCharacters)
#include "TestViewportCharacters.moc"
