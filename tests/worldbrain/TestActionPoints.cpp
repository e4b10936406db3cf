// Action points (Scene.h, ActionPoint): a walker that reaches one stops, turns as it says,
// plays its action for its duration on every frame of the run and goes on to its goal; at
// any frame rate; by the point's chance and types; once per visit; without piling up a
// crowd behind it; identically on 1 and 2 threads and from a checkpoint; and a brain
// senses the points. Everything is read back from the frames a user would see.
#include "TestRegistry.h"

#include "simcore/brain/BrainEvaluator.h"
#include "simcore/io/SceneIO.h"
#include "simcore/world/World.h"
#include "simcore/world/WorldBrain.h"
#include "simcore/world/WorldState.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <QTest>

#include <cmath>
#include <cstring>
#include <numbers>

using namespace throng::sim;

namespace {

Scene load(const std::string& yaml)
{
    const LoadResult r = parseScene(yaml, "scene.yaml", "");
    if (!r.ok())
        qFatal("%s", r.diagnostics[0].format().c_str());
    for (const Diagnostic& d : checkSceneBrains(r.scene))
        qFatal("%s", d.format().c_str());
    return r.scene;
}

const Diagnostic* find(const LoadResult& r, const std::string& key)
{
    for (const Diagnostic& d : r.diagnostics)
        if (d.key == key)
            return &d;
    return nullptr;
}

// One walker from (-10, 0) east to a goal at (12, 0), past a shop window at the origin:
// it looks around for 3 s there, facing north (90 degrees: -z).
std::string window(float fps, const std::string& extra = "")
{
    return "throng: 1\nsettings: {fps: " + std::to_string(fps) +
           ", seed: 3, bounds: {min: [-20, -20], max: [20, 20]}}\n"
           "agent_types:\n"
           "  - {name: walker, max_speed: 1.4, variation: {speed: [1, 1]}}\n"
           "goals: [{name: end, position: [12, 0], radius: 0.5}]\n"
           "action_points:\n"
           "  - {name: shop, position: [0, 0], radius: 1, action: look_around, duration: 3, facing: 90" +
           extra +
           "}\n"
           "agents:\n"
           "  - {id: 1, type: walker, position: [-10, 0, 0], heading: 0, goal: end}\n";
}

// What the frames of one agent show: the frames it plays `clip` on, and where and how.
struct Visit {
    int first = -1, last = -1;  // frames of the first run of the clip (-1: never)
    int runs = 0;               // separate runs of the clip
    float moved = 0.0f;         // m, the farthest it moved from where the first run began
    float endHeadingDeg = 0.0f; // on the run's last frame
    glm::vec3 at{0.0f};         // where the first run began
    float arrivedS = -1.0f;     // the first frame it is arrived on, s
    Clip after = Clip::Idle;    // the clip a second after the first run
};

Visit watch(const Scene& s, std::size_t agent, Clip clip, float seconds, int threads = 1)
{
    World world(s, {0, false, threads});
    Visit v;
    std::vector<AgentFrame> frames;
    bool in = false;
    int afterFrame = -1;
    const float fps = s.settings.fps;
    for (int f = 0; f <= int(seconds * fps); ++f) {
        if (f > 0)
            world.step();
        world.snapshot(frames);
        const AgentFrame& a = frames[agent];
        if (a.clip == clip && !in) {
            ++v.runs;
            if (v.first < 0) {
                v.first = f;
                v.at = a.position;
            }
        }
        if (a.clip == clip && v.runs == 1) {
            v.last = f;
            v.moved = std::max(v.moved, glm::distance(a.position, v.at));
            v.endHeadingDeg = glm::degrees(a.headingRad);
            afterFrame = f + int(fps);
        }
        if (f == afterFrame)
            v.after = a.clip;
        in = a.clip == clip;
        if (a.arrived && v.arrivedS < 0.0f)
            v.arrivedS = float(f) / fps;
    }
    return v;
}

std::uint64_t hashRun(const Scene& s, int threads, int steps, bool* everyThreadWorked = nullptr)
{
    World world(s, {0, false, threads});
    std::uint64_t h = 1469598103934665603ull;
    std::vector<AgentFrame> frames;
    for (int k = 0; k < steps; ++k) {
        world.step();
        world.snapshot(frames);
        for (const AgentFrame& f : frames) {
            std::uint32_t bits[5];
            std::memcpy(bits, &f.position, 12);
            std::memcpy(&bits[3], &f.headingRad, 4);
            bits[4] = std::uint32_t(f.clip);
            for (std::uint32_t b : bits)
                h = (h ^ b) * 1099511628211ull;
        }
    }
    if (everyThreadWorked) {
        *everyThreadWorked = true;
        for (std::uint64_t chunks : world.team().chunksRun())
            *everyThreadWorked = *everyThreadWorked && chunks > 0;
    }
    return h;
}

// `count` walkers in rows of three walking east through a point to a shared goal.
std::string column(int count, float chance, const std::string& types = "")
{
    std::string yaml = "throng: 1\nsettings: {fps: 24, seed: 17, bounds: {min: [-100, -20], max: [40, 20]}}\n"
                       "agent_types:\n"
                       "  - {name: walker, max_speed: 1.3, variation: {speed: [1, 1]}, "
                       "behaviours: {seek: 1, arrival: 1, separation: 1}}\n"
                       "  - {name: tourist, max_speed: 1.3, variation: {speed: [1, 1]}, "
                       "behaviours: {seek: 1, arrival: 1, separation: 1}}\n"
                       "goals: [{name: end, position: [30, 0], radius: 6}]\n"
                       "action_points:\n"
                       "  - {name: kiosk, position: [0, 0], radius: 2, action: phone, duration: 2, chance: " +
                       std::to_string(chance) + types + "}\nagents:\n";
    for (int k = 0; k < count; ++k)
        yaml += "  - {id: " + std::to_string(k + 1) + ", type: " + (k % 2 ? "tourist" : "walker") +
                ", position: [" + std::to_string(-5.0f - 1.2f * float(k / 3)) + ", 0, " +
                std::to_string(k % 3 == 0 ? 0.0f : (k % 3 == 1 ? 0.6f : -0.6f)) + "], heading: 0, goal: end}\n";
    return yaml;
}

}  // namespace

