// The horse's and its rider's actions reach the exported file as a reader evaluates it.
// A galloping rider whose brain waves has the right hand above the helmet while the hooves
// keep galloping (the wave plays on the rider only); a cheering rider at a canter raises
// both hands; a standing horse that looks around turns its head a hand's breadth to each
// side; a horse whose brain picks an action the horse lacks (sit) shows its gait, as the
// same horse without a brain does, to the bit.
#include "GltfReadBack.h"
#include "RecordRun.h"
#include "TestRegistry.h"

#include "export/GltfExporter.h"
#include "export/character/BuiltinCharacters.h"
#include "simcore/io/SceneIO.h"
#include "simcore/world/World.h"

#include <QTemporaryDir>
#include <QTest>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

using namespace throng;

namespace {

constexpr float kActionFps = 30.0f;
constexpr std::size_t kActionFrames = 8 * 30;

// Riders 1 (waves at a gallop), 2 (cheers at a canter), 3 (stands and looks around),
// 4 (stands, its brain asks to sit), 5 (stands, no brain): 4 and 5 share a type and an id
// stream apart from the brain, so their gait is the same.
constexpr const char* kHorseActionsScene = R"(throng: 1
settings: {fps: 30, seed: 6, duration: 8, bounds: {min: [-10, -30], max: [120, 30]}}
agent_types:
  - {name: waver, character: horse, radius: 0.8, max_speed: 9.5, max_force: 30, brain: wave,
     variation: {speed: [1, 1], height: [1, 1]}, behaviours: {seek: 1}}
  - {name: cheerer, character: horse, radius: 0.8, max_speed: 5.5, max_force: 30, brain: cheer,
     variation: {speed: [1, 1], height: [1, 1]}, behaviours: {seek: 1}}
  - {name: looker, character: horse, radius: 0.8, brain: look, variation: {speed: [1, 1], height: [1, 1]}}
  - {name: sitter, character: horse, radius: 0.8, brain: sit, variation: {speed: [1, 1], height: [1, 1]}}
  - {name: stander, character: horse, radius: 0.8, variation: {speed: [1, 1], height: [1, 1]}}
goals:
  - {name: far_1, position: [115, -20], radius: 1}
  - {name: far_2, position: [115, -10], radius: 1}
agents:
  - {id: 1, type: waver, position: [0, 0, -20], heading: 0, goal: far_1}
  - {id: 2, type: cheerer, position: [0, 0, -10], heading: 0, goal: far_2}
  - {id: 3, type: looker, position: [0, 0, 5], heading: 0}
  - {id: 4, type: sitter, position: [0, 0, 15], heading: 0}
  - {id: 5, type: stander, position: [0, 0, 25], heading: 0}
brains:
  - name: wave
    nodes:
      - {id: 1, type: input.constant, params: {value: 1}}
      - {id: 2, type: output.action, params: {actions: "wave"}}
    links: [{from: [1, 0], to: [2, 0]}]
  - name: cheer
    nodes:
      - {id: 1, type: input.constant, params: {value: 1}}
      - {id: 2, type: output.action, params: {actions: "cheer"}}
    links: [{from: [1, 0], to: [2, 0]}]
  - name: look
    nodes:
      - {id: 1, type: input.constant, params: {value: 1}}
      - {id: 2, type: output.action, params: {actions: "look_around"}}
    links: [{from: [1, 0], to: [2, 0]}]
  - name: sit
    nodes:
      - {id: 1, type: input.constant, params: {value: 1}}
      - {id: 2, type: output.action, params: {actions: "sit"}}
    links: [{from: [1, 0], to: [2, 0]}]
)";

const std::vector<std::string> kRiderHead{"body", "rider_hips", "rider_chest", "rider_head"};
std::vector<std::string> handChain(const std::string& side)
{
    return {"body", "rider_hips", "rider_chest", "rider_upper_arm_" + side, "rider_lower_arm_" + side,
            "rider_hand_" + side};
}
const std::vector<std::string> kHorseHeadChain{"body", "neck", "head"};
const std::vector<std::string> kHindHoof{"body", "hind_upper_l", "hind_lower_l", "hind_hoof_l"};

}  // namespace

class TestHorseActions : public QObject {
    Q_OBJECT

    QTemporaryDir m_dir;
    tinygltf::Model m_model;
    sim::FrameCache m_cache;

