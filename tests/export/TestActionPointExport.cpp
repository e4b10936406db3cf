// Action points in the file a user takes away: a walker that passes a bench (an action
// point that plays `sit` for 3 s, facing west) sits on it in the glTF as a reader
// evaluates it. Its hips are at walking height before, where the sit clip puts them
// while it sits, and back up after; its root stands still while it sits and turns to
// face west; the CSV says `sit` on exactly those frames; the Khronos-independent read
// back (tinygltf) sees every frame.
#include "GltfReadBack.h"
#include "RecordRun.h"
#include "TestRegistry.h"

#include "export/GltfExporter.h"
#include "export/character/BuiltinCharacters.h"
#include "export/TrajectoryCsv.h"
#include "simcore/io/SceneIO.h"
#include "simcore/world/World.h"

#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <cmath>

using namespace throng;

namespace {

constexpr const char* kBench = R"(throng: 1
settings: {fps: 24, seed: 3, duration: 14, bounds: {min: [-12, -10], max: [12, 10]}}
agent_types:
  - {name: walker, character: woman, max_speed: 1.3, variation: {speed: [1, 1], height: [1, 1]}}
goals: [{name: east, position: [10, 0], radius: 0.5}]
action_points:
  - {name: bench, position: [0, 0], radius: 0.8, action: sit, duration: 3, facing: 180}
agents:
  - {id: 1, type: walker, position: [-6, 0], heading: 0, goal: east}
)";

constexpr float kFps = 24.0f;
constexpr std::size_t kFrames = 14 * 24;

const std::vector<std::string> kHipsChain{"hips"};

}  // namespace

class TestActionPointExport : public QObject {
    Q_OBJECT

    sim::FrameCache m_cache;
    QTemporaryDir m_dir;
    tinygltf::Model m_model;
    std::size_t m_first = 0, m_last = 0;  // the frames the recording says it sits

private slots:
    void initTestCase()
    {
        const sim::LoadResult r = sim::parseScene(kBench, "bench.yaml", "");
        QVERIFY2(r.ok(), r.ok() ? "" : r.diagnostics[0].format().c_str());
        sim::World world(r.scene, sim::WorldOptions{0, false, 1});
        test::recordRun(world, kFrames, m_cache);
        exporting::GltfOptions options;
        options.path = m_dir.filePath("bench.glb").toStdString();
        QVERIFY(exporting::exportGltf(r.scene, m_cache, options).ok());
        std::string error;
        QVERIFY2(test::loadGltf(options.path, m_model, error), error.c_str());
    }

    void theCsvSaysSitWhileItSits()
    {
        const std::string csv = m_dir.filePath("bench.csv").toStdString();
        QVERIFY(exporting::writeTrajectoryCsv(m_cache, csv).ok());
        QFile file(QString::fromStdString(csv));
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QStringList lines = QString::fromUtf8(file.readAll()).split('\n', Qt::SkipEmptyParts);
        QVERIFY(lines[0].split(',').at(7) == "clip");
        std::vector<std::size_t> sits;
        for (const QString& line : lines.mid(1)) {
            const QStringList cells = line.split(',');
            if (cells[7] == "sit")
                sits.push_back(cells[0].toUInt());
        }
        QCOMPARE(sits.size(), std::size_t(3 * 24));
        for (std::size_t k = 1; k < sits.size(); ++k)
            QCOMPARE(sits[k], sits[k - 1] + 1);  // one run of frames
        m_first = sits.front();
        m_last = sits.back();
        QVERIFY(m_first > 24 * 3 && m_last < kFrames - 24 * 3);  // it walked to it and on
    }

    void itSitsInTheFile()
    {
        QVERIFY(m_last > m_first);
        const std::string root = "agent_1_walker";
        const int node = test::nodeNamed(m_model, root);
        QVERIFY(node >= 0);
        auto at = [&](std::size_t f) { return float(f) / kFps; };
        float walking = 1e9f;
        for (std::size_t f = 24; f + 12 < m_first; ++f)
            walking = std::min(walking, test::jointWorldAt(m_model, root, kHipsChain, at(f)).y);
        // Seated from when the blend (0.8 s) is over to the end of the run: the hips where
        // the woman's sit clip puts them on its 42 cm seat, well below walking height.
        const std::optional<exporting::Character> woman = exporting::makeBuiltinCharacter("woman");
        QVERIFY(woman && woman->actionIndex("sit") >= 0);
        const float sitting = woman->actions[std::size_t(woman->actionIndex("sit"))].clip.samples[0].rootTranslation.y;
        float lowest = 1e9f, highest = 0.0f;
        for (std::size_t f = m_first + 20; f <= m_last; ++f) {
            const float y = test::jointWorldAt(m_model, root, kHipsChain, at(f)).y;
            lowest = std::min(lowest, y);
            highest = std::max(highest, y);
        }
        QVERIFY2(std::fabs(lowest - sitting) < 0.01f && std::fabs(highest - sitting) < 0.01f,
                 qPrintable(QString("hips %1 to %2 m seated, the clip's %3 m").arg(lowest).arg(highest).arg(sitting)));
        QVERIFY2(sitting < walking - 0.15f, qPrintable(QString("%1 seated, %2 m walking").arg(sitting).arg(walking)));
        // Back up a second after it got up.
        float after = 1e9f;
        for (std::size_t f = m_last + 24; f < m_last + 48; ++f)
            after = std::min(after, test::jointWorldAt(m_model, root, kHipsChain, at(f)).y);
        QVERIFY2(std::fabs(after - walking) < 0.05f, qPrintable(QString("%1 vs %2").arg(after).arg(walking)));
        // The root stands still while it sits, and ends facing west (heading 180).
        const glm::vec3 from = glm::vec3(test::nodeLocalAt(m_model, node, at(m_first))[3]);
        const glm::vec3 to = glm::vec3(test::nodeLocalAt(m_model, node, at(m_last))[3]);
        QVERIFY2(glm::distance(from, to) < 1e-3f, qPrintable(QString::number(glm::distance(from, to))));
        QVERIFY(glm::length(glm::vec2(from.x, from.z)) < 0.8f + 0.1f);
        // (Turned half round from how it walked east at 1 s, whatever axis the rig faces.)
        QVERIFY(std::fabs(m_cache.frame(24)[0].headingRad) < 0.02f);
        const glm::mat3 walkingEast(test::nodeLocalAt(m_model, node, at(24)));
        const glm::mat3 seatedTurn(test::nodeLocalAt(m_model, node, at(m_last)));
        const glm::vec3 turned = glm::normalize(seatedTurn * glm::inverse(walkingEast) * glm::vec3(1.0f, 0.0f, 0.0f));
        QVERIFY2(turned.x < -0.999f, qPrintable(QString("%1 %2 %3").arg(turned.x).arg(turned.y).arg(turned.z)));
    }
};

THRONG_REGISTER_TEST(TestActionPointExport)
#include "TestActionPointExport.moc"
