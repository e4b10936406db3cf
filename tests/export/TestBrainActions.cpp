// Brains drive clips: a walker whose brain waves while a hero is within 5 m, and a
// bystander who does the same standing still. The wave is the recorded clip on exactly
// the frames the brain chose it, the CSV's clip column says "wave" there, and in the
// exported glTF, as a reader evaluates it, the right hand rises above the head while the
// agent waves (blended in over the action's 0.3 s, not in one frame), the walker's legs
// keep walking under the wave, and the hand is back down once the hero has passed.
#include "GltfReadBack.h"
#include "TestRegistry.h"

#include "export/AgentTextCache.h"
#include "export/GltfExporter.h"
#include "export/TrajectoryCsv.h"
#include "simcore/io/SceneIO.h"
#include "simcore/world/World.h"

#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include <map>

using namespace throng;

namespace {

// Agent 1 walks east along z = 0 at 1.2 m/s; agent 2 stands at (10, 0, 6). The hero walks
// west along z = 3 from x = 30 (t = 0) to x = -10 (t = 20 s), at 2 m/s: within 5 m of
// agent 1 for t in about [8.1, 10.6] s (the gap 30 - 3.2 t within 4 m) and of agent 2 for
// t in [8, 12] s (20 - 2 t within 4 m). "stroll" is no clip: the speed's clip stands.
const char* kGreeters = R"(throng: 1
settings: {fps: 24, seed: 3, duration: 16, bounds: {min: [-40, -40], max: [40, 40]}}
agent_types:
  - {name: walker, max_speed: 1.2, variation: {speed: [1, 1]}, brain: greeter}
  - {name: hero, max_speed: 3}
goals: [{name: east, position: [30, 0], radius: 0.5}]
agents:
  - {id: 1, type: walker, position: [0, 0, 0], heading: 0, goal: east}
  - {id: 2, type: walker, position: [10, 0, 6], heading: 0}
heroes:
  - name: star
    id: 50
    type: hero
    clearance: 1
    keyframes:
      - {time: 0, position: [30, 0, 3]}
      - {time: 20, position: [-10, 0, 3]}
brains:
  - name: greeter
    nodes:
      - {id: 1, type: input, params: {sensor: hero_distance}}
      - {id: 2, type: math.compare, params: {mode: lt, value: 5}}
      - {id: 3, type: rule.not}
      - {id: 4, type: output.action, params: {actions: "stroll wave"}}
    links:
      - {from: [1, 0], to: [2, 0]}
      - {from: [2, 0], to: [3, 0]}
      - {from: [3, 0], to: [4, 0]}
      - {from: [2, 0], to: [4, 1]}
)";

constexpr std::size_t kFrames = 16 * 24;

// World position of the last joint of `joints` (names under agent_<id>_<type>), at time t.
glm::vec3 jointAt(const tinygltf::Model& model, int agent, const std::vector<std::string>& joints, float t,
                  const std::string& type = "walker")
{
    return test::jointWorldAt(model, "agent_" + std::to_string(agent) + "_" + type, joints, t);
}

const std::vector<std::string> kRightHand{"hips", "spine", "chest", "upper_arm_r", "lower_arm_r", "hand_r"};
const std::vector<std::string> kHead{"hips", "spine", "chest", "neck", "head"};
const std::vector<std::string> kLeftFoot{"hips", "upper_leg_l", "lower_leg_l", "foot_l"};

}  // namespace

class TestBrainActions : public QObject {
    Q_OBJECT