class TestActionPoints : public QObject {
    Q_OBJECT
private slots:
    void loadsSavesAndReportsWhatIsWrong()
    {
        const LoadResult a = parseScene(R"(throng: 1
agent_types: [{name: walker}, {name: shopper}]
action_points:
  - name: window
    position: [3, -2]
    radius: 1.5
    action: look_around
    duration: 6
    facing: -90
    chance: 0.25
    types: [shopper]
  - {name: bench, position: [0, 4], action: sit}
)", "a.yaml", "");
        QVERIFY2(a.ok(), a.ok() ? "" : a.diagnostics[0].format().c_str());
        QCOMPARE(a.scene.actionPoints.size(), std::size_t(2));
        const ActionPoint& w = a.scene.actionPoints[0];
        QCOMPARE(w.position, glm::vec2(3.0f, -2.0f));
        QCOMPARE(w.radiusM, 1.5f);
        QCOMPARE(QString::fromStdString(w.action), QString("look_around"));
        QCOMPARE(w.durationS, 6.0f);
        QVERIFY(w.faces);
        QCOMPARE(w.facingDeg, -90.0f);
        QCOMPARE(w.chance, 0.25f);
        QCOMPARE(w.types, std::vector<std::string>{"shopper"});
        // Defaults: 1 m, 4 s, the heading it came with, every time, every walker.
        const ActionPoint& b = a.scene.actionPoints[1];
        QCOMPARE(b.radiusM, 1.0f);
        QCOMPARE(b.durationS, 4.0f);
        QVERIFY(!b.faces);
        QCOMPARE(b.chance, 1.0f);
        QVERIFY(b.types.empty());

        const std::string text = sceneToYaml(a.scene);
        const LoadResult again = parseScene(text, "again.yaml", "");
        QVERIFY2(again.ok(), again.ok() ? "" : again.diagnostics[0].format().c_str());
        QVERIFY(again.scene == a.scene);
        QCOMPARE(sceneToYaml(again.scene), text);

        const LoadResult bad = parseScene(R"(throng: 1
agent_types: [{name: walker}]
action_points:
  - {name: p, position: [0, 0], action: walk}
  - {name: p, position: [1, 0], action: wave}
  - {name: q, position: [2, 0], action: dance}
  - {name: r, position: [3, 0], action: wave, chance: 1.5, duration: 0, radius: -1}
  - {name: s, action: wave, types: [walker, ghost]}
)", "bad.yaml", "");
        QVERIFY(!bad.ok());
        struct Expect {
            const char* key;
            int line;
            const char* says;
        };
        const Expect expected[] = {
            {"action_points[0].action", 4, "not an action"},
            {"action_points[1].name", 5, "'p'"},
            {"action_points[2].action", 6, "not an action"},
            {"action_points[3].chance", 7, ""},
            {"action_points[3].duration", 7, ""},
            {"action_points[3].radius", 7, ""},
            {"action_points[4].position", 8, ""},
            {"action_points[4].types[1]", 8, "ghost"},
        };
        for (const Expect& e : expected) {
            const Diagnostic* d = find(bad, e.key);
            QVERIFY2(d, e.key);
            QCOMPARE(d->line, e.line);
            QVERIFY2(d->message.find(e.says) != std::string::npos, d->message.c_str());
        }
        // The message names what would do.
        QVERIFY(find(bad, "action_points[0].action")->message.find("look_around") != std::string::npos);
    }

