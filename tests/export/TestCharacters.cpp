// Throng's own characters are well-formed rigs whose clips do what a user would check by
// eye: feet stay put on the ground while the body walks or runs over them, walk turns
// into run with speed and into idle at a stop, car wheels roll with the road, birds flap.
#include "TestRegistry.h"

#include "export/character/BuiltinCharacters.h"
#include "export/character/AgentVariation.h"
#include "export/character/Gait.h"
#include "export/character/LegIk.h"

#include <QTest>

#include <glm/gtc/quaternion.hpp>
#include <glm/mat4x4.hpp>

#include <algorithm>
#include <array>
#include <map>
#include <cmath>

using namespace throng;
using namespace throng::exporting;

namespace {

Character builtin(const char* name)
{
    std::optional<Character> c = makeBuiltinCharacter(name);
    return c ? *c : Character{};
}

int jointNamed(const Character& c, const char* name)
{
    for (std::size_t j = 0; j < c.joints.size(); ++j)
        if (c.joints[j].name == name)
            return static_cast<int>(j);
    return -1;
}

// World position of joint `j` for an agent at `root` facing +X, scaled by `scale`.
glm::vec3 jointWorld(const Character& c, const Pose& pose, int j, glm::vec3 root, float scale)
{
    return root + scale * glm::vec3(jointGlobalTransforms(c, pose)[static_cast<std::size_t>(j)][3]);
}

// The top of what every agent of the character wears (not the accessories some wear).
float maxHeight(const Character& c)
{
    float y = -1e9f;
    for (const MeshPart& part : partsOf(c.mesh))
        if (part.wornShare >= 1.0f && part.slot != MaterialSlot::Hat)
            for (std::uint32_t i = part.firstIndex; i < part.firstIndex + part.indexCount; ++i)
                y = std::max(y, c.mesh.positions[c.mesh.indices[i]].y);
    return y;
}

const MeshPart* partOf(const Character& c, MaterialSlot slot)
{
    for (const MeshPart& part : c.mesh.parts)
        if (part.slot == slot)
            return &part;
    return nullptr;
}

std::size_t triangles(const Character& c) { return c.mesh.indices.size() / 3; }

// Vertices at the same place are one point of the surface (a part's edge is written once
// for each side); each gets the smallest index among them.
std::vector<std::uint32_t> weldedIndices(const CharacterMesh& m)
{
    std::map<std::array<float, 3>, std::uint32_t> first;
    std::vector<std::uint32_t> welded(m.positions.size());
    for (std::uint32_t v = 0; v < m.positions.size(); ++v)
        welded[v] = first.emplace(std::array<float, 3>{m.positions[v].x, m.positions[v].y, m.positions[v].z}, v)
                        .first->second;
    return welded;
}

}  // namespace

class TestCharacters : public QObject {
    Q_OBJECT

private slots:
    void builtinsAreWellFormed_data()
    {
        QTest::addColumn<QString>("name");
        QTest::addColumn<int>("joints");
        for (const char* n : {"man", "woman", "tall_man", "child", "elderly"})
            QTest::newRow(n) << n << 17;
        QTest::newRow("car") << "car" << 5;
        QTest::newRow("bird") << "bird" << 7;
    }

    // Consistent rigs; every vertex's weights sum to exactly 1 in float32, and unused
    // influence slots name joint 0 with weight 0 (what the Khronos validator demands).
    void builtinsAreWellFormed()
    {
        QFETCH(QString, name);
        QFETCH(int, joints);
        const Character c = builtin(qPrintable(name));
        QCOMPARE(checkCharacter(c), std::string());
        QCOMPARE(static_cast<int>(c.joints.size()), joints);
        for (std::size_t v = 0; v < c.mesh.weights.size(); ++v) {
            const glm::vec4 w = c.mesh.weights[v];
            QCOMPARE(w.x + w.y + w.z + w.w, 1.0f);
            for (int k = 0; k < 4; ++k)
                if (w[k] == 0.0f)
                    QCOMPARE(int(c.mesh.joints[v][k]), 0);
        }
        QVERIFY(c.walk.strideM > 0.0f && c.run.strideM > 0.0f);
        QVERIFY(c.walk.samples.size() >= 8);
        QVERIFY(!makeBuiltinCharacter("zombie"));
    }