    sim::Scene m_scene;
    sim::FrameCache m_cache;
    std::map<int, std::vector<bool>> m_heroNear;  // agent id -> per frame: the hero within 5 m at the step's start

private slots:
    void initTestCase()
    {
        const sim::LoadResult r = sim::parseScene(kGreeters, "greeters.yaml", "");
        QVERIFY2(r.ok(), r.ok() ? "" : r.diagnostics[0].format().c_str());
        m_scene = r.scene;
        sim::World world(m_scene, sim::WorldOptions{0, false, 1});
        QVERIFY(world.brainErrors().empty());
        world.startRecording(m_cache);
        std::vector<sim::AgentFrame> frame;
        m_heroNear[1].push_back(false);
        m_heroNear[2].push_back(false);
        for (std::size_t f = 1; f < kFrames; ++f) {
            // The brain senses the state at the step's start.
            const glm::vec3 hero = world.positions()[2];
            for (const int id : {1, 2}) {
                const glm::vec3 p = world.positions()[std::size_t(id - 1)];
                m_heroNear[id].push_back(glm::distance(glm::vec2(p.x, p.z), glm::vec2(hero.x, hero.z)) < 5.0f);
            }
            world.step();
            world.snapshot(frame);
            m_cache.append(frame);
        }
    }

    // The clip is "wave" on exactly the frames whose step began with the hero near.
    void theChosenActionIsTheRecordedClip()
    {
        for (const int id : {1, 2}) {
            std::size_t waving = 0;
            for (std::size_t f = 1; f < kFrames; ++f) {
                const sim::AgentFrame& a = m_cache.at(f, std::size_t(id - 1));
                const bool near = m_heroNear[id][f];
                QVERIFY2((a.clip == sim::Clip::Wave) == near,
                         qPrintable(QString("agent %1 frame %2: clip %3, hero near %4")
                                        .arg(id)
                                        .arg(f)
                                        .arg(sim::toString(a.clip))
                                        .arg(near)));
                waving += near;
            }
            // About 2.5 s of waving for the walker, 4 s for the bystander.
            const std::size_t lo = id == 1 ? 50 : 86, hi = id == 1 ? 70 : 106;
            QVERIFY2(waving > lo && waving < hi, qPrintable(QString::number(waving)));
        }
        // The walker walks on while it waves.
        float slowest = 1e9f;
        for (std::size_t f = 1; f < kFrames; ++f)
            if (m_heroNear[1][f])
                slowest = std::min(slowest, m_cache.at(f, 0).speed);
        QVERIFY2(slowest > 1.0f, qPrintable(QString::number(slowest)));
    }

    // The text cache's clip column says what the CSV's does, line by line.
    void theTextCacheSaysWhatTheCsvSays()
    {
        QTemporaryDir dir;
        QVERIFY(exporting::writeTrajectoryCsv(m_cache, dir.filePath("shot.csv").toStdString()).ok());
        QVERIFY(exporting::writeAgentTextCache(m_cache, dir.filePath("cache").toStdString()).ok());
        auto lines = [](const QString& path) {
            QFile file(path);
            return file.open(QIODevice::ReadOnly) ? QString::fromUtf8(file.readAll()).split('\n', Qt::SkipEmptyParts)
                                                  : QStringList();
        };
        const QStringList csv = lines(dir.filePath("shot.csv"));
        std::map<int, QStringList> clips;  // by agent, in frame order
        for (qsizetype l = 1; l < csv.size(); ++l)
            clips[csv[l].split(',')[1].toInt()].push_back(csv[l].split(',')[7]);
        int waves = 0;
        for (const auto& [agent, expected] : clips) {
            const QStringList text = lines(dir.filePath(QString("cache/agent_%1.txt").arg(agent)));
            QCOMPARE(text.size(), expected.size());
            for (qsizetype f = 0; f < text.size(); ++f) {
                QCOMPARE(text[f].split(' ').value(5), expected[f]);
                waves += expected[f] == "wave" ? 1 : 0;
            }
        }
        QVERIFY(waves > 10);
    }

