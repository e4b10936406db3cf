// The horse with its rider, as a user checks it in the exported file: four riders hold
// the speeds of a walk (1 m/s), a trot (3), a canter (5.5) and a gallop (9.5) along
// straight lanes. In the glTF, as a reader evaluates it, each hoof touches the ground
// once a cycle and stays where it landed while it is down (< 1 cm), the hooves land in
// the gait's order (the walk's four beats, the trot's diagonal pairs, the canter's three
// beats, the gallop's four), the rider sits above the horse's back, and the mesh is a
// smooth surface of a few thousand triangles near, fewer far. Compact mode plays each
// rider's gait too, and up a bumpy hillside the hooves stand on the ground.
#include "GltfReadBack.h"
#include "RecordRun.h"
#include "TestRegistry.h"

#include "export/GltfExporter.h"
#include "export/character/BuiltinCharacters.h"
#include "simcore/io/SceneIO.h"
#include "simcore/scene/TerrainHeight.h"
#include "simcore/world/World.h"

#include <QTemporaryDir>
#include <QTest>

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>

using namespace throng;

namespace {

constexpr float kFps = 60.0f;
constexpr std::size_t kFrames = 12 * 60;
constexpr float kFromS = 5.0f;  // measured from here: every rider is at its speed

struct Gait {
    const char* type;
    float speed;
};
constexpr std::array<Gait, 4> kGaits{{{"walker", 1.0f}, {"trotter", 3.0f}, {"canterer", 5.5f}, {"galloper", 9.5f}}};

std::string scene()
{
    std::string yaml = "throng: 1\nsettings: {fps: 60, seed: 3, duration: 12, bounds: {min: [-10, -20], max: "
                       "[200, 20]}}\nagent_types:\n";
    for (const Gait& g : kGaits)
        yaml += std::string("  - {name: ") + g.type + ", character: horse, radius: 0.8, max_speed: " +
                std::to_string(g.speed) + ", max_force: 30, variation: {speed: [1, 1], height: [1, 1]}, " +
                "behaviours: {seek: 1}}\n";
    yaml += "goals:\n";
    for (std::size_t k = 0; k < kGaits.size(); ++k)
        yaml += "  - {name: far_" + std::to_string(k) + ", position: [195, " + std::to_string(-12.0f + 8.0f * k) +
                "], radius: 1}\n";
    yaml += "agents:\n";
    for (std::size_t k = 0; k < kGaits.size(); ++k)
        yaml += "  - {id: " + std::to_string(k + 1) + ", type: " + kGaits[k].type + ", position: [0, 0, " +
                std::to_string(-12.0f + 8.0f * k) + "], heading: 0, goal: far_" + std::to_string(k) + "}\n";
    return yaml;
}

// Riders at a walk, a trot and a canter up a hillside: an 8 % grade along x with bumps of
// +-15 cm on it, as a 70 x 20 m terrain at 0.5 m samples.
float hillAt(float x, float z)
{
    return 0.08f * x + 0.15f * std::sin(0.6f * x) * std::cos(0.4f * z);
}

std::string hillScene()
{
    std::string yaml = "throng: 1\nsettings: {fps: 30, seed: 5, duration: 10, bounds: {min: [-5, -10], max: [65, "
                       "10]}}\nagent_types:\n";
    const float speeds[3] = {1.0f, 3.0f, 5.5f};
    for (int k = 0; k < 3; ++k)
        yaml += "  - {name: rider_" + std::to_string(k) + ", character: horse, radius: 0.8, max_speed: " +
                std::to_string(speeds[k]) + ", max_force: 30, variation: {speed: [1, 1], height: [1, 1]}, " +
                "behaviours: {seek: 1}}\n";
    yaml += "goals:\n";
    for (int k = 0; k < 3; ++k)
        yaml += "  - {name: top_" + std::to_string(k) + ", position: [64, " + std::to_string(-6 + 6 * k) +
                "], radius: 1}\n";
    yaml += "agents:\n";
    for (int k = 0; k < 3; ++k)
        yaml += "  - {id: " + std::to_string(k + 1) + ", type: rider_" + std::to_string(k) + ", position: [0, 0, " +
                std::to_string(-6 + 6 * k) + "], heading: 0, goal: top_" + std::to_string(k) + "}\n";
    yaml += "terrain:\n  origin: [-5, -10]\n  cell: 0.5\n  cols: 141\n  rows: 41\n  heights: [";
    for (int z = 0; z < 41; ++z)
        for (int x = 0; x < 141; ++x)
            yaml += (x + z > 0 ? ", " : "") + std::to_string(hillAt(-5.0f + 0.5f * float(x), -10.0f + 0.5f * float(z)));
    return yaml + "]\n";
}

const char* kHoofNames[4] = {"fore_l", "fore_r", "hind_l", "hind_r"};

std::vector<std::string> hoofChain(int leg)
{
    const std::string end = std::string(kHoofNames[leg]).substr(std::string(kHoofNames[leg]).size() - 1);
    const std::string part = leg < 2 ? "fore" : "hind";
    return {"body", part + "_upper_" + end, part + "_lower_" + end, part + "_hoof_" + end};
}

// One hoof's stance phases as the file shows them: it is down while its joint is within
// 5 mm of the height it stands at (0.08 m) and up again once 3 cm above it; the times it
// touched down, its worst slide while down, and its lowest height.
struct Stance {
    std::vector<float> touchDowns;  // s
    float worstSlideM = 0.0f;
    float lowestM = 1e9f;
};

constexpr float kStandM = 0.08f, kDownM = 0.005f, kUpM = 0.03f;

}  // namespace

