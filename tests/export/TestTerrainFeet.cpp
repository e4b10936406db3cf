// Feet that stay planted on real ground, measured from the exported file as a reader
// evaluates it. Walkers on a sloped and on a bumpy terrain start from standing, turn two
// corners, turn round, blend walk into run and back and stop at their goals; one stands.
// From each ankle's world position in the file (node transforms and channels, reduced
// keys and 16-bit rotations included) and the scene's terrain:
// - a foot on the ground (its sole within 5 mm of the terrain under it) slides less than
//   1 cm until it lifts, lies on the slope (its up within 3 degrees of the terrain's
//   normal), and each foot is on the ground a fair share of the run;
// - no sole is ever more than 2 cm below the terrain, and while an agent walks or stands
//   (one foot always down in those gaits) its lower sole is within 2 cm of the terrain.
#include "GltfReadBack.h"
#include "TestRegistry.h"

#include "export/GltfExporter.h"
#include "export/character/BuiltinCharacters.h"
#include "simcore/io/SceneIO.h"
#include "simcore/scene/TerrainHeight.h"
#include "simcore/world/World.h"

#include <QTemporaryDir>
#include <QTest>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <sstream>

using namespace throng;

namespace {

constexpr float kFps = 30.0f;
constexpr float kSeconds = 20.0f;
constexpr float kTwoPi = 6.2831853f;
// How far a planted sole may lie off the terrain's slope, degrees (the sloped ground is
// 7.4 degrees steep: a level sole would fail).
constexpr float kTiltDeg = 3.0f;

// A 60 x 40 m terrain at 0.5 m samples, as scene YAML.
std::string terrainYaml(const std::function<float(float, float)>& height)
{
    constexpr int cols = 121, rows = 81;
    std::ostringstream out;
    out << "terrain:\n  origin: [-30, -20]\n  cell: 0.5\n  cols: " << cols << "\n  rows: " << rows << "\n  heights: [";
    for (int z = 0; z < rows; ++z)
        for (int x = 0; x < cols; ++x)
            out << (x + z > 0 ? ", " : "") << height(-30.0f + 0.5f * float(x), -20.0f + 0.5f * float(z));
    out << "]\n";
    return out.str();
}

std::string sceneYaml(const std::function<float(float, float)>& height)
{
    return R"(throng: 1
settings: {fps: 30, seed: 11, duration: 20, bounds: {min: [-30, -20], max: [30, 20]}}
agent_types:
  - name: walker
    character: man
    max_speed: 1.3
    variation: {height: [0.9, 1.1], speed: [1, 1]}
    behaviours: {path_following: 1, arrival: {weight: 1, slowing_distance: 2}, separation: 1}
  - name: strider
    character: woman
    max_speed: 2.6
    max_force: 4
    variation: {height: [0.9, 1.1], speed: [1, 1]}
    behaviours: {arrival: {weight: 1, slowing_distance: 3}, separation: 1}
  - name: runner
    character: man
    max_speed: 3.6
    max_force: 4
    variation: {height: [0.9, 1.1], speed: [1, 1]}
    behaviours: {arrival: {weight: 1, slowing_distance: 4}, separation: 1}
  - name: bystander
    character: woman
    variation: {height: [0.9, 1.1], speed: [1, 1]}
agents:
  - {id: 1, type: walker, position: [-20, -12], heading: 0, path: corners}
  - {id: 2, type: runner, position: [-24, 10], heading: 0, goal: far}
  - {id: 3, type: strider, position: [-24, 16], heading: 0, goal: mid}
  - {id: 4, type: bystander, position: [6, -4], heading: 30}
  - {id: 5, type: walker, position: [14, -10], heading: 0, goal: behind}
goals:
  - {name: far, position: [10, 10], radius: 0.5}
  - {name: mid, position: [4, 16], radius: 0.5}
  - {name: behind, position: [7, -10], radius: 0.5}
paths:
  - {name: corners, points: [[-20, -12], [-15, -12], [-15, -8], [-11, -8]], radius: 0.5}
)" + terrainYaml(height);
}

struct FootTrack {
    std::vector<glm::vec3> ankle;  // world, per frame
    std::vector<float> sole;       // sole height above the terrain under the ankle, m
    std::vector<glm::vec3> up;     // the foot's up (its joint's +Y), world, unit length
};

