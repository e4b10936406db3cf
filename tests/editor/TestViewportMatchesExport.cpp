// The viewport's characters show the motion the export writes: for a recorded run whose
// brains wave, fall and get up, the pose the viewport picks for each agent at a frame
// (AgentCharacters, from the frame cache, as Viewport::setAgents does) puts the head and
// the right hand where the exported glTF, as a reader evaluates it, puts them. Held poses
// (standing, lying, getting up done) agree to a centimetre; moving ones within a centimetre
// of how far the file's joint moves in half the time between two of the viewport's poses
// (8 a cycle; a one-shot's 8 span it from start to end), the most the nearest pose can miss.
#include "GltfReadBack.h"
#include "RecordRun.h"
#include "TestRegistry.h"

#include "editor/viewport/AgentCharacters.h"
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

    // Where the viewport's pose for agent i at frame f puts joint j, in the world.
    glm::vec3 viewportJoint(AgentCharacters& characters, std::size_t f, std::size_t i, int joint)
    {
        std::vector<float> since;
        clipSinceS(m_cache, f, since);
        std::vector<AgentPose> poses;
        characters.posesFor(m_cache.frame(f), m_cache.agentsAt(f), double(f) / kFps, poses, since);
        const AgentPose& pose = poses[i];
        const PoseTable& table = characters.poseTables()[std::size_t(pose.character) * AgentCharacters::kLevels];
        const glm::vec3 local(table.joints[std::size_t(pose.pose) * table.jointCount + std::size_t(joint)][3]);
        const sim::AgentFrame& a = m_cache.at(f, i);
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
            const glm::vec3 shown = viewportJoint(characters, f, i, joint);
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

    // The comparison can fail: the lying pose is far from the standing one, so a viewport
    // that ignored the fall (or a file that did) would be a metre off.
    void lyingIsFarFromStanding()
    {
        AgentCharacters characters;
        QVERIFY(characters.setScene(m_scene, ""));
        const float standing = viewportJoint(characters, std::size_t(0.5f * kFps), 0, kHeadJoint).y;
        const float lying = viewportJoint(characters, std::size_t(3.5f * kFps), 0, kHeadJoint).y;
        QVERIFY2(standing - lying > 1.0f, qPrintable(QString("%1 %2").arg(standing).arg(lying)));
    }
};

THRONG_REGISTER_TEST(TestViewportMatchesExport)
#include "TestViewportMatchesExport.moc"
