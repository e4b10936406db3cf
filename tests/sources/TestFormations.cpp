// Walkers that keep together (issue 26): a group's formation holds its members on their
// slots round the anchor while it walks — a column, a line abreast and a wedge, each
// checked from the positions against the documented layout (and failing without the
// formation) — the anchor walks at 0.9 of its slowest member's top speed, and a leader
// anchors the formation; companions walk in small groups of the drawn sizes, abreast in the
// open, one behind the other through a passage too narrow, and wait for each other; the
// same for any thread count and after a checkpoint, alike at 24 and 60 fps; a school of
// fliers holds its arrow on a straight course and near it through turns; the file keeps
// the keys and refuses what cannot be, with its line.
#include "TestRegistry.h"

#include "simcore/io/SceneIO.h"
#include "simcore/world/Formations.h"
#include "simcore/world/RunStats.h"
#include "simcore/world/World.h"
#include "simcore/world/WorldState.h"

#include <QTest>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

using namespace throng;
using namespace throng::sim;

namespace {

Scene parseFormation(const std::string& yaml)
{
    const LoadResult r = parseScene(yaml, "formation.yaml", "");
    if (!r.ok())
        qFatal("%s\n%s", r.diagnostics[0].format().c_str(), yaml.c_str());
    return r.scene;
}

// `count` walkers in [0, 6] x [-4, 4] bound for a goal 80 m east, with `keep` (a
// `formation:` or `companions:` entry, or nothing) and `extra` sections.
std::string walkersToFar(int count, const std::string& keep, double fps = 24, const std::string& extra = "",
                  const char* speed = "[1, 1]")
{
    std::ostringstream y;
    y << "throng: 1\nsettings: {fps: " << fps
      << ", seed: 6, duration: 120, bounds: {min: [-10, -30], max: [100, 30]}}\n"
      << "agent_types:\n  - {name: walker, radius: 0.25, max_speed: 1.3, variation: {speed: " << speed << "}}\n"
      << "goals:\n  - {name: far, position: [80, 0], radius: 2}\n"
      << "groups:\n  - {name: crowd, type: walker, count: " << count
      << ", rect: {min: [0, -4], max: [6, 4]}, goal: far" << (keep.empty() ? "" : ", " + keep) << "}\n"
      << extra;
    return y.str();
}

glm::vec2 groundOf(glm::vec3 p) { return {p.x, p.z}; }

// Positions of members in the anchor's frame (x right, z forward), its forward taken
// from how it moved over the last second.
std::vector<glm::vec2> localPositions(const World& w, std::size_t anchor, glm::vec2 anchorSecondAgo)
{
    const glm::vec2 a = groundOf(w.positions()[anchor]);
    const glm::vec2 fwd = glm::normalize(a - anchorSecondAgo), right(-fwd.y, fwd.x);
    std::vector<glm::vec2> out;
    for (std::size_t i = 0; i < w.agentCount(); ++i)
        if (i != anchor) {
            const glm::vec2 d = groundOf(w.positions()[i]) - a;
            out.push_back({glm::dot(d, right), glm::dot(d, fwd)});
        }
    return out;
}

// For each expected slot, the distance to the member nearest it, members matched once
// (greedy, slots in order): the formation's error slot by slot.
std::vector<float> slotErrors(std::vector<glm::vec2> members, const std::vector<glm::vec2>& expected)
{
    std::vector<float> errors;
    for (const glm::vec2& s : expected) {
        auto best = std::min_element(members.begin(), members.end(), [&](glm::vec2 p, glm::vec2 q) {
            return glm::length(p - s) < glm::length(q - s);
        });
        errors.push_back(glm::length(*best - s));
        members.erase(best);
    }
    return errors;
}

struct HeldShape {
    float medianM = 0.0f, worstM = 0.0f;  // over the samples from 20 s to 50 s
    std::size_t anchor = 0;
    double anchorSpeed = 0.0;  // m/s over that time
};

// Walks `yaml` (one group) to 50 s; the anchor is the walker that started nearest the goal.
HeldShape holdShape(const std::string& yaml, const std::vector<glm::vec2>& expected)
{
    World w(parseFormation(yaml));
    HeldShape h;
    float nearest = 1e9f;
    for (std::size_t i = 0; i < w.agentCount(); ++i)
        if (const float d = glm::length(groundOf(w.positions()[i]) - glm::vec2(80, 0)); d < nearest) {
            nearest = d;
            h.anchor = i;
        }
    std::vector<float> errors;
    glm::vec2 secondAgo(0.0f), at20(0.0f);
    while (w.timeS() < 50.0 - 1e-9) {
        const int step = int(std::lround(w.timeS() * 24.0));
        if (step % 24 == 0)
            secondAgo = groundOf(w.positions()[h.anchor]);
        w.step();
        const int now = int(std::lround(w.timeS() * 24.0));
        if (now == 20 * 24)
            at20 = groundOf(w.positions()[h.anchor]);
        if (now >= 20 * 24 && now % 24 == 12) {
            const std::vector<float> e = slotErrors(localPositions(w, h.anchor, secondAgo), expected);
            errors.insert(errors.end(), e.begin(), e.end());
        }
    }
    std::sort(errors.begin(), errors.end());
    h.medianM = errors[errors.size() / 2];
    h.worstM = errors.back();
    h.anchorSpeed = glm::length(groundOf(w.positions()[h.anchor]) - at20) / 30.0;
    qInfo("slot error median %.3f m, worst %.3f m; anchor %.3f m/s", double(h.medianM), double(h.worstM),
          h.anchorSpeed);
    return h;
}

bool sameSlots(const std::vector<glm::vec2>& a, const std::vector<glm::vec2>& b)
{
    if (a.size() != b.size())
        return false;
    for (std::size_t k = 0; k < a.size(); ++k)
        if (glm::length(a[k] - b[k]) > 1e-5f)
            return false;
    return true;
}

std::vector<glm::vec2> slotList(std::initializer_list<std::pair<float, float>> xs)
{
    std::vector<glm::vec2> out;
    for (auto [x, z] : xs)
        out.push_back({x, z});
    return out;
}

// Nine fish (fliers) in a wedge 2 m apart, starting round `centre` 28 to 32 m up, behind
// a leader placed at `leader` (position and heading) that flies `path` (named course) 30 m
// up at 6 m/s.
std::string schoolScene(const char* leader, const char* centre, const char* bounds, const char* path)
{
    std::ostringstream y;
    y << "throng: 1\nsettings: {fps: 24, seed: 5, duration: 80, bounds: " << bounds << "}\n"
      << "agent_types:\n"
         "  - {name: lead, kind: flier, radius: 0.3, max_speed: 6, min_speed: 4, max_force: 20,\n"
         "     variation: {speed: [1, 1]}, behaviours: {path_following: {weight: 1, ahead: 10}}}\n"
         "  - {name: fish, kind: flier, radius: 0.3, max_speed: 9, min_speed: 3, max_force: 30, perception: 3,\n"
         "     variation: {speed: [1, 1]}, behaviours: {separation: 1}}\n"
      << "agents:\n  - {id: 1, type: lead, position: " << leader << ", path: course}\n"
      << "groups:\n  - {name: school, type: fish, count: 9, circle: {center: " << centre
      << ", radius: 4}, altitude: [28, 32], leader: 1, formation: {shape: wedge, spacing: 2}}\n"
      << "paths:\n" << path;
    return y.str();
}

// Flies the school (agent 0 its leader) to untilS; from 20 s on, every `everyFrames` frame,
// each fish's distance from its wedge slot in the leader's frame (its forward from how it
// moved over the step, its right level), sorted; `offPlane` gets how far any fish stood
// above or below the leader's plane.
std::vector<float> schoolSlotErrors(World& w, double untilS, int everyFrames, float& offPlane)
{
    const std::vector<glm::vec2> arrow = Formations::layout({FormationShape::Wedge, 2.0f, 2}, 9);
    std::vector<float> errors;
    offPlane = 0.0f;
    while (w.timeS() < untilS) {
        const glm::vec3 before = w.positions()[0];
        w.step();
        if (w.timeS() < 20.0 || std::lround(w.timeS() * 24.0) % everyFrames != 0)
            continue;
        const glm::vec3 fwd = glm::normalize(w.positions()[0] - before);
        const glm::vec3 right = glm::normalize(glm::cross(fwd, glm::vec3(0, 1, 0))), up = glm::cross(right, fwd);
        std::vector<glm::vec2> local;
        for (std::size_t i = 1; i < w.agentCount(); ++i) {
            const glm::vec3 d = w.positions()[i] - w.positions()[0];
            local.push_back({glm::dot(d, right), glm::dot(d, fwd)});
            offPlane = std::max(offPlane, std::abs(glm::dot(d, up)));
        }
        const std::vector<float> e = slotErrors(local, arrow);
        errors.insert(errors.end(), e.begin(), e.end());
    }
    std::sort(errors.begin(), errors.end());
    return errors;
}

}  // namespace

