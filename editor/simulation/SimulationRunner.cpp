#include "editor/simulation/SimulationRunner.h"

#include "simcore/world/World.h"

#include <algorithm>
#include <chrono>
#include <exception>
#include <memory>
#include <utility>

namespace throng::editor {

SimulationRunner::SimulationRunner(std::function<void()> notify) : m_notify(std::move(notify)) {}

SimulationRunner::~SimulationRunner()
{
    stop();
}

void SimulationRunner::start(const sim::Scene& scene)
{
    launch(scene, 0, Replay{});
}

void SimulationRunner::resume(const sim::Scene& scene, std::size_t editFrame)
{
    launch(scene, editFrame, Replay{});
}

void SimulationRunner::replayBrainValues(sim::AgentId agentId, std::size_t recordedFrames)
{
    Replay replay;
    replay.on = true;
    replay.id = agentId;
    replay.recordedFrames = recordedFrames;
    launch(sim::Scene{}, 0, replay);
}

void SimulationRunner::launch(sim::Scene scene, std::size_t resumeFrame, Replay replay)
{
    auto shared = std::make_shared<const sim::Scene>(std::move(scene));
    {
        std::lock_guard lock(m_mutex);
        // The run in progress stops at its next check; one still building a World (which
        // cannot be interrupted) hands nothing over when it is done.
        ++m_run;
        m_request = Request{std::move(shared), resumeFrame, replay};
        m_quit = false;
        m_target = 1;
        m_pending = {};
        m_notified = false;
        m_describe.clear();
        if (resumeFrame == 0 && !replay.on) {
            m_checkpoints.clear();
            m_checkpointBytes = 0;
        }
        if (!m_thread.joinable())
            m_thread = std::thread([this] { work(); });
    }
    m_stepsPerSecond = 0.0;
    m_wake.notify_all();
}

void SimulationRunner::work()
{
    for (;;) {
        Request request;
        RunId runId = 0;
        {
            std::unique_lock lock(m_mutex);
            m_computing = false;
            m_wake.wait(lock, [this] { return m_quit || m_request; });
            if (m_quit)
                return;
            request = std::move(*m_request);
            m_request.reset();
            runId = m_run;
        }
        run(std::move(request.scene), request.resumeFrame, request.replay, runId);
    }
}

bool SimulationRunner::stoppedNow(RunId runId) const
{
    std::lock_guard lock(m_mutex);
    return stopped(runId);
}

void SimulationRunner::describeFrame(std::size_t frame)
{
    {
        std::lock_guard lock(m_mutex);
        if (std::find(m_describe.begin(), m_describe.end(), frame) == m_describe.end())
            m_describe.push_back(frame);
    }
    m_wake.notify_all();
}

void SimulationRunner::describeRecorded(std::size_t frame, RunId runId)
{
    const std::vector<sim::AgentId> ids = m_watch.ids();
    if (ids.empty())
        return;
    Checkpoint from;
    std::size_t fromFrame = 0;
    {
        std::lock_guard lock(m_mutex);
        auto it = m_checkpoints.upper_bound(frame);
        if (it == m_checkpoints.begin())
            return;
        --it;
        fromFrame = it->first;
        from = it->second;
    }
    // A checkpoint at a resume point holds the edited World: the frames from it on were
    // recorded with its scene (every change of scene pins one), so stepping it again
    // gives the recorded frames.
    sim::World world(*from.scene);
    world.restoreState(*from.state);
    for (std::size_t f = fromFrame; f < frame; ++f) {
        if (stoppedNow(runId))
            return;
        world.step();
    }
    FrameSteering described{frame, SteeringWatch::describe(world, ids)};
    std::lock_guard lock(m_mutex);
    if (stopped(runId))
        return;
    m_pending.steering.push_back(std::move(described));
    if (!m_notified) {
        m_notified = true;
        m_notify();
    }
}

void SimulationRunner::setCheckpointBudget(std::size_t intervalFrames, std::size_t budgetBytes)
{
    std::lock_guard lock(m_mutex);
    m_interval = std::max<std::size_t>(1, intervalFrames);
    m_budgetBytes = budgetBytes;
}

std::vector<std::size_t> SimulationRunner::checkpointFrames() const
{
    std::lock_guard lock(m_mutex);
    std::vector<std::size_t> frames;
    for (const auto& [frame, checkpoint] : m_checkpoints)
        frames.push_back(frame);
    return frames;
}

std::size_t SimulationRunner::checkpointBytes() const
{
    std::lock_guard lock(m_mutex);
    return m_checkpointBytes;
}

void SimulationRunner::stop()
{
    {
        std::lock_guard lock(m_mutex);
        m_quit = true;
        ++m_run;
        m_request.reset();
    }
    m_wake.notify_all();
    if (m_thread.joinable())
        m_thread.join();
    m_stepsPerSecond = 0.0;
    m_computing = false;
}

void SimulationRunner::setTarget(std::size_t frameCount)
{
    {
        std::lock_guard lock(m_mutex);
        m_target = std::max(m_target, frameCount);
    }
    m_wake.notify_all();
}

void SimulationRunner::stopAhead()
{
    std::lock_guard lock(m_mutex);
    m_target = 0;
}

SimulationRunner::Batch SimulationRunner::takeFrames()
{
    std::lock_guard lock(m_mutex);
    Batch out = std::move(m_pending);
    m_pending = {};
    m_pending.fps = out.fps;
    m_notified = false;
    return out;
}

void SimulationRunner::keepCheckpoint(std::size_t frame, const std::shared_ptr<const sim::Scene>& scene,
                                      const sim::World& world, bool pinned, Checkpoint before, RunId runId)
{
    auto state = std::make_shared<const sim::WorldState>(world.saveState());
    std::lock_guard lock(m_mutex);
    if (stopped(runId))
        return;  // the checkpoints are another run's now
    if (auto old = m_checkpoints.find(frame); old != m_checkpoints.end())
        m_checkpointBytes -= old->second.state->memoryBytes();
    m_checkpointBytes += state->memoryBytes();
    Checkpoint& kept = m_checkpoints[frame];
    kept.scene = scene;
    kept.state = std::move(state);
    kept.pinned = pinned;
    kept.beforeScene = before.scene;
    kept.beforeState = before.state;
    // Over budget: every other checkpoint goes (the pinned ones stay), the interval doubles.
    while (m_checkpointBytes > m_budgetBytes && m_interval < (std::size_t(1) << 20)) {
        m_interval *= 2;
        for (auto it = m_checkpoints.begin(); it != m_checkpoints.end();) {
            if (!it->second.pinned && it->first % m_interval != 0) {
                m_checkpointBytes -= it->second.state->memoryBytes();
                it = m_checkpoints.erase(it);
            } else {
                ++it;
            }
        }
    }
}

std::unique_ptr<sim::World> SimulationRunner::resumeWorld(const std::shared_ptr<const sim::Scene>& scene,
                                                          std::size_t resumeFrame, std::vector<std::int32_t>& previous,
                                                          RunId runId)
{
    Checkpoint from;
    std::size_t fromFrame = 0;
    {
        std::lock_guard lock(m_mutex);
        auto it = m_checkpoints.upper_bound(resumeFrame);
        if (it == m_checkpoints.begin())
            return nullptr;
        --it;
        fromFrame = it->first;
        from = it->second;
    }
    // Frames fromFrame..resumeFrame were recorded with the checkpoint's scene (every
    // change of scene pins a checkpoint where it took over): step them again with it.
    // An edit at a resume point (an undo) starts from what was resumed there.
    Checkpoint before;
    if (fromFrame == resumeFrame && from.beforeState) {
        before.scene = from.beforeScene;
        before.state = from.beforeState;
    } else {
        sim::World recorded(*from.scene);
        recorded.restoreState(*from.state);
        for (std::size_t f = fromFrame; f < resumeFrame; ++f)
            recorded.step();
        before.scene = from.scene;
        before.state = std::make_shared<const sim::WorldState>(recorded.saveState());
    }
    auto edited = std::make_unique<sim::World>(*scene);
    if (!edited->adoptState(*before.state, *before.scene, *scene, &previous))
        return nullptr;

    {
        std::lock_guard lock(m_mutex);
        if (stopped(runId))
            return nullptr;
        for (auto it = m_checkpoints.upper_bound(resumeFrame); it != m_checkpoints.end();) {
            m_checkpointBytes -= it->second.state->memoryBytes();
            it = m_checkpoints.erase(it);
        }
    }
    keepCheckpoint(resumeFrame, scene, *edited, true, before, runId);
    return edited;
}

std::unique_ptr<sim::World> SimulationRunner::replayWorld(const Replay& replay, std::shared_ptr<const sim::Scene>& scene,
                                                          RunId runId)
{
    std::vector<std::pair<std::size_t, Checkpoint>> spans;
    {
        std::lock_guard lock(m_mutex);
        for (const auto& [frame, checkpoint] : m_checkpoints)
            if (frame < replay.recordedFrames)
                spans.emplace_back(frame, checkpoint);
    }
    std::unique_ptr<sim::World> world;
    for (std::size_t k = 0; k < spans.size(); ++k) {
        const std::size_t from = spans[k].first;
        const std::size_t to = k + 1 < spans.size() ? spans[k + 1].first : replay.recordedFrames - 1;
        scene = spans[k].second.scene;
        world = std::make_unique<sim::World>(*scene);
        world->restoreState(*spans[k].second.state);
        std::ptrdiff_t picked = -1;
        for (std::size_t i = 0; i < world->agentCount() && picked < 0; ++i)
            if (world->id(i) == replay.id)
                picked = std::ptrdiff_t(i);
        world->pickBrainAgent(picked);
        for (std::size_t f = from; f < to; ++f) {
            if (stoppedNow(runId))
                return nullptr;
            world->step();
            PickedBrainValues brain{picked, {}};
            if (const sim::BrainEvaluator* e = picked < 0 ? nullptr : world->agentBrainEvaluator(std::size_t(picked)))
                brain.values = e->pickedValues();
            std::lock_guard lock(m_mutex);
            if (stopped(runId))
                return nullptr;
            m_pending.brainValues.push_back(std::move(brain));
            ++m_pending.frameCount;
            if (!m_notified) {
                m_notified = true;
                m_notify();
            }
        }
    }
    return world;
}

void SimulationRunner::run(std::shared_ptr<const sim::Scene> scene, std::size_t resumeFrame, Replay replay,
                           RunId runId)
{
    using Clock = std::chrono::steady_clock;
    std::unique_ptr<sim::World> world;
    std::vector<sim::AgentFrame> frame;
    std::size_t produced = 0;
    std::vector<std::int32_t> previous;
    try {
        if (replay.on) {
            world = replayWorld(replay, scene, runId);
            if (!world)
                return;
            resumeFrame = replay.recordedFrames - 1;  // the live run goes on from there
        } else if (resumeFrame > 0) {
            world = resumeWorld(scene, resumeFrame, previous, runId);
        }
        if (world) {
            produced = resumeFrame + 1;
        } else {
            resumeFrame = 0;
            {
                std::lock_guard lock(m_mutex);
                if (stopped(runId))
                    return;
                m_checkpoints.clear();
                m_checkpointBytes = 0;
            }
            if (m_buildGate)
                m_buildGate();
            world = std::make_unique<sim::World>(*scene);
            keepCheckpoint(0, scene, *world, true, Checkpoint{}, runId);
        }
    } catch (const std::exception& e) {
        std::lock_guard lock(m_mutex);
        if (stopped(runId))
            return;
        m_pending.error = e.what();
        m_notified = true;
        m_notify();
        return;
    }
    std::ptrdiff_t picked = -1;
    bool firstAfterResume = resumeFrame > 0 && !replay.on;
    m_watch.forgetWorld();
    auto publish = [&](bool first, std::size_t frameIndex) {
        world->snapshot(frame);
        std::vector<sim::AgentDebug> steering = m_watch.describe(*world);
        sim::addOrigin(frame, world->origin());
        PickedBrainValues brain{first ? -1 : picked, {}};
        if (const sim::BrainEvaluator* e = first || picked < 0 ? nullptr : world->agentBrainEvaluator(std::size_t(picked)))
            brain.values = e->pickedValues();
        std::lock_guard lock(m_mutex);
        if (stopped(runId))
            return;
        if (first) {
            m_pending.agents = world->agentInfo();
            m_pending.fps = scene->settings.fps;
            m_pending.started = frameIndex == 0;
        }
        // Only the first batch after a resume says so: the controller drops what it holds
        // after the resume frame once, not again for every batch.
        if (std::exchange(firstAfterResume, false)) {
            m_pending.resumedAt = resumeFrame;
            m_pending.agents = world->agentInfo();
            m_pending.previous = previous;
        }
        m_pending.frames.insert(m_pending.frames.end(), frame.begin(), frame.end());
        m_pending.brainValues.push_back(std::move(brain));
        if (!steering.empty())
            m_pending.steering.push_back({frameIndex, std::move(steering)});
        ++m_pending.frameCount;
        if (!m_notified) {
            m_notified = true;
            m_notify();
        }
    };
    if (resumeFrame == 0) {
        publish(true, 0);
        produced = 1;
    } else if (!replay.on) {
        // The edit frame again, from the edited World: what the edit added shows at once
        // (a stroke's agents at their spawn state, erased ones gone).
        publish(true, resumeFrame);
        std::lock_guard lock(m_mutex);
        if (!stopped(runId))
            m_target = std::max(m_target, produced);
    } else {
        std::lock_guard lock(m_mutex);
        if (!stopped(runId)) {
            m_pending.fps = scene->settings.fps;
            m_target = std::max(m_target, produced);
        }
    }
    for (;;) {
        {
            std::unique_lock lock(m_mutex);
            m_computing = false;
            m_wake.wait(lock, [&] { return stopped(runId) || produced < m_target || !m_describe.empty(); });
            if (stopped(runId))
                return;
            m_computing = true;
        }
        // Frames recorded before the watched agents were picked, described on request.
        for (;;) {
            std::size_t describe = 0;
            {
                std::lock_guard lock(m_mutex);
                if (m_describe.empty() || stopped(runId))
                    break;
                describe = m_describe.front();
                m_describe.erase(m_describe.begin());
            }
            if (describe < produced)
                describeRecorded(describe, runId);
        }
        const Clock::time_point begin = Clock::now();
        std::size_t steps = 0;
        // Step in short bursts so stop() and new targets are seen within a few steps.
        while (steps < 8) {
            std::size_t interval = 0;
            {
                std::lock_guard lock(m_mutex);
                if (stopped(runId) || produced >= m_target)
                    break;
                interval = m_interval;
            }
            if (const std::ptrdiff_t want = m_brainAgent.load(); want != picked) {
                picked = want >= 0 && std::size_t(want) < world->agentCount() ? want : -1;
                world->pickBrainAgent(picked);
            }
            world->step();
            publish(false, produced);
            if (produced % interval == 0)
                keepCheckpoint(produced, scene, *world, false, Checkpoint{}, runId);
            ++produced;
            ++steps;
        }
        const double seconds = std::chrono::duration<double>(Clock::now() - begin).count();
        if (steps > 0 && seconds > 0.0)
            m_stepsPerSecond = double(steps) / seconds;
    }
}

}  // namespace throng::editor