    // The humanoid skeleton has the joints the issue lists; builds differ in size, the
    // child always wears its hat, the man only sometimes, and the elderly stoop, grey-haired.
    void humanoidLooks()
    {
        const Character man = builtin("man"), woman = builtin("woman"), tall = builtin("tall_man");
        const Character child = builtin("child"), elderly = builtin("elderly");
        for (const char* j : {"hips", "spine", "chest", "neck", "head", "upper_arm_l", "lower_arm_l", "hand_l",
                              "upper_arm_r", "lower_arm_r", "hand_r", "upper_leg_l", "lower_leg_l", "foot_l",
                              "upper_leg_r", "lower_leg_r", "foot_r"})
            QVERIFY2(jointNamed(man, j) >= 0, j);
        QVERIFY(std::abs(maxHeight(man) - 1.75f) < 0.08f);
        QVERIFY(maxHeight(tall) > maxHeight(man) + 0.1f);
        QVERIFY(maxHeight(woman) < maxHeight(man));
        QVERIFY(maxHeight(child) < 1.3f);
        QVERIFY(maxHeight(elderly) < maxHeight(man) && maxHeight(elderly) > maxHeight(woman) - 0.1f);
        QVERIFY(partOf(child, MaterialSlot::Hat) && partOf(child, MaterialSlot::Hat)->wornShare == 1.0f);
        QVERIFY(partOf(man, MaterialSlot::Hat) && partOf(man, MaterialSlot::Hat)->wornShare < 0.5f);
        QVERIFY(partOf(elderly, MaterialSlot::GreyHair) && !partOf(elderly, MaterialSlot::Hair));
        QVERIFY(!partOf(elderly, MaterialSlot::Bag) && partOf(woman, MaterialSlot::Bag));
        // The stoop: the neck sits ahead of the chest, the man's straight above it.
        QVERIFY(elderly.joints[kNeck].restTranslation.x > 0.04f);
        QCOMPARE(man.joints[kNeck].restTranslation.x, 0.0f);
        QVERIFY(man.mesh.positions.size() != woman.mesh.positions.size());  // skirt and hair
    }

    void smoothClosedSurfaces_data()
    {
        QTest::addColumn<QString>("name");
        for (const char* n : {"man", "woman", "tall_man", "child", "elderly"})
            QTest::newRow(n) << n;
    }

    // No boxes: at every level of detail each body is closed surfaces (every edge, welded
    // across part borders, joins exactly two triangles, once each way), smooth (no crease:
    // a point's copies share one normal; at the near level nine in ten edges turn the
    // normal by under 30 degrees and none folds it by 90), with normals pointing out of the
    // triangles around them; near has a few thousand triangles, each farther level about
    // half or less.
    void smoothClosedSurfaces()
    {
        QFETCH(QString, name);
        std::size_t previous = 0;
        for (Lod lod : {Lod::Near, Lod::Mid, Lod::Far}) {
            const std::optional<Character> made = makeBuiltinCharacter(name.toStdString(), lod);
            QVERIFY(made);
            const CharacterMesh& m = made->mesh;
            const QString what = name + " " + toString(lod);
            QCOMPARE(checkCharacter(*made), std::string());
            const std::size_t count = triangles(*made);
            if (lod == Lod::Near)
                QVERIFY2(count >= 3000 && count <= 9000, qPrintable(what + ": " + QString::number(count)));
            else
                QVERIFY2(count * 2 <= previous + previous / 5 && count >= 400,
                         qPrintable(what + ": " + QString::number(count)));
            previous = count;

            const std::vector<std::uint32_t> welded = weldedIndices(m);
            std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
            std::vector<glm::vec3> faceNormalSum(m.positions.size(), glm::vec3(0.0f));
            for (std::size_t t = 0; t < m.indices.size(); t += 3) {
                const std::uint32_t v[3] = {m.indices[t], m.indices[t + 1], m.indices[t + 2]};
                const glm::vec3 n =
                    glm::cross(m.positions[v[1]] - m.positions[v[0]], m.positions[v[2]] - m.positions[v[0]]);
                for (int k = 0; k < 3; ++k) {
                    ++directed[{welded[v[k]], welded[v[(k + 1) % 3]]}];
                    faceNormalSum[welded[v[k]]] += n;
                }
            }
            int open = 0, twisted = 0, turning = 0, folded = 0, inward = 0, split = 0;
            for (const auto& [edge, uses] : directed) {
                const auto back = directed.find({edge.second, edge.first});
                open += back == directed.end() ? 1 : 0;
                twisted += uses != 1 ? 1 : 0;
                const float cosine = glm::dot(m.normals[edge.first], m.normals[edge.second]);
                turning += cosine < std::cos(glm::radians(30.0f)) ? 1 : 0;
                folded += cosine <= 0.0f ? 1 : 0;
            }
            for (std::uint32_t v = 0; v < m.positions.size(); ++v) {
                split += m.normals[v] != m.normals[welded[v]] ? 1 : 0;
                if (welded[v] == v && glm::length(faceNormalSum[v]) > 0.0f)
                    inward += glm::dot(glm::normalize(faceNormalSum[v]), m.normals[v]) < 0.5f ? 1 : 0;
            }
            QVERIFY2(open == 0 && twisted == 0,
                     qPrintable(what + QString(": %1 open, %2 twisted edges").arg(open).arg(twisted)));
            QVERIFY2(split == 0, qPrintable(what + QString(": %1 points with two normals").arg(split)));
            if (lod == Lod::Near)
                QVERIFY2(turning * 10 < int(directed.size()) && folded == 0,
                         qPrintable(what + QString(": %1 of %2 edges turn the normal 30 degrees or more, %3 by 90")
                                               .arg(turning)
                                               .arg(directed.size())
                                               .arg(folded)));
            QVERIFY2(inward == 0, qPrintable(what + QString(": %1 normals against their faces").arg(inward)));
        }
    }

