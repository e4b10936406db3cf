// The viewport's characters show the motion the export writes: for a recorded run whose
// brains wave, fall and get up, the pose the viewport picks for each agent at a frame
// (AgentCharacters, from the frame cache, as Viewport::setAgents does) puts the head and
// the right hand where the exported glTF, as a reader evaluates it, puts them. Held poses
// (standing, lying, getting up done) agree to a centimetre; moving ones within a centimetre
// of how far the file's joint moves in half the time between two of the viewport's poses
// (8 a cycle; a one-shot's 8 span it from start to end), the most the nearest pose can miss.
// Riders at each of the horse's four gaits put every hoof where the file does: the same
// gait, at the same phase of it; riders that wave at each gait hold the hand up where the
// file does, within the wave's own swing (the viewport shows it at mid-cycle).
#include "GltfReadBack.h"
#include "RecordRun.h"
#include "TestRegistry.h"

#include "editor/viewport/AgentCharacters.h"
#include "export/character/BuiltinCharacters.h"
#include "export/GltfExporter.h"
#include "simcore/io/SceneIO.h"
#include "simcore/world/World.h"

#include <QTemporaryDir>
#include <QTest>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>

using namespace throng;
using namespace throng::editor;

namespace {

// Agent 1 falls at 1 s and gets up at 4 s; agent 2 waves all along; agent 3 walks by.
constexpr const char* kScene = R"(throng: 1
settings: {fps: 24, seed: 3, duration: 9, bounds: {min: [-10, -10], max: [10, 10]}}
agent_types:
  - {name: faller, character: man, variation: {height: [0.95, 0.95]}, brain: faller}
  - {name: waver, character: woman, variation: {height: [1.05, 1.05]}, brain: waver}
  - {name: walker, character: man, max_speed: 1.3, behaviours: {seek: 1}}
agents:
  - {id: 1, type: faller, position: [0, 0], heading: 30}
  - {id: 2, type: waver, position: [3, 2], heading: -60}
  - {id: 3, type: walker, position: [-6, -4], heading: 0, goal: away}
goals:
  - {name: away, position: [8, -4], radius: 0.5}
brains:
  - name: faller
    nodes:
      - {id: 1, type: input, params: {sensor: time}}
      - {id: 2, type: fuzz.trapezoid, params: {points: [1, 1, 4, 4]}}
      - {id: 3, type: fuzz.trapezoid, params: {points: [4.01, 4.01, 7, 7]}}
      - {id: 4, type: input.constant, params: {value: 0.5}}
      - {id: 5, type: output.action, params: {actions: "idle fall get_up"}}
    links:
      - {from: [1, 0], to: [2, 0]}
      - {from: [1, 0], to: [3, 0]}
      - {from: [4, 0], to: [5, 0]}
      - {from: [2, 0], to: [5, 1]}
      - {from: [3, 0], to: [5, 2]}
  - name: waver
    nodes:
      - {id: 1, type: input.constant, params: {value: 1}}
      - {id: 2, type: output.action, params: {actions: "wave"}}
    links:
      - {from: [1, 0], to: [2, 0]}
)";

// Four riders held at the horse's walk, trot, canter and gallop, side by side.
struct Rider {
    const char* type;
    float speed;   // m/s
    float strideM; // of its gait's cycle (Horse.cpp)
};
constexpr Rider kRiders[4] = {{"walker", 1.0f, 1.6f}, {"trotter", 3.0f, 2.5f}, {"canterer", 5.5f, 3.4f},
                              {"galloper", 9.5f, 5.0f}};

std::string ridersScene(bool waving = false)
{
    std::string yaml = "throng: 1\nsettings: {fps: 24, seed: 4, duration: 8, bounds: {min: [-10, -20], max: "
                       "[120, 20]}}\nagent_types:\n";
    for (const Rider& r : kRiders)
        yaml += std::string("  - {name: ") + r.type + ", character: horse, radius: 0.8, max_speed: " +
                std::to_string(r.speed) + ", max_force: 30, variation: {speed: [1, 1], height: [1, 1]}, " +
                "behaviours: {seek: 1}" + (waving ? ", brain: waver" : "") + "}\n";
    if (waving)
        yaml += "brains:\n  - name: waver\n    nodes:\n      - {id: 1, type: input.constant, params: {value: 1}}\n"
                "      - {id: 2, type: output.action, params: {actions: \"wave\"}}\n"
                "    links:\n      - {from: [1, 0], to: [2, 0]}\n";
    yaml += "goals:\n";
    for (int k = 0; k < 4; ++k)
        yaml += "  - {name: far_" + std::to_string(k) + ", position: [115, " + std::to_string(-12 + 8 * k) +
                "], radius: 1}\n";
    yaml += "agents:\n";
    for (int k = 0; k < 4; ++k)
        yaml += "  - {id: " + std::to_string(11 + k) + ", type: " + kRiders[k].type + ", position: [0, 0, " +
                std::to_string(-12 + 8 * k) + "], heading: 0, goal: far_" + std::to_string(k) + "}\n";
    return yaml;
}

