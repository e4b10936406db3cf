// The viewport's gait clocks (GaitPhases) give every agent, at every frame, the phase and
// the walk-run or gait-ladder place the glTF export computes for it (exporting::computeGait
// over the whole recording), to the bit, whatever order the frames are asked in: playing
// forward, jumping back and forth past checkpoints, after the recording grew, after it was
// cut and recorded again differently (an edit), and after it started over. Agents that
// appear late and leave for a while are read as the export reads them.
#include "TestRegistry.h"

#include "editor/viewport/GaitPhases.h"
#include "export/character/BuiltinCharacters.h"
#include "export/character/Gait.h"

#include <QTest>

#include <glm/geometric.hpp>

#include <cmath>
#include <random>

using namespace throng;
using namespace throng::editor;

namespace {

constexpr float kRecordFps = 24.0f;

// Agent a's speed on frame f, m/s: a man that walks, runs and stops; a horse that goes from
// a stand through every gait; a woman strolling. `variant` makes everyone 0.4 m/s faster per
// step from frame 200 on (an edit recorded again).
float speedOf(std::size_t a, std::size_t f, int variant)
{
    const float t = float(f) / kRecordFps;
    const float change = f >= 200 ? 0.4f * float(variant) : 0.0f;
    if (a == 0)
        return std::max(0.0f, 1.4f + 1.6f * std::sin(0.3f * t) + change);
    if (a == 1)
        return std::min(10.0f, 0.8f * t + change);
    return 1.1f + 0.3f * std::cos(t) + change;
}

// Agent a's recorded frame f: along a circle of its own, covering speed / fps a frame. The
// woman is absent for the first 30 frames and between frames 100 and 130.
sim::AgentFrame recorded(std::size_t a, std::size_t f, int variant)
{
    const float radius = 20.0f + 10.0f * float(a);
    float s = 0.0f;  // m walked before frame f
    for (std::size_t g = 0; g < f; ++g)
        s += speedOf(a, g, variant) / kRecordFps;
    sim::AgentFrame frame;
    frame.position = glm::vec3(radius * std::cos(s / radius), 0.0f, radius * std::sin(s / radius));
    frame.speed = speedOf(a, f, variant);
    frame.clip = frame.speed > 0.1f ? sim::Clip::Walk : sim::Clip::Idle;
    frame.present = !(a == 2 && (f < 30 || (f >= 100 && f < 130)));
    return frame;
}

void record(sim::FrameCache& cache, std::size_t from, std::size_t to, int variant)
{
    std::vector<sim::AgentFrame> frame(3);
    for (std::size_t f = from; f < to; ++f) {
        for (std::size_t a = 0; a < 3; ++a)
            frame[a] = recorded(a, f, variant);
        cache.append(frame);
    }
}

// What GltfExporter hands computeGait for agent a: where absent, where it was last (or
// will first be) at rest.
std::vector<exporting::GaitFrame> exported(const sim::FrameCache& cache, std::size_t a,
                                           const exporting::Character& character, const exporting::AgentVariation& v)
{
    const std::size_t frames = cache.frameCount();
    std::vector<glm::vec3> positions(frames);
    std::vector<float> speeds(frames, 0.0f);
    std::size_t first = frames;
    for (std::size_t f = 0; f < frames; ++f) {
        const sim::AgentFrame& at = cache.at(f, a);
        if (!at.present) {
            positions[f] = f > 0 ? positions[f - 1] : glm::vec3(0.0f);
            continue;
        }
        if (first == frames) {
            first = f;
            for (std::size_t g = 0; g < f; ++g)
                positions[g] = at.position;
        }
        positions[f] = at.position;
        speeds[f] = at.speed;
    }
    return exporting::computeGait(character, positions, speeds, v);
}

}  // namespace

class TestGaitPhases : public QObject {
    Q_OBJECT

    exporting::Character m_man = *exporting::makeBuiltinCharacter("man", exporting::Lod::Far);
    exporting::Character m_horse = exporting::makeHorse(exporting::Lod::Far);
    exporting::Character m_woman = *exporting::makeBuiltinCharacter("woman", exporting::Lod::Far);
    std::vector<GaitPhases::Walker> m_walkers;

    void setWalkers()
    {
        m_walkers.assign(3, {});
        const exporting::Character* characters[3] = {&m_man, &m_horse, &m_woman};
        const float heights[3] = {1.0f, 1.0f, 0.93f}, paces[3] = {1.05f, 1.0f, 0.9f}, offsets[3] = {0.3f, 0.0f, 0.7f};
        for (std::size_t a = 0; a < 3; ++a) {
            m_walkers[a].character = characters[a];
            m_walkers[a].variation.heightScale = heights[a];
            m_walkers[a].variation.speedFactor = paces[a];
            m_walkers[a].variation.phaseOffset = offsets[a];
        }
    }

