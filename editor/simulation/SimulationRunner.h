#pragma once
// Steps a World on its own thread and hands the frames over: the GUI thread takes them
// with takeFrames(). Knows nothing of widgets; the World never leaves its thread.

#include "simcore/brain/BrainEvaluator.h"
#include "simcore/scene/Scene.h"
#include "simcore/world/FrameCache.h"

#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <functional>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace throng::editor {

class SimulationRunner {
public:
    // `notify` is called on the runner's thread whenever frames wait to be taken (it
    // must only post to the GUI thread).
    explicit SimulationRunner(std::function<void()> notify);
    ~SimulationRunner();

    // Stops any run, then builds a World of `scene` on the runner thread and records
    // frame 0. Frames are computed up to the target (setTarget).
    void start(const sim::Scene& scene);
    void stop();
    // Computes frames until `frameCount` frames exist (including frame 0).
    void setTarget(std::size_t frameCount);
    // Computes nothing more until the next setTarget; frames already made stay.
    void stopAhead();

    // One frame's node values of the agent picked for the brain editor's live view.
    struct PickedBrainValues {
        std::ptrdiff_t agent = -1;                // dense World index; -1 = nobody was picked
        std::vector<sim::BrainNodeValue> values;  // empty at frame 0 or without a running brain
    };
    // Records agent `agent`'s brain node values with each frame computed from now on
    // (-1 = nobody); frames already computed keep what they recorded. Any thread.
    void pickBrainAgent(std::ptrdiff_t agent) { m_brainAgent = agent; }

    struct Batch {
        std::vector<sim::AgentInfo> agents;  // set with frame 0 only
        float fps = 24.0f;
        std::vector<sim::AgentFrame> frames; // frame-major, agents.size() per frame
        std::size_t frameCount = 0;
        std::string error;                   // the World could not be built
        // Per frame of `frames`: the picked agent's brain node values (see pickBrainAgent).
        std::vector<PickedBrainValues> brainValues;
    };
    // Moves out what was computed since the last call.
    Batch takeFrames();
    // Steps per second over the last run of steps; 0 when idle.
    double stepsPerSecond() const { return m_stepsPerSecond.load(); }
    bool isComputing() const { return m_computing.load(); }

private:
    void run(sim::Scene scene);

    std::function<void()> m_notify;
    std::thread m_thread;
    std::mutex m_mutex;
    std::condition_variable m_wake;
    std::size_t m_target = 1;
    bool m_stop = false;
    Batch m_pending;
    bool m_notified = false;
    std::atomic<double> m_stepsPerSecond{0.0};
    std::atomic<bool> m_computing{false};
    std::atomic<std::ptrdiff_t> m_brainAgent{-1};
};

}  // namespace throng::editor