class TestHorse : public QObject {
    Q_OBJECT

    QTemporaryDir m_dir;
    tinygltf::Model m_model;
    sim::FrameCache m_cache;

    Stance stance(std::size_t agent, int leg) const { return stanceIn(m_model, agent, leg); }
    Stance stanceIn(const tinygltf::Model& model, std::size_t agent, int leg) const
    {
        const std::string root = "agent_" + std::to_string(agent + 1) + "_" + kGaits[agent].type;
        std::vector<glm::vec3> at;
        for (std::size_t f = std::size_t(kFromS * kFps); f < kFrames; ++f)
            at.push_back(test::jointWorldAt(model, root, hoofChain(leg), float(f) / kFps));
        Stance s;
        std::size_t start = 0;
        bool down = at[0].y < kStandM + kDownM;
        for (std::size_t k = 0; k < at.size(); ++k) {
            s.lowestM = std::min(s.lowestM, at[k].y);
            if (!down && at[k].y < kStandM + kDownM) {
                down = true;
                start = k;
                s.touchDowns.push_back(kFromS + float(k) / kFps);
            } else if (down && at[k].y > kStandM + kUpM) {
                down = false;
            }
            if (down && at[k].y < kStandM + kDownM)
                s.worstSlideM =
                    std::max(s.worstSlideM, glm::length(glm::vec2(at[k].x - at[start].x, at[k].z - at[start].z)));
        }
        return s;
    }

    // The cycle's length in s at this rider's speed: the gait's stride over its speed.
    float cycleS(std::size_t agent) const
    {
        const exporting::Character horse = exporting::makeHorse(exporting::Lod::Far);
        return horse.ladder[agent].strideM / kGaits[agent].speed;
    }

    // Left fore, right fore, left hind, right hind: the walk's lateral four beats, the
    // trot's diagonals, the canter's three beats (right lead), the gallop's four; each
    // hoof's first landing at or after the left hind's, as a share of the cycle.
    void checkOrder(const tinygltf::Model& model) const
    {
        const std::array<std::array<float, 4>, 4> expected{{{0.25f, 0.75f, 0.0f, 0.5f},
                                                             {0.5f, 0.0f, 0.0f, 0.5f},
                                                             {0.3f, 0.55f, 0.0f, 0.3f},
                                                             {0.45f, 0.57f, 0.0f, 0.12f}}};
        for (std::size_t a = 0; a < kGaits.size(); ++a) {
            const float cycle = cycleS(a);
            const std::vector<float> hind = stanceIn(model, a, 2).touchDowns;
            QVERIFY(!hind.empty());
            for (int leg = 0; leg < 4; ++leg) {
                const std::vector<float> downs = stanceIn(model, a, leg).touchDowns;
                QVERIFY(!downs.empty());
                const float share = std::fmod((downs[0] - hind[0]) / cycle + 10.0f, 1.0f);
                const float want = expected[a][std::size_t(leg)];
                const float off = std::min(std::fabs(share - want), 1.0f - std::fabs(share - want));
                QVERIFY2(off < 0.04f, qPrintable(QString("%1 %2 lands at %3 of the cycle, not %4")
                                                     .arg(kGaits[a].type, kHoofNames[leg])
                                                     .arg(share)
                                                     .arg(want)));
            }
        }
    }

private slots:
    void initTestCase()
    {
        const sim::LoadResult r = sim::parseScene(scene(), "horses.yaml", "");
        QVERIFY2(r.ok(), r.ok() ? "" : r.diagnostics[0].format().c_str());
        sim::World world(r.scene, sim::WorldOptions{0, false, 1});
        test::recordRun(world, kFrames, m_cache);
        for (std::size_t a = 0; a < kGaits.size(); ++a)
            for (std::size_t f = std::size_t(kFromS * kFps); f < kFrames; f += 60)
                QVERIFY2(std::fabs(m_cache.frame(f)[a].speed - kGaits[a].speed) < 0.02f * kGaits[a].speed,
                         qPrintable(QString("%1 at %2 m/s").arg(kGaits[a].type).arg(m_cache.frame(f)[a].speed)));
        exporting::GltfOptions options;
        options.path = m_dir.filePath("horses.glb").toStdString();
        QVERIFY(exporting::exportGltf(r.scene, m_cache, options).ok());
        std::string error;
        QVERIFY2(test::loadGltf(options.path, m_model, error), error.c_str());
    }