    void aWalkerStopsTurnsPlaysAndGoesOn()
    {
        const Scene s = load(window(30.0f));
        const Visit v = watch(s, 0, Clip::LookAround, 30.0f);
        QVERIFY2(v.first > 0, "it never looked around");
        QCOMPARE(v.runs, 1);
        // It stopped where it entered the disk: within the radius, on its way in (x < 0).
        QVERIFY2(glm::length(glm::vec2(v.at.x, v.at.z)) <= 1.0f + 1.4f / 30.0f, qPrintable(QString::number(v.at.x)));
        QVERIFY(v.at.x < 0.0f);
        // For 3 s (to within a frame), standing still.
        const float playedS = float(v.last - v.first + 1) / 30.0f;
        QVERIFY2(std::fabs(playedS - 3.0f) <= 1.0f / 30.0f + 1e-4f, qPrintable(QString::number(playedS)));
        QVERIFY2(v.moved < 1e-4f, qPrintable(QString::number(v.moved)));
        // Facing the window: turned from east to north.
        QVERIFY2(std::fabs(v.endHeadingDeg - 90.0f) < 0.5f, qPrintable(QString::number(v.endHeadingDeg)));
        // Then on to its goal, walking.
        QCOMPARE(v.after, Clip::Walk);
        QVERIFY2(v.arrivedS > float(v.last) / 30.0f, qPrintable(QString::number(v.arrivedS)));
        // Without the point it arrives 3 s and the turns sooner.
        Scene plain = s;
        plain.actionPoints.clear();
        const Visit p = watch(plain, 0, Clip::LookAround, 30.0f);
        QCOMPARE(p.runs, 0);
        QVERIFY(p.arrivedS > 0.0f);
        QVERIFY2(v.arrivedS - p.arrivedS >= 3.0f && v.arrivedS - p.arrivedS < 5.0f,
                 qPrintable(QString("%1 vs %2").arg(v.arrivedS).arg(p.arrivedS)));
    }