    // Clothes and skin are separate materials that own their vertices; elbows and knees
    // bend one surface: a whole ring of vertices there is skinned to both bones.
    void partsAndSmoothSkinning()
    {
        for (const char* name : {"man", "woman", "child", "elderly"}) {
            const Character c = builtin(name);
            std::vector<int> owner(c.mesh.positions.size(), -1);
            for (std::size_t p = 0; p < c.mesh.parts.size(); ++p) {
                const MeshPart& part = c.mesh.parts[p];
                for (std::uint32_t i = part.firstIndex; i < part.firstIndex + part.indexCount; ++i) {
                    int& o = owner[c.mesh.indices[i]];
                    QVERIFY2(o < 0 || o == int(p), name);
                    o = int(p);
                }
            }
            for (MaterialSlot slot : {MaterialSlot::Skin, MaterialSlot::Top, MaterialSlot::Bottom, MaterialSlot::Shoes})
                QVERIFY2(partOf(c, slot), qPrintable(QString("%1 has no %2").arg(name, toString(slot))));
            auto shared = [&](int a, int b) {
                int n = 0;
                for (std::size_t v = 0; v < c.mesh.positions.size(); ++v) {
                    float wa = 0.0f, wb = 0.0f;
                    for (int k = 0; k < 4; ++k) {
                        wa += c.mesh.joints[v][k] == a ? c.mesh.weights[v][k] : 0.0f;
                        wb += c.mesh.joints[v][k] == b ? c.mesh.weights[v][k] : 0.0f;
                    }
                    n += wa >= 0.25f && wb >= 0.25f ? 1 : 0;
                }
                return n;
            };
            QVERIFY2(shared(kUpperArmL, kLowerArmL) >= 14, name);
            QVERIFY2(shared(kUpperLegR, kLowerLegR) >= 14, name);
            QVERIFY2(shared(kSpine, kChest) >= 14, name);
            QVERIFY2(shared(kNeck, kHead) >= 14, name);
        }
    }

    // Who wears an accessory is drawn per agent and seed: about the share the build
    // gives, the same on every call, and a different crowd for another seed.
    void accessoriesAreWornByTheirShare()
    {
        const Character man = builtin("man");
        const MeshPart& hat = *partOf(man, MaterialSlot::Hat);
        int worn = 0, differ = 0;
        for (std::uint32_t id = 1; id <= 4000; ++id) {
            const bool w = wearsPart(hat, 7, id);
            QCOMPARE(wearsPart(hat, 7, id), w);
            worn += w ? 1 : 0;
            differ += w != wearsPart(hat, 8, id) ? 1 : 0;
        }
        QVERIFY2(std::abs(worn / 4000.0 - hat.wornShare) < 0.025, qPrintable(QString::number(worn)));
        QVERIFY(differ > 400);
        QVERIFY(wearsPart(*partOf(builtin("child"), MaterialSlot::Hat), 7, 123));
    }