// The terrain's unit normal under (x, z), by central differences 10 cm apart.
glm::vec3 terrainNormal(const sim::Terrain& terrain, float x, float z)
{
    constexpr float h = 0.1f;
    const float dx = sim::terrainHeight(terrain, x + h, z) - sim::terrainHeight(terrain, x - h, z);
    const float dz = sim::terrainHeight(terrain, x, z + h) - sim::terrainHeight(terrain, x, z - h);
    return glm::normalize(glm::vec3(-dx / (2.0f * h), 1.0f, -dz / (2.0f * h)));
}

}  // namespace

class TestTerrainFeet : public QObject {
    Q_OBJECT

private slots:
    void feetStandOnTheTerrainAndDoNotSlide_data()
    {
        QTest::addColumn<int>("ground");
        QTest::newRow("sloped") << 0;
        QTest::newRow("bumpy") << 1;
        QTest::newRow("flat") << 2;
    }

    void feetStandOnTheTerrainAndDoNotSlide()
    {
        QFETCH(int, ground);
        std::function<float(float, float)> height = [](float, float) { return 0.0f; };
        if (ground == 0)
            height = [](float x, float z) { return 0.12f * x + 0.05f * z; };  // 12 % and 5 % grades
        else if (ground == 1)
            height = [](float x, float z) {
                return 0.1f * std::sin(kTwoPi * x / 4.0f) * std::cos(kTwoPi * z / 5.0f) +
                       0.05f * std::sin(kTwoPi * (x + z) / 3.0f);
            };
        const sim::LoadResult r = sim::parseScene(sceneYaml(height), "terrain-feet.yaml", "");
        QVERIFY2(r.ok(), r.ok() ? "" : r.diagnostics[0].format().c_str());
        const sim::Scene& scene = r.scene;
        QCOMPARE(scene.settings.fps, kFps);
        sim::World world(scene, sim::WorldOptions{0, false, 1});
        sim::FrameCache cache;
        world.startRecording(cache);
        std::vector<sim::AgentFrame> frame;
        const std::size_t frames = std::size_t(kSeconds * kFps);
        for (std::size_t f = 1; f < frames; ++f) {
            world.step();
            world.snapshot(frame);
            cache.append(frame);
        }
        QCOMPARE(cache.frameCount(), frames);

        // The run does what the test claims: start, run, stop, turn, stand, on real slopes.
        std::map<int, std::size_t> index;
        for (std::size_t i = 0; i < cache.agentCount(); ++i)
            index[int(cache.agents()[i].id)] = i;
        const auto maxSpeed = [&](int id) {
            float v = 0.0f;
            for (std::size_t f = 0; f < frames; ++f)
                v = std::max(v, cache.at(f, index.at(id)).speed);
            return v;
        };
        QVERIFY2(maxSpeed(2) > 3.2f, qPrintable(QString::number(maxSpeed(2))));  // the runner runs
        QVERIFY(maxSpeed(3) > 2.3f && maxSpeed(3) < 2.8f);                       // between walk and run
        QVERIFY(maxSpeed(4) < 0.01f);                                             // the bystander stands
        for (const int id : {1, 2, 3, 5})
            QVERIFY2(cache.at(frames - 1, index.at(id)).speed < 0.05f, qPrintable(QString("agent %1 stops").arg(id)));
        float turned = 0.0f, climbed = 0.0f;  // agent 1 and 5's turning, agent 2's climb
        for (std::size_t f = 1; f < frames; ++f) {
            for (const int id : {1, 5})
                turned += std::abs(std::remainder(cache.at(f, index.at(id)).headingRad -
                                                      cache.at(f - 1, index.at(id)).headingRad,
                                                  kTwoPi));
            const float rise = cache.at(f, index.at(2)).position.y - cache.at(0, index.at(2)).position.y;
            climbed = std::max(climbed, std::abs(rise));
        }
        QVERIFY2(turned > 1.5f * 3.14159f, qPrintable(QString::number(turned)));  // two corners and a turn round
        QVERIFY2(ground == 2 ? climbed == 0.0f : climbed > 0.1f, qPrintable(QString::number(climbed)));

        QTemporaryDir dir;
        exporting::GltfOptions options;
        options.path = dir.filePath("terrain.glb").toStdString();
        QVERIFY(exporting::exportGltf(scene, cache, options).ok());
        tinygltf::Model model;
        std::string error;
        QVERIFY2(test::loadGltf(options.path, model, error), error.c_str());

        for (std::size_t i = 0; i < cache.agentCount(); ++i) {
            const int id = int(cache.agents()[i].id);
            const sim::AgentType& type = scene.agentTypes[cache.agents()[i].typeIndex];
            const std::string root = "agent_" + std::to_string(id) + "_" + type.name;
            const auto character = exporting::makeBuiltinCharacter(type.character, exporting::Lod::Far);
            QVERIFY(character && character->legs.size() == 2);
            const int rootNode = test::nodeNamed(model, root);
            QVERIFY(rootNode >= 0);
            const float scale = glm::length(glm::vec3(test::nodeLocalAt(model, rootNode, 0.0f)[0]));
            QVERIFY(scale > 0.85f && scale < 1.15f);
            const float ankleHeight = character->legs[0].plantedAnkle.y * scale;
            std::vector<FootTrack> feet(2);
            for (int side = 0; side < 2; ++side) {
                const std::string s = side == 0 ? "l" : "r";
                std::vector<int> chain{rootNode};
                for (const std::string& j : {std::string("hips"), "upper_leg_" + s, "lower_leg_" + s, "foot_" + s})
                    chain.push_back(test::nodeNamed(model, root + "__" + j));
                QVERIFY(std::find(chain.begin(), chain.end(), -1) == chain.end());
                for (std::size_t f = 0; f < frames; ++f) {
                    glm::mat4 m(1.0f);
                    for (int node : chain)
                        m = m * test::nodeLocalAt(model, node, float(f) / kFps);
                    const glm::vec3 a(m[3]);
                    feet[side].ankle.push_back(a);
                    feet[side].sole.push_back(a.y - ankleHeight - sim::terrainHeight(scene.terrain, a.x, a.z));
                    feet[side].up.push_back(glm::normalize(glm::vec3(m[1])));
                }
            }
            const QString who = QString("agent %1 (%2)").arg(id).arg(QString::fromStdString(type.name));
            for (int side = 0; side < 2; ++side) {
                const FootTrack& foot = feet[side];
                std::size_t down = 0;
                float worstSlide = 0.0f, lowest = 1e9f, worstTiltDeg = 0.0f;
                glm::vec3 touchdown(0.0f);
                for (std::size_t f = 0; f < frames; ++f) {
                    lowest = std::min(lowest, foot.sole[f]);
                    const bool isDown = std::abs(foot.sole[f]) < 0.005f;
                    if (!isDown)
                        continue;
                    if (f == 0 || std::abs(foot.sole[f - 1]) >= 0.005f)
                        touchdown = foot.ankle[f];
                    ++down;
                    // A planted sole lies on the slope: its up is the terrain's normal.
                    const glm::vec3 normal = terrainNormal(scene.terrain, foot.ankle[f].x, foot.ankle[f].z);
                    const float cosine = std::clamp(glm::dot(foot.up[f], normal), -1.0f, 1.0f);
                    worstTiltDeg = std::max(worstTiltDeg, std::acos(cosine) * 180.0f / 3.14159265f);
                    worstSlide = std::max(worstSlide, glm::length(glm::vec2(foot.ankle[f].x - touchdown.x,
                                                                            foot.ankle[f].z - touchdown.z)));
                }
                const QString what =
                    QString("%1 %2 foot: down %3 of %4 frames, slid %5 m, lowest sole %6 m, sole off the slope %7 deg")
                        .arg(who).arg(side == 0 ? "left" : "right").arg(down).arg(frames).arg(worstSlide).arg(lowest)
                        .arg(worstTiltDeg);
                qInfo("%s", qPrintable(what));
                QVERIFY2(down > frames / 4, qPrintable(what));
                QVERIFY2(worstSlide < 0.01f, qPrintable(what));
                QVERIFY2(lowest > -0.02f, qPrintable(what));
                QVERIFY2(worstTiltDeg < kTiltDeg, qPrintable(what));
            }
            // Walking or standing, one foot is always down: the lower sole is on the terrain.
            float worstAbove = 0.0f;
            std::size_t judged = 0;
            for (std::size_t f = 0; f < frames; ++f) {
                if (cache.at(f, i).speed > 1.9f)
                    continue;
                ++judged;
                worstAbove = std::max(worstAbove, std::min(feet[0].sole[f], feet[1].sole[f]));
            }
            QVERIFY(judged > frames / 10);
            QVERIFY2(worstAbove < 0.02f, qPrintable(QString("%1: lower sole up to %2 m above the terrain")
                                                         .arg(who).arg(worstAbove)));
        }
    }
};

THRONG_REGISTER_TEST(TestTerrainFeet)
#include "TestTerrainFeet.moc"
