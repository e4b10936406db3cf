// Feet stay planted in the exported file itself, as a reader evaluates it: the foot joint's
// world position, computed from the file's node transforms and animation channels (16-bit
// rotations, dropped keys, compact windows and all), holds still while the foot is down.
#include "CrowdFixture.h"
#include "GltfReadBack.h"
#include "TestRegistry.h"

#include "export/GltfExporter.h"

#include <QTemporaryDir>
#include <QTest>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

using namespace throng;
using throng::test::CrowdFixture;

namespace {

glm::vec3 worldAt(const tinygltf::Model& model, const std::vector<int>& chain, float t)
{
    glm::mat4 m(1.0f);
    for (int node : chain)
        m = m * test::nodeLocalAt(model, node, t);
    return glm::vec3(m[3]);
}

}  // namespace

class TestBakedFeet : public QObject {
    Q_OBJECT

private slots:
    void feetStayPlantedInTheFile_data()
    {
        QTest::addColumn<bool>("compact");
        QTest::newRow("exact") << false;
        QTest::newRow("compact") << true;
    }

    // Agent 7 walks straight on at 1.2 m/s for 2 s: each foot, while within 3 mm of its
    // lowest point, stays within 1.5 cm of where it touched down, and is down at least a
    // third of the frames. Compact, exact in a steady walk, must do as well as exact.
    void feetStayPlantedInTheFile()
    {
        QFETCH(bool, compact);
        const CrowdFixture fx = CrowdFixture::make();
        QTemporaryDir dir;
        exporting::GltfOptions options;
        options.path = dir.filePath("crowd.glb").toStdString();
        options.mode = compact ? exporting::GltfMode::Compact : exporting::GltfMode::Exact;
        QVERIFY(exporting::exportGltf(fx.scene, fx.cache, options).ok());
        tinygltf::Model model;
        std::string error;
        QVERIFY2(test::loadGltf(options.path, model, error), error.c_str());
        for (const char* foot : {"foot_l", "foot_r"}) {
            const std::string side = std::string(foot).substr(5);  // "l" or "r"
            std::vector<int> chain;
            for (const std::string& name : {std::string("agent_7_walker"), std::string("agent_7_walker__hips"),
                                            "agent_7_walker__upper_leg_" + side, "agent_7_walker__lower_leg_" + side,
                                            "agent_7_walker__foot_" + side})
                chain.push_back(test::nodeNamed(model, name));
            QVERIFY(std::find(chain.begin(), chain.end(), -1) == chain.end());
            // Compact's first and last frame sit up to 1/24 cycle off (docs/export.md): judge
            // the frames between them.
            std::vector<glm::vec3> world;
            for (std::size_t f = compact ? 1 : 0; f < CrowdFixture::kFrames - (compact ? 1 : 0); ++f)
                world.push_back(worldAt(model, chain, static_cast<float>(f) / CrowdFixture::kFps));
            float lowest = 1e9f;
            for (const glm::vec3& p : world)
                lowest = std::min(lowest, p.y);
            std::size_t down = 0;
            float worst = 0.0f;
            glm::vec3 touchdown(0.0f);
            for (std::size_t f = 0; f < world.size(); ++f) {
                const bool isDown = world[f].y < lowest + 0.003f;
                if (isDown && (f == 0 || world[f - 1].y >= lowest + 0.003f))
                    touchdown = world[f];
                if (isDown) {
                    ++down;
                    worst = std::max(worst, glm::length(glm::vec2(world[f].x - touchdown.x, world[f].z - touchdown.z)));
                }
            }
            const QString what = QString("%1: down %2 of %3 frames, slid %4 m").arg(foot).arg(down).arg(world.size()).arg(worst);
            QVERIFY2(down >= world.size() / 3, qPrintable(what));
            QVERIFY2(worst < 0.015f, qPrintable(what));
            QVERIFY(world.back().x - world.front().x > 1.5f);  // the foot did travel with the body
        }
    }
};

THRONG_REGISTER_TEST(TestBakedFeet)
#include "TestBakedFeet.moc"