class TestFormations : public QObject {
    Q_OBJECT

private slots:
    void aColumnHoldsItsRowsWhileItWalks()
    {
        // 13 walkers: the anchor and four rows of three, 1.2 m apart, behind it.
        const auto expected =
            slotList({{-1.2f, -1.2f}, {0, -1.2f}, {1.2f, -1.2f}, {-1.2f, -2.4f}, {0, -2.4f}, {1.2f, -2.4f},
                      {-1.2f, -3.6f}, {0, -3.6f}, {1.2f, -3.6f}, {-1.2f, -4.8f}, {0, -4.8f}, {1.2f, -4.8f}});
        QVERIFY(sameSlots(Formations::layout({FormationShape::Column, 1.2f, 3}, 12), expected));
        const HeldShape held =
            holdShape(walkersToFar(13, "formation: {shape: column, spacing: 1.2, width: 3}"), expected);
        QVERIFY2(held.medianM < 0.15f && held.worstM < 0.5f,
                 qPrintable(QString("median %1 m, worst %2 m").arg(held.medianM).arg(held.worstM)));
        // The anchor walks at 0.9 of its members' top speed (1.3 m/s), so they can close up.
        QVERIFY2(std::abs(held.anchorSpeed - 0.9 * 1.3) < 0.05, qPrintable(QString::number(held.anchorSpeed)));
        // Without the formation the same walkers hold no such shape.
        const HeldShape loose = holdShape(walkersToFar(13, ""), expected);
        QVERIFY2(loose.worstM > 2.0f, qPrintable(QString::number(loose.worstM)));
    }