    void theCharacterIsWhole()
    {
        const exporting::Character near = exporting::makeHorse(exporting::Lod::Near);
        const exporting::Character far = exporting::makeHorse(exporting::Lod::Far);
        QCOMPARE(QString::fromStdString(exporting::checkCharacter(near)), QString());
        QCOMPARE(QString::fromStdString(exporting::checkCharacter(far)), QString());
        const std::size_t nearTriangles = near.mesh.indices.size() / 3, farTriangles = far.mesh.indices.size() / 3;
        QVERIFY2(nearTriangles > 3000 && nearTriangles < 15000, qPrintable(QString::number(nearTriangles)));
        QVERIFY2(farTriangles < nearTriangles / 2, qPrintable(QString::number(farTriangles)));
        QCOMPARE(near.ladder.size(), std::size_t(4));
        QCOMPARE(QString::fromStdString(near.ladder[1].name), QString("trot"));
        QVERIFY(exporting::makeBuiltinCharacter("horse").has_value());
    }

    // While down, no hoof moves more than 1 cm; each lands once a cycle, in every gait.
    void hoovesStayWhereTheyLand()
    {
        for (std::size_t a = 0; a < kGaits.size(); ++a) {
            float worst = 0.0f, lowest = 1e9f;
            for (int leg = 0; leg < 4; ++leg) {
                const Stance s = stance(a, leg);
                worst = std::max(worst, s.worstSlideM);
                lowest = std::min(lowest, s.lowestM);
                const QString what = QString("%1 %2").arg(kGaits[a].type, kHoofNames[leg]);
                QVERIFY2(s.worstSlideM < 0.01f, qPrintable(what + QString(": slides %1 m").arg(s.worstSlideM)));
                // Never more than 1 cm into the ground.
                QVERIFY2(s.lowestM > kStandM - 0.01f, qPrintable(what + QString(": lowest %1").arg(s.lowestM)));
                const float windowS = float(kFrames) / kFps - kFromS;
                const float expected = windowS / cycleS(a);
                QVERIFY2(std::fabs(float(s.touchDowns.size()) - expected) <= 1.5f,
                         qPrintable(what + QString(": %1 touch-downs, %2 cycles")
                                               .arg(s.touchDowns.size())
                                               .arg(expected)));
                for (std::size_t k = 1; k < s.touchDowns.size(); ++k)
                    QVERIFY2(std::fabs(s.touchDowns[k] - s.touchDowns[k - 1] - cycleS(a)) < 2.5f / kFps,
                             qPrintable(what + ": an uneven beat"));
            }
            qInfo("%s at %.1f m/s: worst slide while down %.1f mm, lowest hoof joint %.1f mm (standing: 80)",
                  kGaits[a].type, double(kGaits[a].speed), 1000.0 * double(worst), 1000.0 * double(lowest));
        }
    }

    // When each hoof lands in the cycle, relative to the left hind, as a share of it.
    void theHoovesLandInTheGaitsOrder() { checkOrder(m_model); }

    // Compact mode keeps each rider in the rung of the ladder it rides most (all shot but
    // its start, here): its hooves stay where they land (within 1.5 cm) and land in that
    // gait's order.
    void compactPlaysEachRidersGait()
    {
        const sim::LoadResult r = sim::parseScene(scene(), "horses.yaml", "");
        QVERIFY(r.ok());
        exporting::GltfOptions options;
        options.path = m_dir.filePath("horses-compact.glb").toStdString();
        options.mode = exporting::GltfMode::Compact;
        QVERIFY(exporting::exportGltf(r.scene, m_cache, options).ok());
        tinygltf::Model compact;
        std::string error;
        QVERIFY2(test::loadGltf(options.path, compact, error), error.c_str());
        for (std::size_t a = 0; a < kGaits.size(); ++a)
            for (int leg = 0; leg < 4; ++leg) {
                const Stance s = stanceIn(compact, a, leg);
                // The bar TestBakedFeet holds the humanoids' compact feet to.
                QVERIFY2(s.worstSlideM < 0.015f, qPrintable(QString("%1 %2: slides %3 m in compact")
                                                               .arg(kGaits[a].type, kHoofNames[leg])
                                                               .arg(s.worstSlideM)));
            }
        checkOrder(compact);
    }