std::vector<std::string> hoofChain(const std::string& leg)
{
    const std::string part = leg.substr(0, leg.find('_')), end = leg.substr(leg.find('_') + 1);
    return {"body", part + "_upper_" + end, part + "_lower_" + end, part + "_hoof_" + end};
}

constexpr float kFps = 24.0f;
constexpr std::size_t kFrames = 9 * 24;

const std::vector<std::string> kHead{"hips", "spine", "chest", "neck", "head"};
const std::vector<std::string> kRightHand{"hips", "spine", "chest", "upper_arm_r", "lower_arm_r", "hand_r"};
constexpr int kHeadJoint = 4, kRightHandJoint = 10;  // the humanoid skeleton's order (BuiltinCharacters.h)

}  // namespace

class TestViewportMatchesExport : public QObject {
    Q_OBJECT

    sim::Scene m_scene;
    sim::FrameCache m_cache;
    QTemporaryDir m_dir;
    tinygltf::Model m_model;

    sim::Scene m_ridersScene;
    sim::FrameCache m_ridersCache;
    tinygltf::Model m_ridersModel;

    sim::Scene m_wavingScene;
    sim::FrameCache m_wavingCache;
    tinygltf::Model m_wavingModel;

    // Where the viewport's pose for agent i at frame f puts joint j, in the world: as
    // Viewport::setAgents poses it, from the recording.
    static glm::vec3 viewportJoint(AgentCharacters& characters, const sim::FrameCache& cache, std::size_t f,
                                   std::size_t i, int joint)
    {
        std::vector<float> since;
        clipSinceS(cache, f, since);
        std::vector<exporting::GaitFrame> gait;
        characters.gaitAt(cache, f, gait);
        std::vector<AgentPose> poses;
        characters.posesFor(cache.frame(f), cache.agentsAt(f), double(f) / kFps, poses, since, gait);
        const AgentPose& pose = poses[i];
        const PoseTable& table = characters.poseTables()[std::size_t(pose.character) * AgentCharacters::kLevels];
        const glm::vec3 local(table.joints[std::size_t(pose.pose) * table.jointCount + std::size_t(joint)][3]);
        const sim::AgentFrame& a = cache.at(f, i);
        // Heading: the character's +X nose turns to (cos h, 0, -sin h), about +Y.
        const glm::quat yaw = glm::angleAxis(a.headingRad, glm::vec3(0.0f, 1.0f, 0.0f));
        return a.position + yaw * (pose.heightScale * local);
    }

private slots:
    void initTestCase()
    {
        const sim::LoadResult r = sim::parseScene(kScene, "viewport-export.yaml", "");
        QVERIFY2(r.ok(), r.ok() ? "" : r.diagnostics[0].format().c_str());
        m_scene = r.scene;
        sim::World world(m_scene, sim::WorldOptions{0, false, 1});
        QVERIFY(world.brainErrors().empty());
        test::recordRun(world, kFrames, m_cache);
        exporting::GltfOptions options;
        options.path = m_dir.filePath("viewport-export.glb").toStdString();
        QVERIFY(exporting::exportGltf(m_scene, m_cache, options).ok());
        std::string error;
        QVERIFY2(test::loadGltf(options.path, m_model, error), error.c_str());

        const sim::LoadResult riders = sim::parseScene(ridersScene(), "riders.yaml", "");
        QVERIFY2(riders.ok(), riders.ok() ? "" : riders.diagnostics[0].format().c_str());
        m_ridersScene = riders.scene;
        sim::World ridersWorld(m_ridersScene, sim::WorldOptions{0, false, 1});
        test::recordRun(ridersWorld, 8 * 24, m_ridersCache);
        options.path = m_dir.filePath("riders.glb").toStdString();
        QVERIFY(exporting::exportGltf(m_ridersScene, m_ridersCache, options).ok());
        QVERIFY2(test::loadGltf(options.path, m_ridersModel, error), error.c_str());

        const sim::LoadResult waving = sim::parseScene(ridersScene(true), "waving-riders.yaml", "");
        QVERIFY2(waving.ok(), waving.ok() ? "" : waving.diagnostics[0].format().c_str());
        m_wavingScene = waving.scene;
        sim::World wavingWorld(m_wavingScene, sim::WorldOptions{0, false, 1});
        QVERIFY(wavingWorld.brainErrors().empty());
        test::recordRun(wavingWorld, 8 * 24, m_wavingCache);
        options.path = m_dir.filePath("waving-riders.glb").toStdString();
        QVERIFY(exporting::exportGltf(m_wavingScene, m_wavingCache, options).ok());
        QVERIFY2(test::loadGltf(options.path, m_wavingModel, error), error.c_str());
    }