    // The clocks' gait of every agent on frame f against the export's; counts the frames
    // where an agent walks a rung above the first (so the horse's gaits are really met).
    void compare(GaitPhases& phases, const sim::FrameCache& cache, std::size_t f,
                 const std::vector<std::vector<exporting::GaitFrame>>& reference, int& upperRungs)
    {
        std::vector<exporting::GaitFrame> gait;
        phases.gaitAt(cache, f, m_walkers, gait);
        QCOMPARE(gait.size(), std::size_t(3));
        for (std::size_t a = 0; a < 3; ++a) {
            if (!cache.at(f, a).present && a == 2 && f < 30)
                continue;  // not there yet: nothing is drawn
            const exporting::GaitFrame& want = reference[a][f];
            QVERIFY2(gait[a].phase == want.phase && gait[a].runWeight == want.runWeight &&
                         gait[a].moveWeight == want.moveWeight,
                     qPrintable(QString("agent %1, frame %2: phase %3 / %4, run weight %5 / %6")
                                    .arg(a).arg(f).arg(gait[a].phase, 0, 'g', 17).arg(want.phase, 0, 'g', 17)
                                    .arg(gait[a].runWeight).arg(want.runWeight)));
            if (a == 1 && want.runWeight > 0.5f)
                ++upperRungs;
        }
    }

    std::vector<std::vector<exporting::GaitFrame>> reference(const sim::FrameCache& cache)
    {
        std::vector<std::vector<exporting::GaitFrame>> r;
        for (std::size_t a = 0; a < 3; ++a)
            r.push_back(exported(cache, a, *m_walkers[a].character, m_walkers[a].variation));
        return r;
    }

private slots:
    void initTestCase() { setWalkers(); }

    void forwardBackAndJumping()
    {
        sim::FrameCache cache;
        cache.reset({{1, 0}, {2, 1}, {3, 2}}, kRecordFps);
        record(cache, 0, 300, 0);
        const auto want = reference(cache);
        GaitPhases phases;
        int upper = 0;
        for (std::size_t f = 0; f < 300; ++f)  // playing
            compare(phases, cache, f, want, upper);
        QVERIFY2(phases.checkpointStride() < 300, "the run must span several checkpoints");
        for (std::size_t f = 300; f-- > 0;)  // backwards, a frame at a time
            compare(phases, cache, f, want, upper);
        std::mt19937 rng(7);
        for (int k = 0; k < 200; ++k)  // scrubbing
            compare(phases, cache, std::size_t(rng() % 300), want, upper);
        QVERIFY2(upper > 100, qPrintable(QString("the horse galloped on %1 frames").arg(upper)));
    }

    // Asked while it records, then after the recording is cut at frame 200 and recorded
    // again faster: every frame after the cut is the new take's.
    void growingAndRecordedAgain()
    {
        sim::FrameCache cache;
        cache.reset({{1, 0}, {2, 1}, {3, 2}}, kRecordFps);
        GaitPhases phases;
        int upper = 0;
        for (std::size_t end = 40; end <= 280; end += 40) {
            record(cache, cache.frameCount(), end, 0);
            const auto want = reference(cache);
            compare(phases, cache, end - 1, want, upper);
            compare(phases, cache, end / 2, want, upper);
        }
        const auto before = reference(cache);
        compare(phases, cache, 270, before, upper);  // the clocks are past the cut
        cache.truncate(200);
        record(cache, 200, 280, 2);
        const auto after = reference(cache);
        QVERIFY2(std::abs(after[0][270].phase - before[0][270].phase) > 0.05,
                 "the second take must walk differently after the cut");
        for (std::size_t f : {std::size_t(270), std::size_t(150), std::size_t(210), std::size_t(279), std::size_t(5)})
            compare(phases, cache, f, after, upper);
    }

    // Walkers for another agent set than the cache's (one fewer, one more): no gait at all,
    // not frames read past their width; with the right walkers again, the gait is the export's.
    void walkersOfAnotherAgentSetGiveNoGait()
    {
        sim::FrameCache cache;
        cache.reset({{1, 0}, {2, 1}, {3, 2}}, kRecordFps);
        record(cache, 0, 60, 0);
        GaitPhases phases;
        std::vector<exporting::GaitFrame> gait(5);
        const std::vector<GaitPhases::Walker> fewer(m_walkers.begin(), m_walkers.begin() + 2);
        phases.gaitAt(cache, 40, fewer, gait);
        QVERIFY(gait.empty());
        std::vector<GaitPhases::Walker> more = m_walkers;
        more.push_back(m_walkers[0]);
        gait.resize(5);
        phases.gaitAt(cache, 59, more, gait);
        QVERIFY(gait.empty());
        int upper = 0;
        compare(phases, cache, 50, reference(cache), upper);
    }

    // The same cache started over (File > Revert, a settings edit): nothing kept is used.
    void resetAndRecordedAgain()
    {
        sim::FrameCache cache;
        cache.reset({{1, 0}, {2, 1}, {3, 2}}, kRecordFps);
        record(cache, 0, 250, 0);
        GaitPhases phases;
        int upper = 0;
        compare(phases, cache, 240, reference(cache), upper);
        const double before = reference(cache)[0][240].phase;
        cache.reset({{1, 0}, {2, 1}, {3, 2}}, kRecordFps);
        record(cache, 0, 250, 3);
        const auto after = reference(cache);
        QVERIFY2(std::abs(after[0][240].phase - before) > 0.05,
                 qPrintable(QString("the new take must walk differently: %1 / %2").arg(after[0][240].phase).arg(before)));
        for (std::size_t f : {std::size_t(240), std::size_t(239), std::size_t(60)})
            compare(phases, cache, f, after, upper);
    }
};

THRONG_REGISTER_TEST(TestGaitPhases)
#include "TestGaitPhases.moc"