    void anyFrameRatePlaysTheSameVisit()
    {
        const Visit at30 = watch(load(window(30.0f)), 0, Clip::LookAround, 30.0f);
        for (const float fps : {12.0f, 24.0f, 25.0f, 60.0f}) {
            const Visit v = watch(load(window(fps)), 0, Clip::LookAround, 30.0f);
            const QString at = QString("%1 fps").arg(fps);
            QVERIFY2(v.runs == 1, qPrintable(at));
            const float startS = float(v.first) / fps, playedS = float(v.last - v.first + 1) / fps;
            // Entered within a frame (and a step of walking) of the 30 fps run; played 3 s.
            QVERIFY2(std::fabs(startS - float(at30.first) / 30.0f) <= 1.0f / fps + 1.0f / 30.0f + 0.05f,
                     qPrintable(at + QString(": starts %1 s").arg(startS)));
            QVERIFY2(std::fabs(playedS - 3.0f) <= 1.0f / fps + 1e-4f, qPrintable(at + QString(": %1 s").arg(playedS)));
            QVERIFY2(std::fabs(v.endHeadingDeg - 90.0f) < 0.5f, qPrintable(at));
            QVERIFY2(std::fabs(v.arrivedS - at30.arrivedS) < 0.25f,
                     qPrintable(at + QString(": arrives %1 s, %2 s at 30 fps").arg(v.arrivedS).arg(at30.arrivedS)));
        }
    }

    void withoutFacingItKeepsItsHeading()
    {
        std::string yaml = window(24.0f);
        yaml.replace(yaml.find(", facing: 90"), 12, "");
        const Visit v = watch(load(yaml), 0, Clip::LookAround, 20.0f);
        QCOMPARE(v.runs, 1);
        QVERIFY2(std::fabs(v.endHeadingDeg) < 3.0f, qPrintable(QString::number(v.endHeadingDeg)));
    }

    void chanceAndTypesChooseWhoStops()
    {
        // Per walker, from its frames: whether its centre came into the kiosk's disk
        // (2 m round the origin) and whether it played the kiosk's action.
        struct Walkers {
            std::vector<std::uint8_t> entered, stopped;
        };
        auto run = [](const Scene& s) {
            World world(s, {0, false, 1});
            std::vector<AgentFrame> frames;
            const std::size_t n = world.agentCount();
            Walkers w{std::vector<std::uint8_t>(n, 0), std::vector<std::uint8_t>(n, 0)};
            for (int f = 0; f < 24 * 150; ++f) {
                world.step();
                world.snapshot(frames);
                for (std::size_t i = 0; i < frames.size(); ++i) {
                    w.stopped[i] |= frames[i].clip == Clip::Phone;
                    w.entered[i] |= glm::length(glm::vec2(frames[i].position.x, frames[i].position.z)) < 2.0f;
                }
            }
            for (std::size_t i = 0; i < frames.size(); ++i)
                if (!world.hasArrived(i))
                    qFatal("walker %zu never reached the goal", i);
            return w;
        };
        auto count = [](const std::vector<std::uint8_t>& v) { return int(std::count(v.begin(), v.end(), 1)); };
        // Chance 1: every walker that came into the disk stopped there, and only those
        // (some go round those who stand there and never come in).
        const Walkers all = run(load(column(30, 1.0f)));
        QVERIFY2(count(all.entered) >= 20, qPrintable(QString::number(count(all.entered))));
        QVERIFY(all.stopped == all.entered);
        // Chance 0: nobody.
        const Walkers none = run(load(column(30, 0.0f)));
        QCOMPARE(count(none.stopped), 0);
        QCOMPARE(count(none.entered), 30);
        // Chance 0.5 for 120 walkers: about half of those that come in stop, and the same
        // ones on every run.
        const Scene half = load(column(120, 0.5f));
        const Walkers a = run(half);
        for (std::size_t i = 0; i < a.stopped.size(); ++i)
            QVERIFY(!a.stopped[i] || a.entered[i]);
        const float share = float(count(a.stopped)) / float(count(a.entered));
        QVERIFY2(share > 0.35f && share < 0.65f,
                 qPrintable(QString("%1 of %2").arg(count(a.stopped)).arg(count(a.entered))));
        QVERIFY(run(half).stopped == a.stopped);
        // Only tourists (the odd ones), though walkers come in too.
        const Walkers tourists = run(load(column(30, 1.0f, ", types: [tourist]")));
        int walkersIn = 0;
        for (std::size_t i = 0; i < tourists.stopped.size(); ++i) {
            QVERIFY2(tourists.stopped[i] == (i % 2 ? tourists.entered[i] : 0), qPrintable(QString::number(i)));
            walkersIn += i % 2 == 0 && tourists.entered[i];
        }
        QVERIFY(walkersIn >= 10);
    }