    // Up a bumpy hillside the hooves stand on the terrain: while a hoof is down (within
    // 5 mm of where it stands on the ground under it) it slides less than 1 cm; no hoof
    // is ever more than 2 cm under the ground; and walking, at every frame the lower hoof
    // of each end is within 2 cm of the ground (a walk always has one down there).
    void hoovesStandOnTheHillside()
    {
        const sim::LoadResult r = sim::parseScene(hillScene(), "hill.yaml", "");
        QVERIFY2(r.ok(), r.ok() ? "" : r.diagnostics[0].format().c_str());
        sim::World world(r.scene, sim::WorldOptions{0, false, 1});
        sim::FrameCache cache;
        const std::size_t frames = 10 * 30;
        test::recordRun(world, frames, cache);
        exporting::GltfOptions options;
        options.path = m_dir.filePath("hill.glb").toStdString();
        QVERIFY(exporting::exportGltf(r.scene, cache, options).ok());
        tinygltf::Model model;
        std::string error;
        QVERIFY2(test::loadGltf(options.path, model, error), error.c_str());
        const sim::Terrain& terrain = r.scene.terrain;
        for (int a = 0; a < 3; ++a) {
            const std::string root = "agent_" + std::to_string(a + 1) + "_rider_" + std::to_string(a);
            float worstSlide = 0.0f, deepest = 0.0f, worstLowest = 0.0f;
            std::array<std::vector<glm::vec3>, 4> hooves;
            for (int leg = 0; leg < 4; ++leg)
                for (std::size_t f = 30; f < frames; ++f)  // from 1 s: every rider on its way
                    hooves[std::size_t(leg)].push_back(
                        test::jointWorldAt(model, root, hoofChain(leg), float(f) / 30.0f));
            auto above = [&](const glm::vec3& p) { return p.y - kStandM - sim::terrainHeight(terrain, p.x, p.z); };
            for (int leg = 0; leg < 4; ++leg) {
                const std::vector<glm::vec3>& at = hooves[std::size_t(leg)];
                std::size_t start = 0;
                bool down = false;
                for (std::size_t k = 0; k < at.size(); ++k) {
                    const float h = above(at[k]);
                    deepest = std::min(deepest, h);
                    if (!down && h < kDownM) {
                        down = true;
                        start = k;
                    } else if (down && h > kUpM) {
                        down = false;
                    }
                    if (down && h < kDownM)
                        worstSlide = std::max(worstSlide, glm::length(glm::vec2(at[k].x - at[start].x,
                                                                                at[k].z - at[start].z)));
                }
            }
            // At a walk each end always has a hoof down: the lower of its two on the ground.
            for (std::size_t k = 0; a == 0 && k < hooves[0].size(); ++k)
                for (int end = 0; end < 2; ++end)
                    worstLowest =
                        std::max(worstLowest, std::min(std::fabs(above(hooves[std::size_t(2 * end)][k])),
                                                       std::fabs(above(hooves[std::size_t(2 * end + 1)][k]))));
            qInfo("rider %d up the hill: worst slide while down %.1f mm, deepest hoof %.1f mm under the ground",
                  a, 1000.0 * double(worstSlide), -1000.0 * double(deepest));
            QVERIFY2(worstSlide < 0.01f, qPrintable(QString("rider %1 slides %2 m").arg(a).arg(worstSlide)));
            QVERIFY2(deepest > -0.02f,
                     qPrintable(QString("rider %1: a hoof %2 m under the ground").arg(a).arg(deepest)));
            QVERIFY2(worstLowest < 0.02f, qPrintable(QString("walking, an end %1 m off the ground").arg(worstLowest)));
        }
    }

    // The rider's hips stay in the saddle on the horse's back, however it moves.
    void theRiderSitsOnTheHorse()
    {
        for (std::size_t a = 0; a < kGaits.size(); ++a) {
            const std::string root = "agent_" + std::to_string(a + 1) + "_" + kGaits[a].type;
            for (std::size_t f = std::size_t(kFromS * kFps); f < kFrames; f += 7) {
                const float t = float(f) / kFps;
                const glm::vec3 seat = test::jointWorldAt(m_model, root, {"body", "rider_hips"}, t);
                const glm::vec3 body = test::jointWorldAt(m_model, root, {"body"}, t);
                // 0.42 m from the body joint in the saddle, however the horse pitches.
                QVERIFY2(std::fabs(glm::distance(seat, body) - 0.418f) < 0.01f,
                         qPrintable(QString::number(glm::distance(seat, body))));
                QVERIFY2(seat.y > body.y + 0.3f, qPrintable(QString::number(seat.y - body.y)));
                QVERIFY(std::fabs(seat.z - body.z) < 0.01f);
            }
        }
    }
};

THRONG_REGISTER_TEST(TestHorse)
#include "TestHorse.moc"