    void aLineAndAWedgeHoldTheirShapes()
    {
        const auto line = slotList({{1, 0}, {-1, 0}, {2, 0}, {-2, 0}, {3, 0}, {-3, 0}});
        QVERIFY(sameSlots(Formations::layout({FormationShape::Line, 1.0f, 2}, 6), line));
        const HeldShape abreast = holdShape(walkersToFar(7, "formation: {shape: line, spacing: 1}"), line);
        QVERIFY2(abreast.medianM < 0.15f && abreast.worstM < 0.5f,
                 qPrintable(QString("median %1 m, worst %2 m").arg(abreast.medianM).arg(abreast.worstM)));
        // An arrow: rows of 2, 3 and 4 behind the tip, an equilateral triangle's height apart.
        const float h = 1.5f * 0.8660254f;
        const auto wedge = slotList({{-0.75f, -h}, {0.75f, -h}, {-1.5f, -2 * h}, {0, -2 * h}, {1.5f, -2 * h},
                                 {-2.25f, -3 * h}, {-0.75f, -3 * h}, {0.75f, -3 * h}, {2.25f, -3 * h}});
        QVERIFY(sameSlots(Formations::layout({FormationShape::Wedge, 1.5f, 2}, 9), wedge));
        const HeldShape arrow = holdShape(walkersToFar(10, "formation: {shape: wedge, spacing: 1.5}"), wedge);
        QVERIFY2(arrow.medianM < 0.15f && arrow.worstM < 0.5f,
                 qPrintable(QString("median %1 m, worst %2 m").arg(arrow.medianM).arg(arrow.worstM)));
    }

