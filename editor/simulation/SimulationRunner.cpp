#include "editor/simulation/SimulationRunner.h"

#include "simcore/world/World.h"

#include <algorithm>
#include <chrono>
#include <exception>
#include <memory>

namespace throng::editor {

SimulationRunner::SimulationRunner(std::function<void()> notify) : m_notify(std::move(notify)) {}

SimulationRunner::~SimulationRunner()
{
    stop();
}

void SimulationRunner::start(const sim::Scene& scene)
{
    stop();
    {
        std::lock_guard lock(m_mutex);
        m_stop = false;
        m_target = 1;
        m_pending = {};
        m_notified = false;
    }
    m_thread = std::thread([this, scene] { run(scene); });
}

void SimulationRunner::stop()
{
    {
        std::lock_guard lock(m_mutex);
        m_stop = true;
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

void SimulationRunner::run(sim::Scene scene)
{
    using Clock = std::chrono::steady_clock;
    std::unique_ptr<sim::World> world;
    std::vector<sim::AgentFrame> frame;
    try {
        world = std::make_unique<sim::World>(scene);
    } catch (const std::exception& e) {
        std::lock_guard lock(m_mutex);
        m_pending.error = e.what();
        m_notified = true;
        m_notify();
        return;
    }
    std::size_t produced = 0;
    std::ptrdiff_t picked = -1;
    auto publish = [&](bool first) {
        world->snapshot(frame);
        PickedBrainValues brain{first ? -1 : picked, {}};
        if (const sim::BrainEvaluator* e = first || picked < 0 ? nullptr : world->agentBrainEvaluator(std::size_t(picked)))
            brain.values = e->pickedValues();
        std::lock_guard lock(m_mutex);
        if (first) {
            m_pending.agents = world->agentInfo();
            m_pending.fps = scene.settings.fps;
        }
        m_pending.frames.insert(m_pending.frames.end(), frame.begin(), frame.end());
        m_pending.brainValues.push_back(std::move(brain));
        ++m_pending.frameCount;
        if (!m_notified) {
            m_notified = true;
            m_notify();
        }
    };
    publish(true);
    produced = 1;
    for (;;) {
        {
            std::unique_lock lock(m_mutex);
            m_computing = false;
            m_wake.wait(lock, [&] { return m_stop || produced < m_target; });
            if (m_stop)
                return;
            m_computing = true;
        }
        const Clock::time_point begin = Clock::now();
        std::size_t steps = 0;
        // Step in short bursts so stop() and new targets are seen within a few steps.
        while (steps < 8) {
            {
                std::lock_guard lock(m_mutex);
                if (m_stop || produced >= m_target)
                    break;
            }
            if (const std::ptrdiff_t want = m_brainAgent.load(); want != picked) {
                picked = want >= 0 && std::size_t(want) < world->agentCount() ? want : -1;
                world->pickBrainAgent(picked);
            }
            world->step();
            publish(false);
            ++produced;
            ++steps;
        }
        const double seconds = std::chrono::duration<double>(Clock::now() - begin).count();
        if (steps > 0 && seconds > 0.0)
            m_stepsPerSecond = double(steps) / seconds;
    }
}

}  // namespace throng::editor