    void feetStayPlanted_data()
    {
        QTest::addColumn<QString>("name");
        QTest::addColumn<float>("speed");
        QTest::addColumn<float>("heightScale");
        QTest::newRow("man walking") << "man" << 1.3f << 1.0f;
        QTest::newRow("tall man walking, scaled") << "tall_man" << 1.5f << 1.08f;
        QTest::newRow("child walking") << "child" << 0.8f << 0.95f;
        QTest::newRow("man running") << "man" << 3.6f << 1.0f;
        QTest::newRow("woman running, scaled") << "woman" << 3.6f << 0.92f;
    }

    // An agent walks or runs straight on at constant speed for 3 s. Whenever a foot is down
    // (within 3 mm of its lowest point) it stays within 1 cm of where it touched down,
    // and feet are down a fair share of the time, so the check cannot pass vacuously.
    void feetStayPlanted()
    {
        QFETCH(QString, name);
        QFETCH(float, speed);
        QFETCH(float, heightScale);
        const Character c = builtin(qPrintable(name));
        constexpr float kFps = 60.0f;
        const std::size_t frames = 180;
        std::vector<glm::vec3> positions(frames);
        std::vector<float> speeds(frames, speed);
        for (std::size_t f = 0; f < frames; ++f)
            positions[f] = {speed * static_cast<float>(f) / kFps, 0.0f, 0.0f};
        AgentVariation v;
        v.heightScale = heightScale;
        v.phaseOffset = 0.37f;
        const std::vector<GaitFrame> gait = computeGait(c, positions, speeds, v);
        QVERIFY(gait.back().moveWeight == 1.0f);
        QVERIFY(gait.back().runWeight == 0.0f || gait.back().runWeight == 1.0f);  // one clip, no blend
        for (const char* footName : {"foot_l", "foot_r"}) {
            const int foot = jointNamed(c, footName);
            std::vector<glm::vec3> world(frames);
            for (std::size_t f = 0; f < frames; ++f)
                world[f] = jointWorld(c, gaitPose(c, gait[f]), foot, positions[f], heightScale);
            float lowest = 1e9f;
            for (const glm::vec3& p : world)
                lowest = std::min(lowest, p.y);
            std::size_t planted = 0;
            float worstSlideM = 0.0f;
            glm::vec3 touchdown(0.0f);
            for (std::size_t f = 0; f < frames; ++f) {
                const bool down = world[f].y < lowest + 0.003f;
                if (down && (f == 0 || world[f - 1].y >= lowest + 0.003f))
                    touchdown = world[f];
                if (down) {
                    ++planted;
                    worstSlideM = std::max(worstSlideM, glm::length(glm::vec2(world[f].x - touchdown.x, world[f].z - touchdown.z)));
                }
            }
            const QString what = QString("%1: %2 of %3 frames down, slid %4 m").arg(footName).arg(planted).arg(frames).arg(worstSlideM);
            QVERIFY2(planted > frames / 4, qPrintable(what));
            QVERIFY2(worstSlideM < 0.01f, qPrintable(what));
            // The body really travelled over the planted foot: 3 s at speed.
            QVERIFY(positions.back().x > 2.0f);
        }
    }

    // Stopped: idle, arms hanging (hands under the shoulders); walking pace: walk;
    // fast: run. The phase advances by distance over stride, and not at all standing still.
    void gaitFollowsSpeed()
    {
        const Character man = builtin("man");
        const std::vector<glm::vec3> still(10, glm::vec3(3.0f, 0.0f, 4.0f));
        const std::vector<float> zero(10, 0.0f);
        AgentVariation v;
        v.phaseOffset = 0.25f;
        const std::vector<GaitFrame> standing = computeGait(man, still, zero, v);
        QCOMPARE(standing.back().moveWeight, 0.0f);
        QCOMPARE(standing.back().phase, 0.25);
        const Pose idle = gaitPose(man, standing.back());
        for (auto [shoulder, hand] : {std::pair(kUpperArmL, kHandL), std::pair(kUpperArmR, kHandR)}) {
            const glm::vec3 s = jointWorld(man, idle, shoulder, {}, 1.0f), h = jointWorld(man, idle, hand, {}, 1.0f);
            QVERIFY(std::abs(h.x - s.x) < 0.05f && h.y < s.y - 0.4f);
        }
        std::vector<glm::vec3> line(2);
        line[1] = {10.0f, 0.0f, 0.0f};
        for (auto [speed, run] : {std::pair(1.3f, 0.0f), std::pair(3.6f, 1.0f)}) {
            const std::vector<float> speeds(2, speed);
            const std::vector<GaitFrame> g = computeGait(man, line, speeds, v);
            QCOMPARE(g[1].moveWeight, 1.0f);
            QCOMPARE(g[1].runWeight, run);
            const double stride = run > 0.0f ? man.run.strideM : man.walk.strideM;
            QVERIFY(std::abs((g[1].phase - g[0].phase) - 10.0 / stride) < 1e-6);
        }
        QVERIFY(man.run.strideM > 1.8f * man.walk.strideM);
        const std::vector<float> between(2, 2.6f);
        const float blend = computeGait(man, line, between, v)[1].runWeight;
        QVERIFY(blend > 0.1f && blend < 0.9f);
    }