    void aLeaderAnchorsTheFormation()
    {
        // A placed walker leads; the twelve of the group form a column behind it.
        const std::string yaml =
            walkersToFar(12, "leader: 500, formation: {shape: column, spacing: 1, width: 2}", 24,
                  "agents:\n  - {id: 500, type: walker, position: [-2, 0, 0], goal: far}\n");
        World w(parseFormation(yaml));
        const std::size_t leader = 0;  // placed agents come first
        for (std::size_t i = 1; i < w.agentCount(); ++i)
            QCOMPARE(w.formationAnchor(i), std::int32_t(leader));
        QCOMPARE(w.formationAnchor(leader), -1);
        while (w.timeS() < 40.0)
            w.step();
        // Everyone is behind the leader, at most six rows back, as a column of two.
        const glm::vec2 front = groundOf(w.positions()[leader]);
        for (std::size_t i = 1; i < w.agentCount(); ++i) {
            const glm::vec2 p = groundOf(w.positions()[i]);
            QVERIFY2(p.x < front.x - 0.5f && p.x > front.x - 6.6f && std::abs(p.y - front.y) < 1.0f,
                     qPrintable(QString("%1: (%2, %3) behind (%4, %5)")
                                    .arg(i).arg(p.x).arg(p.y).arg(front.x).arg(front.y)));
        }
    }

    void aSchoolFliesAsAnArrow()
    {
        // Finding Nemo's arrow: the school behind a leader that flies a straight course.
        World w(parseFormation(schoolScene("[0, 30, 0], heading: 0", "[-8, 0]", "{min: [-50, -100], max: [400, 100]}",
                                           "  - {name: course, points: [[0, 0], [1000, 0]], radius: 3}\n")));
        for (std::size_t i = 1; i < w.agentCount(); ++i)
            QCOMPARE(w.formationAnchor(i), 0);
        float offPlane = 0.0f;
        const std::vector<float> errors = schoolSlotErrors(w, 40.0, 24, offPlane);
        QVERIFY(errors.size() >= 9 * 20);
        qInfo("arrow slot error median %.3f m, worst %.3f m; %.3f m off the leader's plane",
              double(errors[errors.size() / 2]), double(errors.back()), double(offPlane));
        QVERIFY2(offPlane < 0.5f, "in the leader's plane");
        QVERIFY2(errors[errors.size() / 2] < 0.2f && errors.back() < 0.6f,
                 qPrintable(QString("median %1, worst %2").arg(errors[errors.size() / 2]).arg(errors.back())));
    }

    void aSchoolHoldsItsArrowThroughTurns()
    {
        // The same school behind a leader flying a circuit 60 m across (12 legs): in the turns
        // the slots swing with the leader's heading, and the school follows them.
        World w(parseFormation(
            schoolScene("[30, 30, 0], heading: 270", "[30, -8]", "{min: [-100, -100], max: [100, 100]}",
                        "  - name: course\n    closed: true\n    radius: 3\n"
                        "    points: [[30, 0], [26, 15], [15, 26], [0, 30], [-15, 26], [-26, 15], [-30, 0], "
                        "[-26, -15], [-15, -26], [0, -30], [15, -26], [26, -15]]\n")));
        float offPlane = 0.0f;
        const std::vector<float> errors = schoolSlotErrors(w, 80.0, 12, offPlane);
        qInfo("arrow in turns: slot error median %.3f m, 95th %.3f m, worst %.3f m",
              double(errors[errors.size() / 2]), double(errors[errors.size() * 95 / 100]), double(errors.back()));
        QVERIFY2(errors[errors.size() / 2] < 0.5f && errors[errors.size() * 95 / 100] < 1.5f,
                 qPrintable(QString("median %1, worst %2").arg(errors[errors.size() / 2]).arg(errors.back())));
    }