    void theCsvSaysWave()
    {
        QTemporaryDir dir;
        const std::string path = dir.filePath("greeters.csv").toStdString();
        QVERIFY(exporting::writeTrajectoryCsv(m_cache, path).ok());
        QFile file(QString::fromStdString(path));
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QStringList lines = QString::fromUtf8(file.readAll()).split('\n', Qt::SkipEmptyParts);
        QCOMPARE(lines.front(), QString("frame,agent,x,y,z,heading,speed,clip,phase"));
        std::size_t rows = 0;
        for (qsizetype l = 1; l < lines.size(); ++l) {
            const QStringList cells = lines[l].split(',');
            const int agent = cells[1].toInt();
            if (agent != 1 && agent != 2)
                continue;
            const auto f = std::size_t(cells[0].toInt());
            const QString expected = m_heroNear[agent][f] ? "wave" : (agent == 1 ? "walk" : "idle");
            if (agent == 1 && f == 0)
                continue;  // frame 0 records the start, before any step: walk or idle by speed
            QVERIFY2(cells[7] == expected || (agent == 1 && m_cache.at(f, 0).speed < 0.1f && cells[7] == "idle"),
                     qPrintable(lines[l]));
            ++rows;
        }
        QVERIFY(rows > 2 * (kFrames - 2));
    }

    // In the exported file: the hand above the head while waving, blended in over the
    // action's blend time, and down again after; the walker's feet still walk.
    void theExportedCharacterWaves()
    {
        QTemporaryDir dir;
        exporting::GltfOptions options;
        options.path = dir.filePath("greeters.glb").toStdString();
        options.mode = exporting::GltfMode::Exact;
        QVERIFY(exporting::exportGltf(m_scene, m_cache, options).ok());
        tinygltf::Model model;
        std::string error;
        QVERIFY2(test::loadGltf(options.path, model, error), error.c_str());
        const float fps = 24.0f;
        for (const int id : {1, 2}) {
            const std::vector<bool>& near = m_heroNear[id];
            const auto first = std::size_t(std::find(near.begin(), near.end(), true) - near.begin());
            const auto last = std::size_t(near.rend() - std::find(near.rbegin(), near.rend(), true)) - 1;
            QVERIFY(first > 24 && last > first + 48 && last + 48 < kFrames);
            auto handOverHead = [&](std::size_t f) {
                const float t = float(f) / fps;
                return jointAt(model, id, kRightHand, t).y - jointAt(model, id, kHead, t).y;
            };
            // Before: the hand hangs well below the head.
            QVERIFY2(handOverHead(first - 12) < -0.6f, qPrintable(QString::number(handOverHead(first - 12))));
            // On the first waving frame it has barely begun to rise (a blend, not a cut)...
            QVERIFY2(handOverHead(first) < -0.4f, qPrintable(QString::number(handOverHead(first))));
            // ...and from 0.3 s on, all the wave long, the hand is above the head.
            for (std::size_t f = first + 8; f <= last; ++f)
                QVERIFY2(handOverHead(f) > 0.05f, qPrintable(QString("agent %1 frame %2: %3 m")
                                                                 .arg(id)
                                                                 .arg(f)
                                                                 .arg(handOverHead(f))));
            // The hand swings side to side while it is up (the forearm's wave).
            float lo = 1e9f, hi = -1e9f;
            for (std::size_t f = first + 8; f <= last; ++f) {
                const float t = float(f) / fps;
                const glm::vec3 hand = jointAt(model, id, kRightHand, t), head = jointAt(model, id, kHead, t);
                const float side = glm::length(glm::vec2(hand.x - head.x, hand.z - head.z));
                lo = std::min(lo, side);
                hi = std::max(hi, side);
            }
            QVERIFY2(hi - lo > 0.08f, qPrintable(QString("%1 %2").arg(lo).arg(hi)));
            // Half a second after, it hangs again.
            QVERIFY2(handOverHead(last + 12) < -0.6f, qPrintable(QString::number(handOverHead(last + 12))));
        }
        // The walker's left foot keeps stepping under the wave: its height above the
        // ground swings by several centimetres over the waving frames.
        const std::vector<bool>& near = m_heroNear[1];
        float footLo = 1e9f, footHi = -1e9f;
        for (std::size_t f = 0; f < kFrames; ++f)
            if (near[f]) {
                const float y = jointAt(model, 1, kLeftFoot, float(f) / fps).y;
                footLo = std::min(footLo, y);
                footHi = std::max(footHi, y);
            }
        QVERIFY2(footHi - footLo > 0.05f, qPrintable(QString("%1 %2").arg(footLo).arg(footHi)));
    }