    // An action blends in and out over 0.3 s at any frame rate (the weight counts time,
    // not frames); a switch from one action to another fades the first out from where it
    // was while the second fades in; an action on the first frame plays in full.
    void actionsBlendOverTheSameTimeAtAnyFrameRate()
    {
        const Character man = *makeBuiltinCharacter("man");
        const int wave = man.actionIndex("wave"), cheer = man.actionIndex("cheer");
        QVERIFY(wave >= 0 && cheer >= 0);
        for (const float fps : {12.0f, 24.0f, 60.0f}) {
            // 1 s idle, 1 s wave, 1 s cheer, 1 s idle, standing still.
            const auto n = std::size_t(4.0f * fps);
            std::vector<glm::vec3> still(n, glm::vec3(0.0f));
            std::vector<float> zero(n, 0.0f), phases(n, 0.25f);
            std::vector<sim::Clip> clips(n, sim::Clip::Idle);
            for (std::size_t f = 0; f < n; ++f)
                clips[f] = f < std::size_t(fps)       ? sim::Clip::Idle
                           : f < std::size_t(2 * fps) ? sim::Clip::Wave
                           : f < std::size_t(3 * fps) ? sim::Clip::Cheer
                                                      : sim::Clip::Idle;
            const std::vector<GaitFrame> g = computeGait(man, still, zero, AgentVariation{}, {clips, phases, fps});
            auto at = [&](float s) { return g[std::size_t(std::lround(s * fps))]; };
            const QString where = QString("at %1 fps").arg(fps);
            QCOMPARE(at(0.5f).action.action, -1);
            QCOMPARE(at(1.0f).action.action, wave);
            QCOMPARE(at(1.0f).action.weight, 0.0f);
            QVERIFY2(std::abs(at(1.15f).action.weight - 0.5f) < 0.06f, qPrintable(where));
            QVERIFY2(at(1.35f).action.weight > 0.99f, qPrintable(where));
            // Wave to cheer: the wave fades out as the cheer fades in, in 0.3 s.
            QCOMPARE(at(2.15f).action.action, cheer);
            QCOMPARE(at(2.15f).fading.action, wave);
            QVERIFY2(std::abs(at(2.15f).action.weight + at(2.15f).fading.weight - 1.0f) < 0.1f, qPrintable(where));
            QCOMPARE(at(2.4f).fading.action, -1);
            // Cheer ends: it fades out and is gone after 0.3 s.
            QCOMPARE(at(3.15f).fading.action, cheer);
            QCOMPARE(at(3.5f).fading.action, -1);
            QCOMPARE(at(3.5f).action.action, -1);
        }
        // On the first frame an action already playing is in full.
        std::vector<sim::Clip> waving(3, sim::Clip::Wave);
        std::vector<float> phases(3, 0.0f), zero(3, 0.0f);
        std::vector<glm::vec3> still(3, glm::vec3(0.0f));
        QCOMPARE(computeGait(man, still, zero, AgentVariation{}, {waving, phases, 24.0f})[0].action.weight, 1.0f);
    }