    void companionsWalkAbreastInSmallGroups()
    {
        World w(parseFormation(walkersToFar(60, "companions: [2, 3]")));
        // The small groups: every walker keeps to an anchor or is one, in groups of 2 or 3
        // (the last may be smaller), the anchor one of its own group.
        std::map<std::int32_t, int> sizes;
        for (std::size_t i = 0; i < w.agentCount(); ++i) {
            const std::int32_t a = w.formationAnchor(i);
            ++sizes[a < 0 ? std::int32_t(i) : a];
            if (a >= 0)
                QCOMPARE(w.formationAnchor(std::size_t(a)), -1);
        }
        int counted = 0, small = 0;
        for (const auto& [anchor, size] : sizes) {
            counted += size;
            small += size < 2 ? 1 : 0;
            QVERIFY2(size <= 3, qPrintable(QString::number(size)));
        }
        QCOMPARE(counted, 60);
        QVERIFY(small <= 1);
        QVERIFY(sizes.size() >= 20 && sizes.size() <= 30);
        // From 15 s on, in the open: each companion beside its anchor (within 0.6 m of level
        // with it) at least 80 % of the time, and never more than 3 m from it.
        int level = 0, samples = 0;
        float farthest = 0.0f;
        std::vector<glm::vec2> before(w.agentCount());
        while (w.timeS() < 45.0) {
            for (std::size_t i = 0; i < w.agentCount(); ++i)
                before[i] = groundOf(w.positions()[i]);
            w.step();
            if (w.timeS() < 15.0)
                continue;
            for (std::size_t i = 0; i < w.agentCount(); ++i) {
                const std::int32_t a = w.formationAnchor(i);
                if (a < 0)
                    continue;
                const glm::vec2 ap = groundOf(w.positions()[std::size_t(a)]);
                const glm::vec2 d = groundOf(w.positions()[i]) - ap, move = ap - before[std::size_t(a)];
                if (glm::length(move) < 1e-4f)
                    continue;
                const glm::vec2 fwd = glm::normalize(move);
                level += std::abs(glm::dot(d, fwd)) < 0.6f ? 1 : 0;
                ++samples;
                farthest = std::max(farthest, glm::length(d));
            }
        }
        QVERIFY(samples > 1000);
        qInfo("level with their anchors %d of %d samples; farthest %.2f m", level, samples, double(farthest));
        QVERIFY2(level > 0.8 * samples, qPrintable(QString("%1 of %2 level").arg(level).arg(samples)));
        QVERIFY2(farthest < 3.0f, qPrintable(QString::number(farthest)));
    }

    void companionsGoOneBehindTheOtherWhereThereIsNoRoom()
    {
        // Three pairs pass a gap 1 m wide in a wall across the way at x = 30: abreast
        // (0.8 m apart, each body 0.5 m across) they would not fit.
        const std::string walls =
            "walls:\n  - {points: [[30, -30], [30, -0.5]]}\n  - {points: [[30, 0.5], [30, 30]]}\n";
        // They navigate by a flow field, as walkers among walls do.
        std::string yaml = walkersToFar(6, "companions: [2, 2]", 24, walls);
        yaml.replace(yaml.find("max_speed: 1.3"), 14, "max_speed: 1.3, navigation: flow_field");
        // A navigation grid fine enough to see the gap open (at the default cell it is closed).
        yaml.replace(yaml.find("bounds:"), 7, "nav_cell: 0.1, bounds:");
        World w(parseFormation(yaml));
        int inGap = 0, behind = 0, after = 0, abreast = 0;
        std::uint64_t through = 0;
        std::vector<glm::vec2> before(w.agentCount());
        while (w.timeS() < 70.0) {
            for (std::size_t i = 0; i < w.agentCount(); ++i)
                before[i] = groundOf(w.positions()[i]);
            w.step();
            for (std::size_t i = 0; i < w.agentCount(); ++i) {
                const glm::vec2 p = groundOf(w.positions()[i]);
                if (before[i].x < 30.0f && p.x >= 30.0f) {
                    ++through;
                    QVERIFY2(std::abs(p.y) < 0.5f, "through the gap, not the wall");
                }
                const std::int32_t a = w.formationAnchor(i);
                if (a < 0)
                    continue;
                const glm::vec2 ap = groundOf(w.positions()[std::size_t(a)]);
                if (ap.x > 29.8f && ap.x < 30.3f && std::abs(ap.y) < 0.5f) {
                    // The anchor in the gap: its companion behind it, not in the gap beside it.
                    ++inGap;
                    const bool besideInGap = p.x > 29.6f && p.x < 30.4f && std::abs(p.y) < 0.5f;
                    behind += p.x < ap.x - 0.2f && !besideInGap ? 1 : 0;
                } else if (ap.x > 45.0f && ap.x < 60.0f) {
                    // Well past it, in the open again: side by side.
                    ++after;
                    abreast += std::abs(p.x - ap.x) < 0.6f && std::abs(p.y - ap.y) > 0.5f ? 1 : 0;
                }
            }
        }
        QCOMPARE(through, std::uint64_t(6));
        QCOMPARE(w.counters().wallPenetrations, std::uint64_t(0));
        QVERIFY(inGap >= 3);
        qInfo("behind in the gap %d of %d; abreast after it %d of %d", behind, inGap, abreast, after);
        QVERIFY2(behind == inGap, qPrintable(QString("%1 of %2 behind").arg(behind).arg(inGap)));
        QVERIFY(after > 100);
        QVERIFY2(abreast > 0.9 * after, qPrintable(QString("%1 of %2 abreast").arg(abreast).arg(after)));
    }

