// The poses the viewport draws characters in: each pre-skinned walk, run and idle pose
// is the character's mesh skinned in the clip's pose at that phase (checked against a
// skinning written out here), the walk poses really differ, and an agent's recorded clip
// and phase pick the nearest pose.
#include "TestRegistry.h"

#include "editor/viewport/AgentCharacters.h"
#include "editor/viewport/PoseTable.h"
#include "export/character/BuiltinCharacters.h"
#include "export/character/Gait.h"

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

constexpr int kOneShotSamples = 16;  // the humanoid's fall and get_up

float topOf(const PoseTable& table, int pose)
{
    float y = -1e9f;
    for (std::size_t v = 0; v < table.vertexCount; ++v)
        y = std::max(y, table.positions[std::size_t(pose) * table.vertexCount + v].y);
    return y;
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
        // An action: standing, its own pose at the action's phase; moving, the walk at the
        // gait phase with the action's upper body; a car has no actions and keeps its wheels.
        const int wave = int(sim::Clip::Wave) - int(sim::Clip::Wait);
        QCOMPARE(man.poseFor(sim::Clip::Wave, 0.3f, 0.26f, false), PoseTable::actionPose(wave, 2));
        QCOMPARE(man.poseFor(sim::Clip::Wave, 0.5f, 0.9f, true), PoseTable::walkingActionPose(wave, 4));
        const int cheer = int(sim::Clip::Cheer) - int(sim::Clip::Wait);
        QCOMPARE(man.poseFor(sim::Clip::Cheer, 0.0f, 0.0f, false), PoseTable::actionPose(cheer, 0));
        QCOMPARE(car.poseFor(sim::Clip::Wave, 0.5f, 0.0f, false), PoseTable::walkPose(4));
    }

    // A horse's gait ladder: each rung's poses follow the others, are that gait skinned at
    // its phase, and a moving horse shows the rung nearest its speed (walk, trot, canter,
    // gallop at 1, 3, 5.5 and 9.5 m/s: past the middle between two, the faster).
    void aHorseShowsTheGaitOfItsSpeed()
    {
        const exporting::Character horse = exporting::makeHorse(exporting::Lod::Far);
        const PoseTable table = buildPoseTable(horse);
        QCOMPARE(table.ladderSpeeds, horse.ladderSpeeds);
        QCOMPARE(table.poseCount(), PoseTable::kPoseCount + 4 * PoseTable::kWalkPoses + 3 * table.ladderActions * PoseTable::kWalkPoses);
        QCOMPARE(table.positions.size(), table.vertexCount * std::size_t(table.poseCount()));
        QCOMPARE(table.joints.size(), table.jointCount * std::size_t(table.poseCount()));
        for (int r = 0; r < 4; ++r)
            for (int k = 0; k < PoseTable::kWalkPoses; k += 3) {
                const double phase = double(k) / PoseTable::kWalkPoses;
                const std::vector<glm::vec3> want = skinnedAt(horse, horse.ladder[std::size_t(r)], phase);
                const float off = maxDistance(table, PoseTable::ladderPose(r, k), want);
                QVERIFY2(off < 1e-4f, qPrintable(QString("rung %1 pose %2 is off by %3 m").arg(r).arg(k).arg(off)));
            }
        // The trot's pose at phase 0 differs from the walk's and the gallop's: the gaits differ.
        QVERIFY(maxDistance(table, PoseTable::ladderPose(1, 0), skinnedAt(horse, horse.ladder[0], 0.0)) > 0.1f);
        QVERIFY(maxDistance(table, PoseTable::ladderPose(1, 0), skinnedAt(horse, horse.ladder[3], 0.0)) > 0.1f);
        const struct { float speed; int rung; } picks[] = {{0.5f, 0}, {1.9f, 0}, {2.1f, 1}, {4.0f, 1}, {4.5f, 2},
                                                           {7.0f, 2}, {7.5f, 3}, {12.0f, 3}};
        for (const auto& p : picks) {
            QCOMPARE(table.poseFor(sim::Clip::Walk, 0.26f, 0.0f, true, p.speed), PoseTable::ladderPose(p.rung, 2));
            QCOMPARE(table.poseFor(sim::Clip::Run, 0.26f, 0.0f, true, p.speed), PoseTable::ladderPose(p.rung, 2));
        }
        // Standing, it stands; without a speed, walk and run as for any character.
        QCOMPARE(table.poseFor(sim::Clip::Idle, 0.26f, 0.0f, false, 0.0f), 0);
        QCOMPARE(table.poseFor(sim::Clip::Run, 0.26f), PoseTable::runPose(2));
    }

    // A rider acts at every gait: past the walk, each rung has a pose per looping action
    // (wait, look_around, shift_weight, wave, point, cheer, talk), the export's pose for
    // that rung with the action at mid-cycle; a moving horse whose rider waves shows its
    // rung with the hand up, and one whose brain picks an action the horse lacks (fall)
    // shows its gait.
    void aRiderActsAtEveryGait()
    {
        const exporting::Character horse = exporting::makeHorse(exporting::Lod::Far);
        const PoseTable table = buildPoseTable(horse);
        QCOMPARE(table.ladderActions, 7);
        QCOMPARE(table.poseCount(), PoseTable::kPoseCount + 4 * PoseTable::kWalkPoses + 3 * 7 * PoseTable::kWalkPoses);
        QCOMPARE(table.positions.size(), table.vertexCount * std::size_t(table.poseCount()));
        QCOMPARE(table.joints.size(), table.jointCount * std::size_t(table.poseCount()));
        const int wave = int(sim::Clip::Wave) - int(sim::Clip::Wait);
        const int talk = int(sim::Clip::Talk) - int(sim::Clip::Wait);
        const int fall = int(sim::Clip::Fall) - int(sim::Clip::Wait);
        QCOMPARE(int(table.ladderActionSlot[std::size_t(fall)]), -1);
        for (const int a : {wave, talk})
            for (int r = 1; r < 4; ++r)
                for (int k = 0; k < PoseTable::kWalkPoses; k += 3) {
                    exporting::GaitFrame g;
                    g.phase = double(k) / PoseTable::kWalkPoses;
                    g.runWeight = float(r) / 3.0f;
                    g.action = {horse.actionIndex(sim::toString(sim::Clip(int(sim::Clip::Wait) + a))), 0.5, 1.0f};
                    QVERIFY(g.action.action >= 0);
                    const std::vector<glm::mat4> globals =
                        exporting::jointGlobalTransforms(horse, exporting::gaitPose(horse, g));
                    std::vector<glm::vec3> want(horse.mesh.positions.size());
                    for (std::size_t v = 0; v < want.size(); ++v)
                        want[v] = skinnedVertex(horse, globals, v);
                    const float off = maxDistance(table, table.ladderActionPose(r, a, k), want);
                    QVERIFY2(off < 1e-4f, qPrintable(QString("action %1 rung %2 pose %3 is off by %4 m")
                                                         .arg(a).arg(r).arg(k).arg(off)));
                }
        // Which pose a moving rider shows: walk (1 m/s, or runWeight 0), trot (3), canter
        // (5.5), gallop (9.5, or runWeight 1); standing, the action's own.
        QCOMPARE(table.poseFor(sim::Clip::Wave, 0.26f, 0.0f, true, 1.0f), PoseTable::walkingActionPose(wave, 2));
        QCOMPARE(table.poseFor(sim::Clip::Wave, 0.26f, 0.0f, true, 3.0f), table.ladderActionPose(1, wave, 2));
        QCOMPARE(table.poseFor(sim::Clip::Wave, 0.26f, 0.0f, true, 5.5f), table.ladderActionPose(2, wave, 2));
        QCOMPARE(table.poseFor(sim::Clip::Wave, 0.26f, 0.0f, true, 9.5f), table.ladderActionPose(3, wave, 2));
        QCOMPARE(table.poseFor(sim::Clip::Wave, 0.26f, 0.0f, true, 1.0f, 0.0f), PoseTable::walkingActionPose(wave, 2));
        QCOMPARE(table.poseFor(sim::Clip::Wave, 0.26f, 0.0f, true, 1.0f, 1.0f), table.ladderActionPose(3, wave, 2));
        QCOMPARE(table.poseFor(sim::Clip::Talk, 0.5f, 0.0f, true, 3.0f, 0.35f), table.ladderActionPose(1, talk, 4));
        QCOMPARE(table.poseFor(sim::Clip::Wave, 0.26f, 0.26f, false, 0.0f), PoseTable::actionPose(wave, 2));
        QCOMPARE(table.poseFor(sim::Clip::Fall, 0.26f, 0.5f, true, 5.5f), PoseTable::ladderPose(2, 2));
        // At a gallop the waving rider's right hand is over its head; the plain gallop's is not.
        const auto jointY = [&](int pose, int joint) {
            return table.joints[std::size_t(pose) * table.jointCount + std::size_t(joint)][3].y;
        };
        for (int k = 0; k < PoseTable::kWalkPoses; ++k) {
            const int waving = table.ladderActionPose(3, wave, k), riding = PoseTable::ladderPose(3, k);
            QVERIFY2(jointY(waving, exporting::kHorseRiderHandR) > jointY(waving, exporting::kHorseRiderHead),
                     qPrintable(QString("pose %1: hand %2, head %3").arg(k)
                                    .arg(jointY(waving, exporting::kHorseRiderHandR))
                                    .arg(jointY(waving, exporting::kHorseRiderHead))));
            QVERIFY(jointY(riding, exporting::kHorseRiderHandR) < jointY(riding, exporting::kHorseRiderHead));
        }
    }

    // Each action pose is the export's pose for it (gaitPose), skinned; the wave lifts a
    // hand above the head, and the walking wave keeps the walk's legs.
    void actionPosesAreTheExportsPoses()
    {
        const exporting::Character man = *exporting::makeBuiltinCharacter("man");
        const PoseTable table = buildPoseTable(man);
        QCOMPARE(table.hasAction, std::vector<std::uint8_t>(PoseTable::kActions, 1));
        auto skinned = [&](const exporting::GaitFrame& g) {
            const std::vector<glm::mat4> globals = exporting::jointGlobalTransforms(man, exporting::gaitPose(man, g));
            std::vector<glm::vec3> out(man.mesh.positions.size());
            for (std::size_t v = 0; v < out.size(); ++v)
                out[v] = skinnedVertex(man, globals, v);
            return out;
        };
        for (int a = 0; a < PoseTable::kActions; ++a) {
            const int index = man.actionIndex(sim::toString(sim::Clip(int(sim::Clip::Wait) + a)));
            QVERIFY(index >= 0);
            for (int k = 0; k < PoseTable::kActionPoses; ++k) {
                exporting::GaitFrame standing;
                standing.moveWeight = 0.0f;
                // A one-shot's poses run from its first sample to its held last one.
                const double last = double(kOneShotSamples - 1) / kOneShotSamples;
                const double phase = table.oneShot[std::size_t(a)] ? last * k / (PoseTable::kActionPoses - 1)
                                                                   : double(k) / PoseTable::kActionPoses;
                standing.action = {index, phase, 1.0f};
                QVERIFY(maxDistance(table, PoseTable::actionPose(a, k), skinned(standing)) < 1e-4f);
                if (table.oneShot[std::size_t(a)])
                    continue;  // played in full, moving or not: no walking poses shown
                exporting::GaitFrame walking;
                walking.phase = double(k) / PoseTable::kWalkPoses;
                walking.action = {index, 0.5, 1.0f};
                QVERIFY(maxDistance(table, PoseTable::walkingActionPose(a, k), skinned(walking)) < 1e-4f);
            }
        }
        auto top = [&](int pose) {
            float y = -1e9f;
            for (std::size_t v = 0; v < table.vertexCount; ++v)
                y = std::max(y, table.positions[std::size_t(pose) * table.vertexCount + v].y);
            return y;
        };
        const int wave = int(sim::Clip::Wave) - int(sim::Clip::Wait);
        QVERIFY2(top(PoseTable::actionPose(wave, 0)) > top(0) + 0.15f,
                 qPrintable(QString("%1 %2").arg(top(PoseTable::actionPose(wave, 0))).arg(top(0))));
        // Walking and waving: the legs are the walk's (some vertex far from the idle pose's
        // place, as in walk pose 2), and the hand is up.
        QVERIFY(top(PoseTable::walkingActionPose(wave, 2)) > top(0) + 0.15f);
        QVERIFY(maxDistance(table, PoseTable::walkingActionPose(wave, 2), skinnedAt(man, man.idle, 0.0)) > 0.15f);
    }

    // Fall and get_up play once: the viewport shows the pose for how far the agent is into
    // it (from its start, held at its end), moving or not; a fall's first pose stands, its
    // last lies on the ground, and getting up is the way back.
    void oneShotsPlayFromTheirStartAndHoldTheirEnd()
    {
        const exporting::Character man = *exporting::makeBuiltinCharacter("man", exporting::Lod::Mid);
        const PoseTable table = buildPoseTable(man);
        const int fall = int(sim::Clip::Fall) - int(sim::Clip::Wait);
        const int getUp = int(sim::Clip::GetUp) - int(sim::Clip::Wait);
        const int wave = int(sim::Clip::Wave) - int(sim::Clip::Wait);
        const int end = PoseTable::kActionPoses - 1;
        QVERIFY(table.oneShot[std::size_t(fall)] && table.oneShot[std::size_t(getUp)]);
        QVERIFY(!table.oneShot[std::size_t(wave)]);
        QCOMPARE(table.poseFor(sim::Clip::Fall, 0.3f, 0.0f, false), PoseTable::actionPose(fall, 0));
        QCOMPARE(table.poseFor(sim::Clip::Fall, 0.3f, 1.0f, true), PoseTable::actionPose(fall, end));
        QCOMPARE(table.poseFor(sim::Clip::Fall, 0.3f, 0.5f, true), PoseTable::actionPose(fall, 4));
        QCOMPARE(table.poseFor(sim::Clip::GetUp, 0.0f, 7.0f, false), PoseTable::actionPose(getUp, end));
        const QString tops = QString("fall %1 .. %2, get_up %3 .. %4 m")
                                 .arg(topOf(table, PoseTable::actionPose(fall, 0)))
                                 .arg(topOf(table, PoseTable::actionPose(fall, PoseTable::kActionPoses - 1)))
                                 .arg(topOf(table, PoseTable::actionPose(getUp, 0)))
                                 .arg(topOf(table, PoseTable::actionPose(getUp, PoseTable::kActionPoses - 1)));
        QVERIFY2(topOf(table, PoseTable::actionPose(fall, 0)) > 1.6f, qPrintable(tops));
        QVERIFY2(topOf(table, PoseTable::actionPose(fall, PoseTable::kActionPoses - 1)) < 0.5f, qPrintable(tops));
        QVERIFY2(topOf(table, PoseTable::actionPose(getUp, 0)) < 0.5f, qPrintable(tops));
        QVERIFY2(topOf(table, PoseTable::actionPose(getUp, PoseTable::kActionPoses - 1)) > 1.6f, qPrintable(tops));
        // Down on the way: every pose of the fall is no higher than the one before.
        for (int k = 1; k < PoseTable::kActionPoses; ++k)
            QVERIFY(topOf(table, PoseTable::actionPose(fall, k)) <=
                    topOf(table, PoseTable::actionPose(fall, k - 1)) + 0.02f);
    }

    // How long an agent has played its one-shot, counted back through the recorded frames:
    // 0 on the frame it switched, a frame's time per frame after, and no further back than
    // the clip lasts (it holds its end after that); 0 for agents playing anything else.
    void clipSinceCountsBackToTheSwitch()
    {
        sim::FrameCache cache;
        cache.reset({{1, 0}, {2, 0}}, 24.0f);
        for (int f = 0; f < 105; ++f) {
            sim::AgentFrame a, b;
            a.clip = f < 5 ? sim::Clip::Idle : sim::Clip::Fall;
            b.clip = f < 50 ? sim::Clip::Wave : sim::Clip::GetUp;
            cache.append(std::vector<sim::AgentFrame>{a, b});
        }
        std::vector<float> since;
        clipSinceS(cache, 5, since);
        QCOMPARE(since, (std::vector<float>{0.0f, 0.0f}));
        clipSinceS(cache, 8, since);
        QCOMPARE(since[0], 3.0f / 24.0f);
        QCOMPARE(since[1], 0.0f);  // a wave loops by time, not from its start
        clipSinceS(cache, 104, since);
        QVERIFY(since[0] >= sim::clipCycleS(sim::Clip::Fall));
        QCOMPARE(sim::oneShotProgress(sim::Clip::Fall, since[0]), 1.0f);
        QVERIFY(since[1] >= sim::clipCycleS(sim::Clip::GetUp) && since[1] < 54.0f / 24.0f);  // only as far as needed
        QCOMPARE(sim::oneShotProgress(sim::Clip::GetUp, since[1]), 1.0f);
        clipSinceS(cache, 60, since);
        QCOMPARE(since[1], 10.0f / 24.0f);
        QCOMPARE(sim::oneShotProgress(sim::Clip::GetUp, since[1]), float((10.0 / 24.0) / 2.0));
    }
};

THRONG_REGISTER_TEST(TestPoseTable)
#include "TestPoseTable.moc"