    void aCrowdPassesThoseWhoStopAndArrives()
    {
        // 30 walkers with one goal, each stopping 2 s on the way: nobody stops for good
        // behind one that plays (the pile at a goal must not take them for arrived).
        const Scene s = load(column(30, 1.0f));
        World world(s, {0, false, 1});
        float lastArrivalS = 0.0f;
        for (int f = 0; f < 24 * 150; ++f)
            world.step();
        for (std::size_t i = 0; i < world.agentCount(); ++i) {
            QVERIFY2(world.hasArrived(i), qPrintable(QString::number(i)));
            // At the goal's pile (within its 6 m and a few bodies), not held back at the point.
            QVERIFY2(world.positions()[i].x > 20.0f, qPrintable(QString::number(world.positions()[i].x)));
            lastArrivalS = std::max(lastArrivalS, world.arrivalTimeS(i));
        }
        QVERIFY(lastArrivalS > 0.0f);
    }

    void oncePerVisitOnALoop()
    {
        // A walker round a closed path 16 m long passes the point once a lap: it plays
        // there once per lap, not once for good and not again while still in the disk.
        const Scene s = load(R"(throng: 1
settings: {fps: 24, seed: 2, bounds: {min: [-20, -20], max: [20, 20]}}
agent_types:
  - {name: walker, max_speed: 1.4, variation: {speed: [1, 1]}, behaviours: {path_following: 1}}
paths:
  - {name: loop, points: [[-2, -2], [2, -2], [2, 2], [-2, 2]], closed: true, radius: 0.5}
action_points:
  - {name: corner, position: [2, 0], radius: 0.8, action: wave, duration: 1}
agents:
  - {id: 1, type: walker, position: [-2, 0, -2], heading: 0, path: loop}
)");
        const Visit v = watch(s, 0, Clip::Wave, 40.0f);
        // 40 s at about 1.4 m/s is 3 laps and a half, less a second a lap.
        QVERIFY2(v.runs >= 3 && v.runs <= 4, qPrintable(QString::number(v.runs)));
        QVERIFY2(std::fabs(float(v.last - v.first + 1) / 24.0f - 1.0f) <= 1.0f / 24.0f + 1e-4f,
                 qPrintable(QString::number(v.last - v.first + 1)));
    }