    // Fall and get_up play once from the frame they start: the phase runs from the first
    // sample to the last over the clip's length and then holds it, so the hips go down and
    // stay down until get_up brings them back. A type's action_blend replaces the clip's
    // own blend time (here a second instead of 0.15 s).
    void oneShotsPlayOnceAndHoldWithTheTypesBlend()
    {
        const Character man = builtin("man");
        const int fall = man.actionIndex("fall"), getUp = man.actionIndex("get_up");
        QVERIFY(fall >= 0 && getUp >= 0 && man.actions[std::size_t(fall)].oneShot &&
                man.actions[std::size_t(getUp)].oneShot && !man.actions[std::size_t(man.actionIndex("wave"))].oneShot);
        constexpr float kFps = 24.0f;
        const std::size_t frames = 24 * 9, fallAt = 24, getUpAt = 24 + 72;  // idle for 2 s after
        std::vector<glm::vec3> positions(frames, glm::vec3(0.0f));
        std::vector<float> speeds(frames, 0.0f), phases(frames, 0.0f);
        std::vector<sim::Clip> clips(frames, sim::Clip::Idle);
        for (std::size_t f = fallAt; f < getUpAt; ++f)
            clips[f] = sim::Clip::Fall;
        for (std::size_t f = getUpAt; f < getUpAt + 72; ++f)
            clips[f] = sim::Clip::GetUp;
        const double last = 15.0 / 16.0;  // the last of 16 samples
        for (const float blendS : {-1.0f, 1.0f}) {
            const std::vector<GaitFrame> gait = computeGait(man, positions, speeds, AgentVariation{},
                                                            {clips, phases, kFps, blendS});
            QCOMPARE(gait[fallAt].action.action, fall);
            QCOMPARE(gait[fallAt].action.phase, 0.0);
            QCOMPARE(gait[fallAt].action.weight, 0.0f);
            QVERIFY(std::abs(gait[fallAt + 12].action.phase - last * 0.5 / 1.2) < 1e-6);
            QCOMPARE(gait[fallAt + 40].action.phase, last);  // 1.67 s in: held at the end
            QCOMPARE(gait[getUpAt - 1].action.phase, last);
            // The blend: 0.15 s of the clip's own, or the type's second.
            const float halfSecond = gait[fallAt + 12].action.weight;
            QVERIFY2(blendS < 0.0f ? halfSecond == 1.0f : std::abs(halfSecond - 0.5f) < 1e-4f,
                     qPrintable(QString::number(halfSecond)));
            const auto hipsY = [&](std::size_t f) {
                return jointGlobalTransforms(man, gaitPose(man, gait[f]))[0][3].y;
            };
            const float standing = hipsY(fallAt - 1);
            QVERIFY2(standing > 0.85f, qPrintable(QString::number(standing)));
            for (std::size_t f = fallAt + 48; f < getUpAt; ++f)  // 2 s in: lying, and held
                QVERIFY2(hipsY(f) < 0.3f && std::abs(hipsY(f) - hipsY(getUpAt - 1)) < 1e-5f,
                         qPrintable(QString("frame %1: hips %2 m").arg(f).arg(hipsY(f))));
            QVERIFY(hipsY(getUpAt + 24) > 0.3f);               // getting up, half-way
            QVERIFY(std::abs(hipsY(getUpAt + 60) - standing) < 0.02f);  // up after its 2 s and the blend
            QVERIFY(std::abs(hipsY(frames - 1) - standing) < 1e-4f);   // and idle again, blended back
        }
    }

