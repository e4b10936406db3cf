// The poses the viewport draws characters in: each pre-skinned walk, run and idle pose
// is the character's mesh skinned in the clip's pose at that phase (checked against a
// skinning written out here), the walk poses really differ, and an agent's recorded clip
// and phase pick the nearest pose.
#include "TestRegistry.h"

#include "editor/viewport/PoseTable.h"
#include "export/character/BuiltinCharacters.h"

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>

#include <QTest>

#include <algorithm>

using namespace throng;
using namespace throng::editor;

namespace {

// Linear blend skinning of one vertex, term by term: sum over influences of
// weight * (joint's global transform * inverse bind matrix) * bind position.
glm::vec3 skinnedVertex(const exporting::Character& c, const std::vector<glm::mat4>& globals, std::size_t v)
{
    const exporting::CharacterMesh& m = c.mesh;
    glm::vec3 sum(0.0f);
    for (int k = 0; k < 4; ++k) {
        const float w = m.weights[v][k];
        if (w == 0.0f)
            continue;
        const std::size_t j = m.joints[v][std::size_t(k)];
        sum += w * glm::vec3(globals[j] * (m.inverseBindMatrices[j] * glm::vec4(m.positions[v], 1.0f)));
    }
    return sum;
}

// Largest distance between pose `pose` of the table and `reference`, m.
float maxDistance(const PoseTable& table, int pose, const std::vector<glm::vec3>& reference)
{
    float worst = 0.0f;
    for (std::size_t v = 0; v < table.vertexCount; ++v)
        worst = std::max(worst, glm::distance(table.positions[std::size_t(pose) * table.vertexCount + v], reference[v]));
    return worst;
}

std::vector<glm::vec3> skinnedAt(const exporting::Character& c, const exporting::CycleClip& clip, double phase)
{
    const std::vector<glm::mat4> globals = exporting::jointGlobalTransforms(c, exporting::sampleClip(clip, phase));
    std::vector<glm::vec3> out(c.mesh.positions.size());
    for (std::size_t v = 0; v < out.size(); ++v)
        out[v] = skinnedVertex(c, globals, v);
    return out;
}

}  // namespace

class TestPoseTable : public QObject {
    Q_OBJECT

private slots:
    void posesAreTheClipSkinnedAtTheirPhase_data()
    {
        QTest::addColumn<QString>("character");
        QTest::newRow("man") << "man";
        QTest::newRow("woman") << "woman";
        QTest::newRow("car") << "car";
    }

    void posesAreTheClipSkinnedAtTheirPhase()
    {
        QFETCH(QString, character);
        const std::optional<exporting::Character> c = exporting::makeBuiltinCharacter(character.toStdString());
        QVERIFY(c);
        const PoseTable table = buildPoseTable(*c);
        QCOMPARE(table.vertexCount, c->mesh.positions.size());
        QCOMPARE(table.positions.size(), table.vertexCount * PoseTable::kPoseCount);
        QCOMPARE(table.normals.size(), table.positions.size());
        QCOMPARE(table.indices, c->mesh.indices);
        for (int k = 0; k < PoseTable::kWalkPoses; ++k) {
            const float walk = maxDistance(table, PoseTable::walkPose(k),
                                           skinnedAt(*c, c->walk, double(k) / PoseTable::kWalkPoses));
            QVERIFY2(walk < 1e-4f, qPrintable(QString("walk pose %1 is off by %2 m").arg(k).arg(walk)));
            const float run =
                maxDistance(table, PoseTable::runPose(k), skinnedAt(*c, c->run, double(k) / PoseTable::kRunPoses));
            QVERIFY2(run < 1e-4f, qPrintable(QString("run pose %1 is off by %2 m").arg(k).arg(run)));
        }
        QVERIFY(maxDistance(table, 0, skinnedAt(*c, c->idle, 0.0)) < 1e-4f);
        for (std::size_t v = 0; v < table.normals.size(); ++v)
            QVERIFY(std::abs(glm::length(table.normals[v]) - 1.0f) < 1e-3f);
    }

    void walkPosesMoveTheLegs()
    {
        const exporting::Character man = *exporting::makeBuiltinCharacter("man");
        const PoseTable table = buildPoseTable(man);
        // A quarter cycle apart, some vertex (a foot) has moved by a good part of a stride.
        const std::vector<glm::vec3> quarter = skinnedAt(man, man.walk, 0.25);
        const float moved = maxDistance(table, PoseTable::walkPose(0), quarter);
        QVERIFY2(moved > 0.15f, qPrintable(QString::number(moved)));
        // The man stands on the ground at about his height.
        float lowest = 1e9f, highest = -1e9f;
        for (std::size_t v = 0; v < table.vertexCount; ++v) {
            lowest = std::min(lowest, table.positions[v].y);
            highest = std::max(highest, table.positions[v].y);
        }
        QVERIFY2(std::abs(lowest) < 0.05f, qPrintable(QString::number(lowest)));
        QVERIFY2(highest > 1.5f && highest < 2.0f, qPrintable(QString::number(highest)));
    }

    void recordedClipAndPhasePickTheNearestPose()
    {
        const PoseTable man = buildPoseTable(*exporting::makeBuiltinCharacter("man"));
        QCOMPARE(man.poseFor(sim::Clip::Idle, 0.3f), 0);
        QCOMPARE(man.poseFor(sim::Clip::Walk, 0.0f), PoseTable::walkPose(0));
        QCOMPARE(man.poseFor(sim::Clip::Walk, 0.26f), PoseTable::walkPose(2));
        QCOMPARE(man.poseFor(sim::Clip::Walk, 0.97f), PoseTable::walkPose(0));  // wraps to the cycle's start
        QCOMPARE(man.poseFor(sim::Clip::Run, 0.5f), PoseTable::runPose(4));
        // A car has no idle: stopped, it holds its wheels where the phase left them.
        const PoseTable car = buildPoseTable(*exporting::makeBuiltinCharacter("car"));
        QVERIFY(!car.hasIdle);
        QCOMPARE(car.poseFor(sim::Clip::Idle, 0.5f), PoseTable::walkPose(4));
    }
};

THRONG_REGISTER_TEST(TestPoseTable)
#include "TestPoseTable.moc"