    void companionsWaitForEachOther()
    {
        // Walkers of very different speeds (0.4 to 1 of 1.3 m/s): each small group keeps
        // within a few metres over 60 m; on their own the fast would be 20 m ahead.
        World w(parseFormation(walkersToFar(30, "companions: [2, 2]", 24, "", "[0.4, 1]")));
        float farthest = 0.0f;
        while (w.timeS() < 70.0) {
            w.step();
            for (std::size_t i = 0; i < w.agentCount(); ++i)
                if (const std::int32_t a = w.formationAnchor(i); a >= 0 && w.timeS() > 5.0)
                    farthest = std::max(farthest, glm::length(groundOf(w.positions()[i]) -
                                                              groundOf(w.positions()[std::size_t(a)])));
        }
        QVERIFY2(farthest < 3.5f, qPrintable(QString::number(farthest)));
        qInfo("companions of speeds 0.4 to 1: farthest %.2f m apart", double(farthest));
        World alone(parseFormation(walkersToFar(30, "", 24, "", "[0.4, 1]")));
        float spread = 0.0f;
        while (alone.timeS() < 50.0)
            alone.step();
        float lo = 1e9f, hi = -1e9f;
        for (std::size_t i = 0; i < alone.agentCount(); ++i) {
            lo = std::min(lo, alone.positions()[i].x);
            hi = std::max(hi, alone.positions()[i].x);
        }
        spread = hi - lo;
        QVERIFY2(spread > 15.0f, qPrintable(QString::number(spread)));
        qInfo("alone: spread over %.1f m after 50 s", double(spread));
    }

    void threadsCheckpointsAndFrameRatesAgree()
    {
        // 2,400 walkers in pairs and threes: one and two threads step them alike.
        std::ostringstream y;
        y << "throng: 1\nsettings: {fps: 24, seed: 9, duration: 60, bounds: {min: [-10, -60], max: [120, 60]}}\n"
             "agent_types:\n  - {name: walker, radius: 0.25, max_speed: 1.3}\n"
             "goals:\n  - {name: far, position: [110, 0], radius: 10}\n"
             "groups:\n  - {name: crowd, type: walker, count: 2400, rect: {min: [0, -50], max: [40, 50]}, goal: far, "
             "companions: [2, 3]}\n";
        const Scene s = parseFormation(y.str());
        World one(s, WorldOptions{0, false, 1}), two(s, WorldOptions{0, false, 2});
        for (int k = 0; k < 5 * 24; ++k) {
            one.step();
            two.step();
        }
        for (const std::uint64_t chunks : two.team().chunksRun())
            QVERIFY2(chunks > 0, "a thread ran no chunk");
        for (std::size_t i = 0; i < one.agentCount(); ++i)
            QCOMPARE(two.positions()[i], one.positions()[i]);
        const WorldState at5 = one.saveState();
        for (int k = 0; k < 3 * 24; ++k)
            one.step();
        World resumed(s);
        resumed.restoreState(at5);
        for (int k = 0; k < 3 * 24; ++k)
            resumed.step();
        for (std::size_t i = 0; i < one.agentCount(); ++i)
            QCOMPARE(resumed.positions()[i], one.positions()[i]);

        // The column at 60 fps holds its shape as at 24.
        const auto expected = Formations::layout({FormationShape::Column, 1.2f, 3}, 12);
        World at60(parseFormation(walkersToFar(13, "formation: {shape: column, spacing: 1.2, width: 3}", 60)));
        while (at60.timeS() < 40.0)
            at60.step();
        World at24(parseFormation(walkersToFar(13, "formation: {shape: column, spacing: 1.2, width: 3}", 24)));
        while (at24.timeS() < 40.0)
            at24.step();
        std::size_t anchor = 0;
        for (std::size_t i = 0; i < at24.agentCount(); ++i)
            if (at24.formationAnchor(i) >= 0)
                anchor = std::size_t(at24.formationAnchor(i));
        QCOMPARE(at60.formationAnchor(anchor == 0 ? 1 : 0), std::int32_t(anchor));
        const float gap = std::abs(at60.positions()[anchor].x - at24.positions()[anchor].x);
        QVERIFY2(gap < 0.5f, qPrintable(QString::number(gap)));
    }