    // Sitting down is slower than a wave: the clip's own 0.8 s blend, at any frame rate.
    // Seated, the hips are 40 cm lower, the thighs level and the ankles where standing put
    // them; getting up takes the same time. A weight shift holds the feet too.
    void sittingTakesItsOwnBlendAndKeepsTheFeetDown()
    {
        const Character man = *makeBuiltinCharacter("man");
        const int sit = man.actionIndex("sit");
        QVERIFY(sit >= 0 && man.actionIndex("shift_weight") >= 0 && man.actionIndex("point") >= 0);
        QCOMPARE(man.actions[std::size_t(sit)].blendS, 0.8f);
        const std::vector<std::uint8_t>& sitMask = man.actions[std::size_t(sit)].layered;
        QVERIFY(std::count(sitMask.begin(), sitMask.end(), 1) == 0);
        const Pose idle = sampleClip(man.idle, 0.0);
        const std::vector<glm::mat4> standing = jointGlobalTransforms(man, idle);
        for (const float fps : {12.0f, 24.0f, 60.0f}) {
            // 1 s standing, 2 s seated, 1 s standing again, in place.
            const auto n = std::size_t(4.0f * fps);
            std::vector<glm::vec3> still(n, glm::vec3(0.0f));
            std::vector<float> zero(n, 0.0f), phases(n, 0.0f);
            std::vector<sim::Clip> clips(n, sim::Clip::Idle);
            for (std::size_t f = std::size_t(fps); f < std::size_t(3 * fps); ++f)
                clips[f] = sim::Clip::Sit;
            const std::vector<GaitFrame> g = computeGait(man, still, zero, AgentVariation{}, {clips, phases, fps});
            auto at = [&](float s) { return g[std::size_t(std::lround(s * fps))]; };
            const QString where = QString("at %1 fps").arg(fps);
            QVERIFY2(std::abs(at(1.4f).action.weight - 0.5f) < 0.06f, qPrintable(where));
            QVERIFY2(at(1.7f).action.weight < 0.9f && at(1.85f).action.weight > 0.99f, qPrintable(where));
            QCOMPARE(at(3.4f).fading.action, sit);
            QVERIFY2(std::abs(at(3.4f).fading.weight - 0.5f) < 0.06f, qPrintable(where));
            // Sitting down and getting up, the ankles stay where they stood (leg IK).
            for (std::size_t f = 0; f < n; ++f) {
                const std::vector<glm::mat4> m = jointGlobalTransforms(man, gaitPose(man, g[f]));
                for (int foot : {int(kFootL), int(kFootR)})
                    QVERIFY2(glm::distance(glm::vec3(m[foot][3]), glm::vec3(standing[foot][3])) < 0.005f,
                             qPrintable(where + QString(", frame %1").arg(f)));
            }
            const std::vector<glm::mat4> seated = jointGlobalTransforms(man, gaitPose(man, at(2.5f)));
            QVERIFY2(standing[kHips][3].y - seated[kHips][3].y > 0.35f, qPrintable(where));
            for (int upper : {int(kUpperLegL), int(kUpperLegR)}) {
                QVERIFY2(std::abs(seated[upper + 1][3].y - seated[upper][3].y) < 0.05f, qPrintable(where));  // level
                QVERIFY2(std::abs(seated[upper + 2][3].y - standing[upper + 2][3].y) < 0.01f, qPrintable(where));
                QVERIFY2(seated[upper + 1][3].x > seated[upper][3].x + 0.35f, qPrintable(where));  // knees ahead
            }
        }
        // A weight shift: the hips move 4 cm or more sideways while both feet stay within 5 mm.
        const int shift = man.actionIndex("shift_weight");
        float hipsLo = 1e9f, hipsHi = -1e9f, footMoved = 0.0f;
        for (int k = 0; k < 32; ++k) {
            GaitFrame frame;
            frame.moveWeight = 0.0f;
            frame.action = {shift, k / 32.0, 1.0f};
            const std::vector<glm::mat4> m = jointGlobalTransforms(man, gaitPose(man, frame));
            hipsLo = std::min(hipsLo, m[kHips][3].z);
            hipsHi = std::max(hipsHi, m[kHips][3].z);
            for (int foot : {int(kFootL), int(kFootR)})
                footMoved = std::max(footMoved, glm::distance(glm::vec3(m[foot][3]), glm::vec3(standing[foot][3])));
        }
        QVERIFY2(hipsHi - hipsLo > 0.08f && footMoved < 0.005f,
                 qPrintable(QString("%1 %2").arg(hipsHi - hipsLo).arg(footMoved)));
    }

    // Leg IK puts the ankle on a target the leg reaches (within 1 mm), bends the knee
    // forward as it bent, keeps the foot's orientation and moves no other joint; a
    // target out of reach gets the leg pointing at it.
    void legIkReachesTargetsAndKeepsTheSole()
    {
        const Character man = builtin("man");
        QCOMPARE(man.legs.size(), std::size_t(2));
        const Pose idle = sampleClip(man.idle, 0.0);
        const std::vector<glm::mat4> before = jointGlobalTransforms(man, idle);
        const Leg& leg = man.legs[0];
        QVERIFY(glm::distance(leg.plantedAnkle, glm::vec3(before[leg.foot][3])) < 1e-5f);
        for (const glm::vec3 shift :
             {glm::vec3(0.1f, 0.15f, 0.0f), glm::vec3(-0.05f, 0.3f, 0.05f), glm::vec3(0.2f, 0.05f, -0.05f)}) {
            Pose pose = idle;
            const glm::vec3 target = leg.plantedAnkle + shift;
            reachWithLeg(man, leg, target, pose);
            const std::vector<glm::mat4> after = jointGlobalTransforms(man, pose);
            QVERIFY(glm::distance(glm::vec3(after[leg.foot][3]), target) < 0.001f);
            QVERIFY(after[leg.lower][3].x > after[leg.upper][3].x - 0.01f);  // the knee ahead of the hip
            const glm::mat3 footBefore(before[leg.foot]), footAfter(after[leg.foot]);
            for (int k = 0; k < 3; ++k)
                QVERIFY(glm::distance(footBefore[k], footAfter[k]) < 1e-4f);
            for (std::size_t j = 0; j < man.joints.size(); ++j)
                if (int(j) != leg.upper && int(j) != leg.lower && int(j) != leg.foot)
                    QCOMPARE(pose.rotations[j], idle.rotations[j]);
        }
        Pose stretched = idle;
        const glm::vec3 hip(before[leg.upper][3]);
        reachWithLeg(man, leg, hip + glm::vec3(0.0f, -3.0f, 0.0f), stretched);
        const std::vector<glm::mat4> after = jointGlobalTransforms(man, stretched);
        const glm::vec3 ankle(after[leg.foot][3]);
        QVERIFY(std::abs(ankle.x - hip.x) < 0.01f && std::abs(ankle.z - hip.z) < 0.01f);
        QVERIFY(hip.y - ankle.y > 0.85f);  // thigh and shin all but straight
    }