    void jointsAgree_data()
    {
        QTest::addColumn<int>("agent");
        QTest::addColumn<float>("timeS");
        QTest::addColumn<float>("poseStepS");  // time between two of the viewport's poses; 0: held
        QTest::newRow("standing, before the fall") << 1 << 0.5f << 0.0f;
        QTest::newRow("lying, held") << 1 << 3.5f << 0.0f;
        QTest::newRow("falling, half-way") << 1 << 1.6f << 1.2f / 7.0f;
        QTest::newRow("getting up, half-way") << 1 << 5.0f << 2.0f / 7.0f;
        QTest::newRow("up again") << 1 << 8.0f << 0.0f;
        QTest::newRow("waving") << 2 << 2.0f << 1.0f / 8.0f;
        QTest::newRow("walking") << 3 << 3.0f << 1.0f / 8.0f;  // 1.3 m/s over the walk's 1.29 m stride
    }

    // The head and the right hand, viewport against file, at the frame.
    void jointsAgree()
    {
        QFETCH(int, agent);
        QFETCH(float, timeS);
        QFETCH(float, poseStepS);
        AgentCharacters characters;
        QVERIFY(characters.setScene(m_scene, ""));
        QVERIFY2(characters.problems().empty(), characters.problems().c_str());
        const auto f = std::size_t(std::lround(timeS * kFps));
        std::size_t i = 0;
        while (m_cache.agents()[i].id != sim::AgentId(agent))
            ++i;
        const std::string root =
            "agent_" + std::to_string(agent) + "_" + m_scene.agentTypes[m_cache.agents()[i].typeIndex].name;
        for (const auto& [joint, chain] : {std::pair{kHeadJoint, kHead}, std::pair{kRightHandJoint, kRightHand}}) {
            const glm::vec3 shown = viewportJoint(characters, m_cache, f, i, joint);
            const float t = float(f) / kFps;
            const glm::vec3 written = test::jointWorldAt(m_model, root, chain, t);
            float toleranceM = 0.01f;
            for (const float side : {-0.5f, 0.5f}) {
                const glm::vec3 near = test::jointWorldAt(m_model, root, chain, t + side * poseStepS);
                toleranceM = std::max(toleranceM, 0.01f + glm::distance(written, near));
            }
            const QString what = QString("joint %1: viewport (%2, %3, %4), file (%5, %6, %7), within %8 m")
                                     .arg(joint).arg(shown.x).arg(shown.y).arg(shown.z)
                                     .arg(written.x).arg(written.y).arg(written.z).arg(toleranceM);
            QVERIFY2(glm::distance(shown, written) < toleranceM, qPrintable(what));
        }
    }

    // Each hoof of a rider at each of the horse's gaits, viewport against file, on every
    // frame of two seconds at its speed where the file has it down: the viewport's rung is
    // the file's and its legs are at the file's phase (within how far the file's hoof moves
    // against the body in half of an eighth of the gait's cycle, the most the nearest of the
    // viewport's 8 poses can miss, and 1 cm).
    void hoovesAgree_data()
    {
        QTest::addColumn<int>("rider");
        for (int k = 0; k < 4; ++k)
            QTest::newRow(kRiders[k].type) << k;
    }