    void theFileKeepsFormationsAndRefusesWhatCannotBe()
    {
        const Scene column = parseFormation(walkersToFar(13, "formation: {shape: column, spacing: 1.2, width: 3}"));
        QCOMPARE(column.groups[0].formation, (GroupFormation{FormationShape::Column, 1.2f, 3}));
        QVERIFY(parseFormation(sceneToYaml(column)) == column);
        const Scene pairs = parseFormation(walkersToFar(10, "companions: [2, 4]"));
        QCOMPARE(pairs.groups[0].companions, glm::uvec2(2, 4));
        QVERIFY(parseFormation(sceneToYaml(pairs)) == pairs);
        const Scene wedge = parseFormation(walkersToFar(10, "formation: {shape: wedge}"));
        QCOMPARE(wedge.groups[0].formation.spacingM, 1.0f);
        QVERIFY(parseFormation(sceneToYaml(wedge)) == wedge);

        const std::pair<const char*, const char*> bad[] = {
            {"formation: {shape: circle}", "'line', 'column' or 'wedge'"},
            {"formation: {shape: line, spacing: 0.3}", "closer than two"},
            {"formation: {shape: column, width: 0}", "at least 1"},
            {"formation: {shape: line}, companions: [2, 3]", "not both"},
            {"companions: [3, 2]", "1 <= min <= max"},
            {"companions: [1, 9]", "2 <= max <= 8"},
            {"companions: [2.5, 3]", "whole numbers"},
        };
        const std::string placed = "agents:\n  - {id: 500, type: walker, position: [-2, 0, 0]}\n";
        for (const auto& [keep, words] : bad) {
            const LoadResult r = parseScene(walkersToFar(10, keep, 24, placed), "bad.yaml", "");
            QVERIFY2(!r.ok(), keep);
            bool found = false;
            for (const Diagnostic& d : r.diagnostics)
                found = found || (d.format().find(words) != std::string::npos &&
                                  d.format().find("bad.yaml:8") != std::string::npos);
            QVERIFY2(found, (std::string(keep) + ": " + r.diagnostics[0].format()).c_str());
        }
        // Companions with a leader load, with a warning: they follow it once their own arrived.
        const LoadResult led =
            parseScene(walkersToFar(10, "companions: [2, 3], leader: 500", 24, placed), "led.yaml", "");
        QVERIFY(led.ok());
        QVERIFY(!led.diagnostics.empty() && led.diagnostics[0].format().find("warning") != std::string::npos);
        // Fliers fly in formation, but do not walk as companions; exit choosers do neither.
        std::string flier = walkersToFar(10, "companions: [2, 3]");
        flier.replace(flier.find("max_speed: 1.3"), 14, "max_speed: 1.3, kind: flier");
        const LoadResult f = parseScene(flier, "flier.yaml", "");
        QVERIFY(!f.ok());
        QVERIFY(f.diagnostics[0].format().find("only walkers walk as companions") != std::string::npos);
        std::string exits = walkersToFar(10, "formation: {shape: line}");
        exits.replace(exits.find("goals:\n"), 7, "goals:\n  - {name: e1, position: [90, 5], radius: 1, exit: true}\n"
                                                 "  - {name: e2, position: [90, -5], radius: 1, exit: true}\n");
        exits.replace(exits.find("goal: far,"), 10, "exits: [e1, e2],");
        const LoadResult e = parseScene(exits, "exits.yaml", "");
        QVERIFY(!e.ok());
        QVERIFY2(e.diagnostics[0].format().find("not exits") != std::string::npos, e.diagnostics[0].format().c_str());
    }
};

THRONG_REGISTER_TEST(TestFormations)
#include "TestFormations.moc"