    // One wheel turn per 2 pi r of road, forward: after a quarter of it the point that was
    // on top of the wheel is at its front.
    void carWheelsRoll()
    {
        const Character car = builtin("car");
        const float r = car.joints[0].restTranslation.y;  // the body sits at axle height
        QVERIFY(std::abs(car.walk.strideM - 2.0f * 3.14159265f * r) < 1e-4f);
        const Pose quarter = sampleClip(car.walk, 0.25);
        const glm::vec3 top = glm::mat4_cast(quarter.rotations[1]) * glm::vec4(0.0f, r, 0.0f, 0.0f);
        QVERIFY2(std::abs(top.x - r) < 1e-3f && std::abs(top.y) < 1e-3f, qPrintable(QString("%1 %2").arg(top.x).arg(top.y)));
        const glm::quat full = sampleClip(car.walk, 3.0).rotations[2];
        QVERIFY(std::abs(std::abs(glm::dot(full, glm::quat(1.0f, 0.0f, 0.0f, 0.0f))) - 1.0f) < 1e-4f);
    }

    // Flapping wingtips sweep up and down by decimetres; gliding ones hold still.
    void birdFlapsAndGlides()
    {
        const Character bird = builtin("bird");
        const int tip = jointNamed(bird, "wingtip_l");
        auto sweep = [&](const CycleClip& clip) {
            float lo = 1e9f, hi = -1e9f;
            for (double p = 0.0; p < 1.0; p += 0.05) {
                const float y = jointWorld(bird, sampleClip(clip, p), tip, {}, 1.0f).y;
                lo = std::min(lo, y);
                hi = std::max(hi, y);
            }
            return hi - lo;
        };
        QVERIFY(sweep(bird.walk) > 0.15f);
        QCOMPARE(sweep(bird.run), 0.0f);
        std::vector<glm::vec3> line{{0.0f, 5.0f, 0.0f}, {1.0f, 5.0f, 0.0f}};
        QCOMPARE(computeGait(bird, line, std::vector<float>(2, 7.0f), AgentVariation{})[1].runWeight, 1.0f);
        QCOMPARE(computeGait(bird, line, std::vector<float>(2, 3.0f), AgentVariation{})[1].runWeight, 0.0f);
        // A smooth bird, no box: no point of it has two normals, and the wingtips reach
        // out 34 cm, the wing's tip skinned to the wingtip joint.
        const std::vector<std::uint32_t> welded = weldedIndices(bird.mesh);
        std::uint32_t outermost = 0;
        for (std::uint32_t v = 0; v < bird.mesh.positions.size(); ++v) {
            QVERIFY(bird.mesh.normals[v] == bird.mesh.normals[welded[v]]);
            if (bird.mesh.positions[v].z < bird.mesh.positions[outermost].z)
                outermost = v;
        }
        const float tipZ = bird.mesh.positions[outermost].z;
        QVERIFY2(tipZ < -0.33f, qPrintable(QString::number(tipZ)));
        QCOMPARE(int(bird.mesh.joints[outermost][0]), tip);
        QCOMPARE(bird.mesh.weights[outermost][0], 1.0f);
    }
};

THRONG_REGISTER_TEST(TestCharacters)
#include "TestCharacters.moc"