    // The scene docs/images/export-actions.jpg is rendered from: each bystander plays its
    // type's action on every frame, and in the file no foot leaves its place (wait's sway
    // included) while every pose differs from the plain idle's somewhere above the hips.
    void everyActionPlaysInTheDocumentedScene()
    {
        const sim::LoadResult r = sim::loadScene(std::string(THRONG_TEST_DATA_DIR) + "/scenes/actions.yaml");
        QVERIFY2(r.ok(), r.ok() ? "" : r.diagnostics[0].format().c_str());
        sim::World world(r.scene, sim::WorldOptions{0, false, 1});
        QVERIFY(world.brainErrors().empty());
        sim::FrameCache cache;
        world.startRecording(cache);
        std::vector<sim::AgentFrame> frame;
        for (int f = 1; f < 48; ++f) {
            world.step();
            world.snapshot(frame);
            cache.append(frame);
        }
        for (std::size_t i = 0; i < cache.agentCount(); ++i) {
            const std::string& type = r.scene.agentTypes[cache.agents()[i].typeIndex].name;
            for (std::size_t f = 1; f < cache.frameCount(); ++f)
                QCOMPARE(QString(sim::toString(cache.at(f, i).clip)), QString::fromStdString(type));
        }
        QTemporaryDir dir;
        exporting::GltfOptions options;
        options.path = dir.filePath("actions.glb").toStdString();
        QVERIFY(exporting::exportGltf(r.scene, cache, options).ok());
        tinygltf::Model model;
        std::string error;
        QVERIFY2(test::loadGltf(options.path, model, error), error.c_str());
        for (std::size_t i = 0; i < cache.agentCount(); ++i) {
            const int id = int(cache.agents()[i].id);
            const std::string type = r.scene.agentTypes[cache.agents()[i].typeIndex].name;
            auto joint = [&](const std::vector<std::string>& chain, float t) {
                return jointAt(model, id, chain, t, type);
            };
            const glm::vec3 foot0 = joint(kLeftFoot, 0.0f);
            float moved = 0.0f;
            for (int f = 0; f < 48; f += 2) {
                const float t = float(f) / 24.0f;
                QVERIFY2(glm::distance(joint(kLeftFoot, t), foot0) < 0.01f, qPrintable(QString::fromStdString(type)));
                moved = std::max(moved, glm::distance(joint(kRightHand, t), joint(kRightHand, 0.0f)) +
                                            glm::distance(joint(kHead, t), joint(kHead, 0.0f)));
            }
            // Every action moves the hand or the head by a few centimetres over 2 s.
            QVERIFY2(moved > 0.02f, qPrintable(QString::fromStdString(type) + QString(": %1 m").arg(moved)));
        }
    }

    // The bystander's feet stay put through the wave (the action plays over its standing legs).
    void theStandingWaverKeepsItsFeet()
    {
        QTemporaryDir dir;
        exporting::GltfOptions options;
        options.path = dir.filePath("greeters.glb").toStdString();
        QVERIFY(exporting::exportGltf(m_scene, m_cache, options).ok());
        tinygltf::Model model;
        std::string error;
        QVERIFY2(test::loadGltf(options.path, model, error), error.c_str());
        const glm::vec3 start = jointAt(model, 2, kLeftFoot, 0.0f);
        for (std::size_t f = 0; f < kFrames; f += 3) {
            const glm::vec3 foot = jointAt(model, 2, kLeftFoot, float(f) / 24.0f);
            QVERIFY2(glm::distance(foot, start) < 0.01f, qPrintable(QString("frame %1: %2 m")
                                                                      .arg(f)
                                                                      .arg(glm::distance(foot, start))));
        }
    }
};

THRONG_REGISTER_TEST(TestBrainActions)
#include "TestBrainActions.moc"