    void sameFramesOnOneAndTwoThreads()
    {
        // 2,400 walkers, so that both threads take chunks of every phase.
        const Scene s = load(R"(throng: 1
settings: {fps: 24, seed: 9, bounds: {min: [-60, -60], max: [60, 60]}}
agent_types:
  - {name: walker, max_speed: 1.3, behaviours: {seek: 1, arrival: 1, separation: 1}}
goals: [{name: east, position: [50, 0], radius: 8}]
action_points:
  - {name: a, position: [-20, 0], radius: 4, action: look_around, duration: 2, facing: 45, chance: 0.7}
  - {name: b, position: [0, 10], radius: 5, action: talk, duration: 1.5, chance: 0.4}
  - {name: c, position: [10, -8], radius: 5, action: sit, duration: 3}
groups:
  - {name: crowd, type: walker, count: 2400, rect: {min: [-50, -40], max: [-25, 40]}, goal: east}
)");
        bool worked = false;
        const std::uint64_t one = hashRun(s, 1, 240), two = hashRun(s, 2, 240, &worked);
        QVERIFY2(worked, "a thread did no work");
        QCOMPARE(two, one);
        // And the points make a difference (the run is not that of a scene without them).
        Scene none = s;
        none.actionPoints.clear();
        QVERIFY(hashRun(none, 1, 240) != one);
    }

    void aCheckpointMidActionResumesBitForBit()
    {
        const Scene s = load(window(24.0f));
        World through(s, {0, false, 1});
        std::vector<AgentFrame> frames;
        WorldState mid;
        bool saved = false;
        std::vector<AgentFrame> expected;
        for (int f = 0; f < 24 * 20; ++f) {
            through.step();
            through.snapshot(frames);
            if (!saved && frames[0].clip == Clip::LookAround) {
                for (int k = 0; k < 24; ++k)
                    through.step();  // a second into the action
                mid = through.saveState();
                saved = true;
            }
        }
        QVERIFY(saved);
        through.snapshot(expected);
        World resumed(s, {0, false, 1});
        resumed.restoreState(mid);
        resumed.snapshot(frames);
        QCOMPARE(frames[0].clip, Clip::LookAround);
        while (resumed.stepIndex() < through.stepIndex())
            resumed.step();
        resumed.snapshot(frames);
        QCOMPARE(std::memcmp(&frames[0].position, &expected[0].position, sizeof(glm::vec3)), 0);
        QCOMPARE(frames[0].arrived, expected[0].arrived);

        // An edit that removes the point while the walker plays there: it goes on at once.
        Scene edited = s;
        edited.actionPoints.clear();
        World adopted(edited, {0, false, 1});
        QVERIFY(adopted.adoptState(mid, s, edited));
        adopted.snapshot(frames);
        QVERIFY(frames[0].clip != Clip::LookAround);
        const glm::vec3 from = frames[0].position;
        for (int k = 0; k < 12; ++k)
            adopted.step();
        adopted.snapshot(frames);
        QVERIFY2(frames[0].position.x > from.x + 0.3f, qPrintable(QString::number(frames[0].position.x - from.x)));
        // An edit of its duration keeps the time it had left.
        Scene longer = s;
        longer.actionPoints[0].durationS = 10.0f;
        World kept(longer, {0, false, 1});
        QVERIFY(kept.adoptState(mid, s, longer));
        for (int k = 0; k < 12; ++k)
            kept.step();
        kept.snapshot(frames);
        QCOMPARE(frames[0].clip, Clip::LookAround);
    }