    void hoovesAgree()
    {
        QFETCH(int, rider);
        AgentCharacters characters;
        QVERIFY(characters.setScene(m_ridersScene, ""));
        QVERIFY2(characters.problems().empty(), characters.problems().c_str());
        const std::size_t i = std::size_t(rider);
        QCOMPARE(m_ridersCache.agents()[i].id, sim::AgentId(11 + rider));
        const std::string root = std::string("agent_") + std::to_string(11 + rider) + "_" + kRiders[rider].type;
        const float poseStepS = kRiders[rider].strideM / kRiders[rider].speed / 8.0f;
        const int hooves[4] = {exporting::kHorseForeHoofL, exporting::kHorseForeHoofR, exporting::kHorseHindHoofL,
                               exporting::kHorseHindHoofR};
        const char* legs[4] = {"fore_l", "fore_r", "hind_l", "hind_r"};
        float worst = 0.0f;
        int compared = 0;
        for (std::size_t f = 5 * 24; f < 7 * 24; ++f) {
            const float t = float(f) / kFps;
            QVERIFY2(std::abs(m_ridersCache.at(f, i).speed - kRiders[rider].speed) < 0.05f * kRiders[rider].speed,
                     qPrintable(QString("not at its speed: %1 m/s").arg(m_ridersCache.at(f, i).speed)));
            for (int leg = 0; leg < 4; ++leg) {
                const glm::vec3 written = test::jointWorldAt(m_ridersModel, root, hoofChain(legs[leg]), t);
                // Where the file's hoof is down: there the export's foot planter holds it where
                // the clip put it, while in the air it eases the hoof from where it stood back to
                // the clip's path, which the viewport (no planter) shows at once.
                if (written.y > 0.085f)
                    continue;
                ++compared;
                const glm::vec3 shown = viewportJoint(characters, m_ridersCache, f, i, hooves[leg]);
                // The viewport's pose is the nearest of 8 while the body moves on: the miss is
                // how far the hoof moves against the body (a planted hoof stands still in the
                // world while the body passes over it).
                const auto againstBody = [&](float at) {
                    return test::jointWorldAt(m_ridersModel, root, hoofChain(legs[leg]), at) -
                           test::jointWorldAt(m_ridersModel, root, {"body"}, at);
                };
                float toleranceM = 0.01f;
                for (const float side : {-0.5f, 0.5f})
                    toleranceM =
                        std::max(toleranceM, 0.01f + glm::distance(againstBody(t), againstBody(t + side * poseStepS)));
                worst = std::max(worst, glm::distance(shown, written) / toleranceM);
                QVERIFY2(glm::distance(shown, written) < toleranceM,
                         qPrintable(QString("%1 at %2 s: viewport (%3, %4, %5), file (%6, %7, %8), within %9 m")
                                        .arg(legs[leg]).arg(t).arg(shown.x).arg(shown.y).arg(shown.z)
                                        .arg(written.x).arg(written.y).arg(written.z).arg(toleranceM)));
            }
        }
        QVERIFY2(compared > 30, qPrintable(QString("%1 hooves down").arg(compared)));
        qInfo("%s: %d hooves down, the worst %.0f %% of its tolerance from the file's", kRiders[rider].type, compared,
              100.0 * worst);
    }

    // A rider waving at each of the horse's gaits, viewport against file, on every frame of
    // two seconds at its speed: the right hand is over the rider's head in both, and the
    // viewport's is where the file's is, within the wave's swing about its mid-cycle (the
    // viewport's pose; worked out from the horse's clip), plus what the hoof test allows.
    void waveAtEveryGait_data() { hoovesAgree_data(); }