    glm::vec3 joint(const std::string& root, const std::vector<std::string>& chain, std::size_t f) const
    {
        return test::jointWorldAt(m_model, root, chain, float(f) / kActionFps);
    }

private slots:
    void initTestCase()
    {
        const sim::LoadResult r = sim::parseScene(kHorseActionsScene, "horse-actions.yaml", "");
        QVERIFY2(r.ok(), r.ok() ? "" : r.diagnostics[0].format().c_str());
        sim::World world(r.scene, sim::WorldOptions{0, false, 1});
        QVERIFY(world.brainErrors().empty());
        test::recordRun(world, kActionFrames, m_cache);
        exporting::GltfOptions options;
        options.path = m_dir.filePath("horse-actions.glb").toStdString();
        QVERIFY(exporting::exportGltf(r.scene, m_cache, options).ok());
        std::string error;
        QVERIFY2(test::loadGltf(options.path, m_model, error), error.c_str());
    }

    // The horse carries these actions and no others.
    void theHorsePlaysItsActions()
    {
        const exporting::Character horse = exporting::makeHorse(exporting::Lod::Far);
        for (const char* name : {"wait", "look_around", "shift_weight", "wave", "point", "cheer", "talk"})
            QVERIFY2(horse.actionIndex(name) >= 0, name);
        for (const char* name : {"sit", "phone", "fall", "get_up"})
            QVERIFY2(horse.actionIndex(name) < 0, name);
    }

    void waveAtAGallop()
    {
        float lowestHoof = 1e9f, highestHoof = -1e9f;
        for (std::size_t f = 5 * 30; f < kActionFrames; f += 2) {
            QVERIFY2(m_cache.at(f, 0).speed > 9.0f, "at a gallop");
            QVERIFY2(m_cache.at(f, 0).clip == sim::Clip::Wave, "its brain picks wave");
            const glm::vec3 hand = joint("agent_1_waver", handChain("r"), f);
            const glm::vec3 head = joint("agent_1_waver", kRiderHead, f);
            QVERIFY2(hand.y > head.y + 0.2f,
                     qPrintable(QString("frame %1: hand at %2 m, head at %3 m").arg(f).arg(hand.y).arg(head.y)));
            const glm::vec3 resting = joint("agent_1_waver", handChain("l"), f);
            QVERIFY2(resting.y < head.y - 0.3f, "the left hand keeps the reins");
            const float hoof = joint("agent_1_waver", kHindHoof, f).y;
            lowestHoof = std::min(lowestHoof, hoof);
            highestHoof = std::max(highestHoof, hoof);
        }
        QVERIFY2(lowestHoof < 0.09f && highestHoof > 0.3f,
                 qPrintable(QString("the hind hoof goes from %1 to %2 m").arg(lowestHoof).arg(highestHoof)));
    }

    void cheerAtACanter()
    {
        for (std::size_t f = 5 * 30; f < kActionFrames; f += 5) {
            const glm::vec3 head = joint("agent_2_cheerer", kRiderHead, f);
            for (const char* side : {"l", "r"}) {
                const glm::vec3 hand = joint("agent_2_cheerer", handChain(side), f);
                QVERIFY2(hand.y > head.y + 0.2f, qPrintable(QString("frame %1: %2 hand at %3 m, head at %4 m")
                                                                .arg(f).arg(side).arg(hand.y).arg(head.y)));
            }
        }
    }

    void lookAroundStanding()
    {
        float left = 1e9f, right = -1e9f;
        for (std::size_t f = 30; f < kActionFrames; ++f) {
            const glm::vec3 head = joint("agent_3_looker", kHorseHeadChain, f);
            left = std::min(left, head.z);
            right = std::max(right, head.z);
        }
        QVERIFY2(right - left > 0.2f, qPrintable(QString("the head swings %1 m").arg(right - left)));
    }

    // sit is no horse's action: the horse stands as it does without a brain.
    void anActionTheHorseLacksShowsItsGait()
    {
        for (std::size_t f = 1; f < kActionFrames; f += 7) {
            QVERIFY2(m_cache.at(f, 3).clip == sim::Clip::Sit, "its brain picks sit");
            const glm::vec3 sitter = joint("agent_4_sitter", kRiderHead, f) - glm::vec3(0.0f, 0.0f, 15.0f);
            const glm::vec3 stander = joint("agent_5_stander", kRiderHead, f) - glm::vec3(0.0f, 0.0f, 25.0f);
            QVERIFY2(glm::distance(sitter, stander) < 1e-4f,
                     qPrintable(QString("frame %1: %2 m apart").arg(f).arg(glm::distance(sitter, stander))));
        }
    }
};

THRONG_REGISTER_TEST(TestHorseActions)
#include "TestHorseActions.moc"