    void aBrainSensesThePoints()
    {
        // A walker passes a point it never stops at (chance 0) and waves while it is
        // within 2 m of the point's edge; its probe shows the point's bearing.
        const std::string brain = R"(brains:
  - name: greeter
    nodes:
      - {id: 1, type: input, params: {sensor: action_point_distance}}
      - {id: 2, type: math.compare, params: {mode: lt, value: 2}}
      - {id: 3, type: rule.not}
      - {id: 4, type: output.action, params: {actions: "stroll wave"}}
      - {id: 5, type: input, params: {sensor: action_point_bearing}}
      - {id: 6, type: probe, params: {name: bearing}}
      - {id: 7, type: input, params: {sensor: action_point_time}}
      - {id: 8, type: probe, params: {name: left}}
    links:
      - {from: [1, 0], to: [2, 0]}
      - {from: [2, 0], to: [3, 0]}
      - {from: [3, 0], to: [4, 0]}
      - {from: [2, 0], to: [4, 1]}
      - {from: [5, 0], to: [6, 0]}
      - {from: [7, 0], to: [8, 0]}
)";
        auto scene = [&](float chance) {
            return load(R"(throng: 1
settings: {fps: 24, seed: 4, bounds: {min: [-30, -30], max: [30, 30]}}
agent_types:
  - {name: walker, max_speed: 1.2, variation: {speed: [1, 1]}, brain: greeter}
goals: [{name: end, position: [20, 0], radius: 1}]
action_points:
  - {name: stall, position: [0, 0], radius: 1, action: look_around, duration: 2, chance: )" +
                        std::to_string(chance) + R"(}
agents:
  - {id: 1, type: walker, position: [-10, 0, 0], heading: 0, goal: end}
)" + brain);
        };
        auto probe = [](const World& w, const char* name) -> float {
            for (const auto& [probeName, value] : w.brainEvaluator(0)->pickedProbes())
                if (probeName == name)
                    return value;
            qFatal("no value for probe %s", name);
        };
        {
            World world(scene(0.0f), {0, false, 1});
            QVERIFY2(world.brainErrors().empty(), world.brainErrors().empty() ? "" : world.brainErrors()[0].c_str());
            world.pickBrainAgent(0);
            std::vector<AgentFrame> frames;
            int waved = 0, wrong = 0;
            for (int f = 0; f < 24 * 25; ++f) {
                // What the step's sensors read.
                const float x = world.positions()[0].x, z = world.positions()[0].z;
                const float heading = std::atan2(-world.forwards()[0].z, world.forwards()[0].x);
                world.step();
                world.snapshot(frames);
                const float edge = std::max(0.0f, std::fabs(x) - 1.0f);
                waved += frames[0].clip == Clip::Wave;
                wrong += (frames[0].clip == Clip::Wave) != (edge < 2.0f);
                // The point's centre seen from where it stood, + = left of its heading.
                const glm::vec2 to = -glm::vec2(x, z), fw(std::cos(heading), -std::sin(heading));
                const float expected = glm::degrees(std::atan2(glm::dot(to, glm::vec2(fw.y, -fw.x)), glm::dot(to, fw)));
                QVERIFY2(std::fabs(probe(world, "bearing") - expected) < 0.01f,
                         qPrintable(QString("%1, not %2, at x %3").arg(probe(world, "bearing")).arg(expected).arg(x)));
                QCOMPARE(probe(world, "left"), 0.0f);  // it never plays there
            }
            // Within 2 m of the edge on both sides of a 2 m disk: 6 m at 1.2 m/s = 5 s.
            QVERIFY2(waved > 24 * 4 && waved < 24 * 6, qPrintable(QString::number(waved)));
            QCOMPARE(wrong, 0);
        }
        {
            // One that stops reads the seconds it has left there, counting down from 2.
            World world(scene(1.0f), {0, false, 1});
            world.pickBrainAgent(0);
            std::vector<AgentFrame> frames;
            float previous = -1.0f;
            int counted = 0;
            for (int f = 0; f < 24 * 25; ++f) {
                const bool playing = !frames.empty() && frames[0].clip == Clip::LookAround;
                world.step();
                world.snapshot(frames);
                const float left = probe(world, "left");
                if (!playing) {
                    QCOMPARE(left, 0.0f);
                    continue;
                }
                QVERIFY2(left > 0.0f && left <= 2.0f, qPrintable(QString::number(left)));
                if (previous >= 0.0f)
                    QVERIFY2(std::fabs(previous - left - 1.0f / 24.0f) < 1e-4f, qPrintable(QString::number(left)));
                previous = left;
                ++counted;
            }
            QVERIFY2(counted >= 24 * 2 - 2, qPrintable(QString::number(counted)));
        }
    }
};

THRONG_REGISTER_TEST(TestActionPoints)
#include "TestActionPoints.moc"