    void waveAtEveryGait()
    {
        QFETCH(int, rider);
        AgentCharacters characters;
        QVERIFY(characters.setScene(m_wavingScene, ""));
        QVERIFY2(characters.problems().empty(), characters.problems().c_str());
        const std::size_t i = std::size_t(rider);
        QCOMPARE(m_wavingCache.agents()[i].id, sim::AgentId(11 + rider));
        const std::string root = std::string("agent_") + std::to_string(11 + rider) + "_" + kRiders[rider].type;
        const std::vector<std::string> hand{"body", "rider_hips", "rider_chest", "rider_upper_arm_r",
                                            "rider_lower_arm_r", "rider_hand_r"};
        const std::vector<std::string> head{"body", "rider_hips", "rider_chest", "rider_head"};
        // How far the hand swings from its mid-cycle place over the wave, in the rider's frame.
        const exporting::Character horse = exporting::makeHorse(exporting::Lod::Near);
        const int wave = horse.actionIndex("wave");
        QVERIFY(wave >= 0);
        const auto handAt = [&](double phase) {
            exporting::GaitFrame g;
            g.moveWeight = 0.0f;
            g.action = {wave, phase, 1.0f};
            const auto globals = exporting::jointGlobalTransforms(horse, exporting::gaitPose(horse, g));
            return glm::vec3(globals[std::size_t(exporting::kHorseRiderHandR)][3]);
        };
        float swingM = 0.0f;
        for (int k = 0; k < 32; ++k)
            swingM = std::max(swingM, glm::distance(handAt(k / 32.0), handAt(0.5)));
        QVERIFY2(swingM > 0.05f && swingM < 0.5f, qPrintable(QString("the wave swings %1 m").arg(swingM)));
        const float poseStepS = kRiders[rider].strideM / kRiders[rider].speed / 8.0f;
        float worst = 0.0f;
        for (std::size_t f = 5 * 24; f < 7 * 24; ++f) {
            const float t = float(f) / kFps;
            QVERIFY2(std::abs(m_wavingCache.at(f, i).speed - kRiders[rider].speed) < 0.05f * kRiders[rider].speed,
                     qPrintable(QString("not at its speed: %1 m/s").arg(m_wavingCache.at(f, i).speed)));
            QCOMPARE(m_wavingCache.at(f, i).clip, sim::Clip::Wave);
            const glm::vec3 written = test::jointWorldAt(m_wavingModel, root, hand, t);
            const glm::vec3 shown = viewportJoint(characters, m_wavingCache, f, i, exporting::kHorseRiderHandR);
            const float writtenHead = test::jointWorldAt(m_wavingModel, root, head, t).y;
            const float shownHead = viewportJoint(characters, m_wavingCache, f, i, exporting::kHorseRiderHead).y;
            QVERIFY2(written.y > writtenHead && shown.y > shownHead,
                     qPrintable(QString("at %1 s the hand is at %2 m (file) and %3 m (viewport), the head at %4 and %5")
                                    .arg(t).arg(written.y).arg(shown.y).arg(writtenHead).arg(shownHead)));
            const auto againstBody = [&](float at) {
                return test::jointWorldAt(m_wavingModel, root, hand, at) -
                       test::jointWorldAt(m_wavingModel, root, {"body"}, at);
            };
            float toleranceM = 0.01f + swingM;
            for (const float side : {-0.5f, 0.5f})
                toleranceM = std::max(toleranceM,
                                      0.01f + swingM + glm::distance(againstBody(t), againstBody(t + side * poseStepS)));
            worst = std::max(worst, glm::distance(shown, written) / toleranceM);
            QVERIFY2(glm::distance(shown, written) < toleranceM,
                     qPrintable(QString("at %1 s: viewport (%2, %3, %4), file (%5, %6, %7), within %8 m")
                                    .arg(t).arg(shown.x).arg(shown.y).arg(shown.z)
                                    .arg(written.x).arg(written.y).arg(written.z).arg(toleranceM)));
        }
        qInfo("%s: the wave swings %.2f m; the worst hand %.0f %% of its tolerance from the file's",
              kRiders[rider].type, double(swingM), 100.0 * worst);
    }

    // The comparison can fail: the lying pose is far from the standing one, so a viewport
    // that ignored the fall (or a file that did) would be a metre off.
    void lyingIsFarFromStanding()
    {
        AgentCharacters characters;
        QVERIFY(characters.setScene(m_scene, ""));
        const float standing = viewportJoint(characters, m_cache, std::size_t(0.5f * kFps), 0, kHeadJoint).y;
        const float lying = viewportJoint(characters, m_cache, std::size_t(3.5f * kFps), 0, kHeadJoint).y;
        QVERIFY2(standing - lying > 1.0f, qPrintable(QString("%1 %2").arg(standing).arg(lying)));
    }
};

THRONG_REGISTER_TEST(TestViewportMatchesExport)
#include "TestViewportMatchesExport.moc"
