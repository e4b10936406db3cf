#include "editor/simulation/SimulationController.h"

#include <QMetaObject>

#include <algorithm>
#include <cmath>
#include <utility>

namespace throng::editor {

SimulationController::SimulationController(QObject* parent)
    : QObject(parent),
      m_runner([this] { QMetaObject::invokeMethod(this, &SimulationController::takeFrames, Qt::QueuedConnection); })
{
    connect(&m_timer, &QTimer::timeout, this, &SimulationController::tick);
}

SimulationController::~SimulationController()
{
    stopCacheReader();
    m_runner.stop();
}

void SimulationController::setCacheReader(std::function<void()> stop)
{
    m_cacheReader = std::move(stop);
}

void SimulationController::clearCacheReader()
{
    if (!m_cacheReader)
        return;
    m_cacheReader = {};
    takeFrames();  // the runner notifies once until its frames are taken
}

void SimulationController::stopCacheReader()
{
    if (const std::function<void()> stop = std::exchange(m_cacheReader, {}))
        stop();
}

void SimulationController::takeTiming(const sim::Scene& scene)
{
    m_fps = scene.settings.fps > 0.0f ? double(scene.settings.fps) : 24.0;
    m_totalFrames = std::size_t(std::lround(double(scene.settings.durationS) * m_fps)) + 1;
    applyTimerInterval();
}

void SimulationController::setScene(const sim::Scene& scene)
{
    m_hasScene = true;
    takeTiming(scene);
    startOver(scene);
}

void SimulationController::applyEdit(const sim::Scene& scene, const SceneChange& change)
{
    // What the World does not read leaves every frame as it was recorded (and the runner
    // goes on with the scene it has, which simulates alike).
    if (m_hasScene && !change.simulationReads)
        return;
    stopCacheReader();
    // Frames up to the shown one stay; the runner goes on from there with the edited scene
    // (or starts over when the edit cannot be resumed: the first batch then says so).
    const bool resume = m_hasScene && m_current > 0 && m_current < m_cache.frameCount();
    m_hasScene = true;
    takeTiming(scene);
    if (!resume) {
        startOver(scene);
        return;
    }
    m_cache.truncate(m_current + 1);
    m_brainValues.resize(std::min(m_brainValues.size(), m_current + 1));
    m_steering.dropFrom(m_current);  // the edited World describes the edit frame again
    m_runFrames = m_current + 1;
    m_replaying = false;
    m_runner.resume(scene, m_current);
    // Playing or a step asked for goes on with the edited scene.
    if (m_playing)
        m_runner.setTarget(m_totalFrames);
    else if (m_stepPending)
        m_runner.setTarget(m_current + 2);
    else if (m_seekTarget)
        m_runner.setTarget(*m_seekTarget + 1);
    emit recordedChanged(m_cache.frameCount());
}

void SimulationController::startOver(const sim::Scene& scene)
{
    // Playback goes on from frame 0 with the new scene (as a resumed run goes on from the
    // edit), so Play pressed just before the edit reached here still plays.
    const bool wasPlaying = m_playing;
    pause();
    stopCacheReader();
    m_stepPending = false;
    m_seekTarget.reset();
    m_cache = {};
    m_brainValues.clear();
    m_steering.clear();
    m_current = 0;
    m_runner.start(scene);
    m_runFrames = 0;
    m_replaying = false;
    emit recordedChanged(0);
    if (wasPlaying)
        play();
}

void SimulationController::takeFrames()
{
    if (m_cacheReader)
        return;  // they wait in the runner until the reader is done (clearCacheReader)
    SimulationRunner::Batch batch = m_runner.takeFrames();
    if (!batch.error.empty()) {
        pause();
        emit problem(tr("Cannot simulate the scene: %1").arg(QString::fromStdString(batch.error)));
        return;
    }
    // A run that computes recorded frames again (pickBrainAgent) brings only their values.
    const bool resumed = batch.resumedAt > 0;
    const bool restarted = batch.started;
    if (restarted) {
        ++m_restarts;
        m_cache.reset(std::move(batch.agents), batch.fps);
        m_brainValues.clear();
        m_steering.clear();
        m_runFrames = 0;
        m_replaying = false;
        m_seekTarget.reset();
        // A resume that had to start over: back to frame 0, as any restart.
        if (m_current != 0) {
            pause();
            m_stepPending = false;
            m_current = 0;
        }
    } else if (resumed) {
        // A resumed run hands over frames from resumedAt on (the edit frame again, from
        // the edited World), of the edited World's agents (an edit may have added or
        // removed some: the cache keeps both sets).
        if (m_cache.frameCount() > batch.resumedAt)
            m_cache.truncate(batch.resumedAt);
        m_brainValues.resize(std::min(m_brainValues.size(), batch.resumedAt));
        m_steering.dropFrom(batch.resumedAt);
        m_runFrames = batch.resumedAt;
        m_lastResumedAt = batch.resumedAt;
        if (!batch.agents.empty() && batch.previous.size() == batch.agents.size())
            m_cache.changeAgents(batch.agents, batch.previous);
    }
    // The batch's frames are in the World's dense order; frames already recorded (a
    // replay for brain values) bring their values only.
    const std::size_t n = m_cache.worldAgentCount();
    std::size_t appended = 0;
    bool replayed = false;
    for (std::size_t f = 0; f < batch.frameCount; ++f) {
        const std::size_t frame = m_runFrames + f;
        SimulationRunner::PickedBrainValues values =
            f < batch.brainValues.size() ? std::move(batch.brainValues[f]) : SimulationRunner::PickedBrainValues{};
        if (frame < m_cache.frameCount()) {
            if (values.agent >= 0)
                values.agent = m_replayAgent;
            m_brainValues[frame] = std::move(values);
            replayed = true;
            continue;
        }
        if (n == 0 || (appended + 1) * n > batch.frames.size())
            break;
        // Kept by cache agent: World indices change when an edit adds or removes agents.
        if (values.agent >= 0 && std::size_t(values.agent) < n)
            values.agent = std::ptrdiff_t(m_cache.cacheIndexOf(std::size_t(values.agent)));
        m_cache.append(std::span(batch.frames).subspan(appended * n, n));
        ++appended;
        m_brainValues.push_back(std::move(values));
    }
    m_runFrames += batch.frameCount;
    if (replayed)
        emit brainValuesChanged();
    const bool steeringShown = std::any_of(batch.steering.begin(), batch.steering.end(),
                                           [&](const auto& s) { return s.frame == m_current; });
    m_steering.take(std::move(batch.steering));
    if (steeringShown)
        emit steeringChanged();
    emit recordedChanged(m_cache.frameCount());
    if (restarted && m_current == 0)
        emit frameChanged(0);
    // The frame shown was recorded again (the edit frame): show it as it is now.
    if (resumed && m_current >= batch.resumedAt && m_current < m_cache.frameCount())
        emit frameChanged(m_current);
    // Going to a frame not recorded yet: the shown frame follows the recording to it.
    if (m_seekTarget && appended > 0) {
        const std::size_t target = std::min(*m_seekTarget, m_cache.frameCount() - 1);
        if (target == *m_seekTarget)
            m_seekTarget.reset();
        setCurrent(target);
    }
    if (m_stepPending && m_current + 1 < m_cache.frameCount()) {
        m_stepPending = false;
        setCurrent(m_current + 1);
    }
}

void SimulationController::play()
{
    if (m_playing)
        return;
    if (!m_loop && m_current + 1 >= m_totalFrames)
        setCurrent(0);
    m_seekTarget.reset();
    startClock();
    m_playing = true;
    m_runner.setTarget(m_totalFrames);
    m_timer.start();
    emit playingChanged(true);
}

void SimulationController::pause()
{
    if (!m_playing)
        return;
    m_playing = false;
    m_timer.stop();
    emit playingChanged(false);
    describeShown();
}

void SimulationController::setPlaybackMode(PlaybackMode mode)
{
    m_mode = mode;
    applyTimerInterval();
    if (m_playing)
        startClock();
}

void SimulationController::applyTimerInterval()
{
    const double frameMs = 1000.0 / m_fps;
    // Real time reads the clock twice a frame, so no frame shows more than half a frame late.
    const bool realTime = m_mode == PlaybackMode::RealTime;
    m_timer.setTimerType(realTime ? Qt::PreciseTimer : Qt::CoarseTimer);
    m_timer.setInterval(std::max(1, int(std::lround(realTime ? frameMs / 2.0 : frameMs))));
}

void SimulationController::startClock()
{
    m_clockFrame = m_current;
    m_clock.start();
}

void SimulationController::tick()
{
    if (m_mode == PlaybackMode::RealTime) {
        tickRealTime();
        return;
    }
    if (m_current + 1 < m_cache.frameCount()) {
        setCurrent(m_current + 1);
    } else if (m_current + 1 >= m_totalFrames) {
        if (m_loop)
            setCurrent(0);
        else
            pause();
    }
    // Otherwise the runner has not caught up yet: wait for it.
}

void SimulationController::tickRealTime()
{
    const std::size_t due = m_clockFrame + std::size_t(double(m_clock.elapsed()) * m_fps / 1000.0);
    if (m_current + 1 >= m_totalFrames) {
        // The last frame stays up for its own duration before the loop or the stop.
        if (due <= m_current)
            return;
        if (m_loop) {
            setCurrent(0);
            startClock();
        } else {
            pause();
        }
        return;
    }
    const std::size_t recorded = m_cache.frameCount();
    if (recorded == 0)
        return;
    const std::size_t shown = std::min({due, m_totalFrames - 1, recorded - 1});
    if (shown > m_current)
        setCurrent(shown);
    // The computation lags behind the clock: the clock waits for it rather than jumping
    // ahead once the frames arrive.
    if (due > shown && shown == recorded - 1)
        startClock();
}

void SimulationController::stepForward()
{
    pause();
    m_seekTarget.reset();
    if (m_current + 1 >= m_totalFrames)
        return;
    if (m_current + 1 < m_cache.frameCount()) {
        setCurrent(m_current + 1);
        return;
    }
    m_stepPending = true;
    m_runner.setTarget(m_current + 2);
}

void SimulationController::stepBackward()
{
    pause();
    m_seekTarget.reset();
    if (m_current > 0)
        setCurrent(m_current - 1);
}

void SimulationController::restart()
{
    m_seekTarget.reset();
    setCurrent(0);
    if (m_playing)
        startClock();
}

void SimulationController::showLastRecorded()
{
    pause();
    m_seekTarget.reset();
    if (m_cache.frameCount() > 0)
        setCurrent(m_cache.frameCount() - 1);
}

void SimulationController::seek(std::size_t frame)
{
    frame = std::min(frame, m_totalFrames - 1);
    if (frame < m_cache.frameCount()) {
        m_seekTarget.reset();
        setCurrent(frame);
        return;
    }
    m_seekTarget = frame;
    m_runner.setTarget(frame + 1);
    if (m_cache.frameCount() > 0)
        setCurrent(m_cache.frameCount() - 1);
}

void SimulationController::simulateToEnd()
{
    m_runner.setTarget(m_totalFrames);
}

void SimulationController::pickBrainAgent(std::ptrdiff_t agent)
{
    // The runner picks by World index; the editor by cache agent.
    m_runner.pickBrainAgent(agent >= 0 && std::size_t(agent) < m_cache.agentCount() ? m_cache.worldIndexOf(std::size_t(agent)) : -1);
    if (agent < 0 || !m_hasScene || m_cache.frameCount() <= 1 || brainValues(m_cache.frameCount() - 1, agent))
        return;
    // The recorded frames are computed again from the checkpoints, each span with the
    // scene it was recorded with, so the values are those of the frames shown.
    m_runner.replayBrainValues(m_cache.agents()[std::size_t(agent)].id, m_cache.frameCount());
    m_runFrames = 1;
    m_replaying = true;
    m_replayAgent = agent;
    m_runner.setTarget(m_playing ? m_totalFrames : std::max(m_cache.frameCount(), m_seekTarget ? *m_seekTarget + 1 : 0));
}

const std::vector<sim::BrainNodeValue>* SimulationController::brainValues(std::size_t frame, std::ptrdiff_t agent) const
{
    if (agent < 0 || frame >= m_brainValues.size() || m_brainValues[frame].agent != agent)
        return nullptr;
    return &m_brainValues[frame].values;
}

void SimulationController::setCurrent(std::size_t frame)
{
    m_current = frame;
    if (frame < m_cache.frameCount())
        emit frameChanged(frame);
    if (!m_playing)
        describeShown();
}

void SimulationController::watchAgents(std::vector<sim::AgentId> ids)
{
    m_runner.watchAgents(ids);
    m_steering.setWatched(std::move(ids));
    if (!m_playing)
        describeShown();
}

void SimulationController::describeShown()
{
    if (m_current < m_cache.frameCount() && m_steering.wantsDescribing(m_current))
        m_runner.describeFrame(m_current);
}

}  // namespace throng::editor
