// A brain that makes an agent fall and get up again, as a user would check it in the
// exported file: the agent's brain picks `fall` from 1 s to 4 s and `get_up` from 4 s to
// 7 s. In the glTF, as a reader evaluates it, the head is at standing height before 1 s,
// sinks to the ground over the fall's 1.2 s and stays there (lying, held) until 4 s, is up
// again once get_up's 2 s are over, and stays up. The feet do not slide while the knees
// give; the CSV says `fall` and `get_up` on those frames. A second type with
// `action_blend: 1` blends the same fall in over a whole second: half-way into it at 0.5 s.
#include "GltfReadBack.h"
#include "RecordRun.h"
#include "TestRegistry.h"

#include "export/GltfExporter.h"
#include "export/TrajectoryCsv.h"
#include "simcore/io/SceneIO.h"
#include "simcore/world/World.h"

#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

using namespace throng;

namespace {

constexpr const char* kFallers = R"(throng: 1
settings: {fps: 24, seed: 3, duration: 9, bounds: {min: [-10, -10], max: [10, 10]}}
agent_types:
  - {name: faller, character: man, variation: {height: [1, 1]}, brain: faller}
  - {name: slow_faller, character: man, variation: {height: [1, 1]}, brain: faller, action_blend: 1}
agents:
  - {id: 1, type: faller, position: [0, 0], heading: 0}
  - {id: 2, type: slow_faller, position: [0, 4], heading: 0}
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
)";

constexpr float kFps = 24.0f;
constexpr std::size_t kFrames = 9 * 24;

using test::jointWorldAt;

const std::vector<std::string> kHead{"hips", "spine", "chest", "neck", "head"};
const std::vector<std::string> kLeftFoot{"hips", "upper_leg_l", "lower_leg_l", "foot_l"};

}  // namespace

class TestFallAndGetUp : public QObject {
    Q_OBJECT

    sim::Scene m_scene;
    sim::FrameCache m_cache;
    QTemporaryDir m_dir;
    tinygltf::Model m_model;

private slots:
    void initTestCase()
    {
        const sim::LoadResult r = sim::parseScene(kFallers, "fallers.yaml", "");
        QVERIFY2(r.ok(), r.ok() ? "" : r.diagnostics[0].format().c_str());
        m_scene = r.scene;
        QCOMPARE(m_scene.agentTypes[1].actionBlendS, 1.0f);
        QVERIFY(m_scene.agentTypes[0].actionBlendS < 0.0f);
        sim::World world(m_scene, sim::WorldOptions{0, false, 1});
        QVERIFY(world.brainErrors().empty());
        test::recordRun(world, kFrames, m_cache);
        exporting::GltfOptions options;
        options.path = m_dir.filePath("fallers.glb").toStdString();
        QVERIFY(exporting::exportGltf(m_scene, m_cache, options).ok());
        std::string error;
        QVERIFY2(test::loadGltf(options.path, m_model, error), error.c_str());
    }

    // The recorded clip is the brain's: fall from 1 s to 4 s, get_up to 7 s, idle around.
    void theBrainsChoiceIsRecorded()
    {
        QDir().mkpath(m_dir.path());
        const std::string csv = m_dir.filePath("fallers.csv").toStdString();
        QVERIFY(exporting::writeTrajectoryCsv(m_cache, csv).ok());
        QFile file(QString::fromStdString(csv));
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QStringList lines = QString::fromUtf8(file.readAll()).split('\n', Qt::SkipEmptyParts);
        std::size_t falls = 0, getUps = 0;
        for (const QString& line : lines.mid(1)) {
            const QStringList cells = line.split(',');
            const float t = cells[0].toFloat() / kFps;
            const QString clip = cells[7];
            if (t > 1.1f && t < 3.9f)
                QCOMPARE(clip, QString("fall"));
            else if (t > 4.1f && t < 6.9f)
                QCOMPARE(clip, QString("get_up"));
            else if (t < 0.9f || t > 7.1f)
                QCOMPARE(clip, QString("idle"));
            falls += clip == "fall" ? 1 : 0;
            getUps += clip == "get_up" ? 1 : 0;
        }
        QVERIFY(falls > 2 * 60 && getUps > 2 * 60);  // two agents, about 3 s each
    }

    // Standing, down over 1.2 s, lying until the brain says get up, up again after 2 s.
    void theHeadGoesDownStaysDownAndComesBackUp()
    {
        const std::string root = "agent_1_faller";
        float standing = 0.0f, lowest = 1e9f, highestLying = 0.0f, lowestAfter = 1e9f;
        for (std::size_t f = 0; f < kFrames; ++f) {
            const float t = float(f) / kFps;
            const float head = jointWorldAt(m_model, root, kHead, t).y;
            if (t < 1.0f)
                standing = std::max(standing, head);
            if (t > 2.5f && t < 4.0f)  // the fall (1.2 s) and its blend (0.15 s) are over
                highestLying = std::max(highestLying, head);
            lowest = std::min(lowest, head);
            if (t > 6.3f)  // get_up (2 s) and its blend are over
                lowestAfter = std::min(lowestAfter, head);
        }
        const QString what = QString("head standing %1, lying up to %2, after getting up %3 m")
                                 .arg(standing).arg(highestLying).arg(lowestAfter);
        QVERIFY2(standing > 1.5f, qPrintable(what));
        QVERIFY2(highestLying < 0.45f, qPrintable(what));
        QVERIFY2(lowestAfter > 1.5f && std::abs(lowestAfter - standing) < 0.05f, qPrintable(what));
        // Not before the brain says so: still standing a frame after 1 s.
        QVERIFY(jointWorldAt(m_model, root, kHead, 1.0f + 1.0f / kFps).y > 1.45f);
        // Half-way through the fall it is on its way down, neither up nor down.
        const float halfWay = jointWorldAt(m_model, root, kHead, 1.6f).y;
        QVERIFY2(halfWay < standing - 0.2f && halfWay > highestLying + 0.2f, qPrintable(QString::number(halfWay)));
    }

    // While the knees give and the body sits down (the fall's first 60 %), the feet stay
    // where the agent stood.
    void theFeetStayPutWhileTheKneesGive()
    {
        const std::string root = "agent_1_faller";
        const glm::vec3 before = jointWorldAt(m_model, root, kLeftFoot, 0.9f);
        float worst = 0.0f;
        for (float t = 1.0f; t < 1.0f + 0.6f * 1.2f; t += 1.0f / kFps) {
            const glm::vec3 p = jointWorldAt(m_model, root, kLeftFoot, t);
            worst = std::max(worst, glm::length(glm::vec2(p.x - before.x, p.z - before.z)));
        }
        QVERIFY2(worst < 0.03f, qPrintable(QString("the foot moved %1 m").arg(worst)));
    }

    // action_blend: 1 blends the fall in over a second: at 0.5 s in, the slow faller is
    // half-way between standing and the fall's pose, clearly higher than the other.
    void theTypesBlendTimeIsUsed()
    {
        const float t = 1.0f + 0.5f;
        const float quick = jointWorldAt(m_model, "agent_1_faller", kHead, t).y;
        const float slow = jointWorldAt(m_model, "agent_2_slow_faller", kHead, t).y;
        QVERIFY2(slow > quick + 0.1f, qPrintable(QString("head %1 (blend 1 s) vs %2 m").arg(slow).arg(quick)));
        // Both lie in the end.
        QVERIFY(jointWorldAt(m_model, "agent_2_slow_faller", kHead, 3.8f).y < 0.45f);
    }
};

THRONG_REGISTER_TEST(TestFallAndGetUp)
#include "TestFallAndGetUp.moc"
