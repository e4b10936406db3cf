#pragma once
// Steps a World on its own thread and hands the frames over: the GUI thread takes them
// with takeFrames(). Keeps checkpoints of the World (every interval frames, within a byte
// budget) so that an edit resumes from the edit frame instead of frame 0 (resume; the
// rule is in simcore/world/WorldState.h). Knows nothing of widgets; the World never
// leaves its thread, and the caller never waits for it: a new run asked for while one
// is building a World is taken up when that build ends (only the latest one asked for).

#include "editor/simulation/SteeringWatch.h"
#include "simcore/brain/BrainEvaluator.h"
#include "simcore/scene/Scene.h"
#include "simcore/world/FrameCache.h"
#include "simcore/world/WorldState.h"

#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace throng::sim {
class World;
}

namespace throng::editor {

class SimulationRunner {
public:
    // `notify` is called on the runner's thread whenever frames wait to be taken (it
    // must only post to the GUI thread).
    explicit SimulationRunner(std::function<void()> notify);
    ~SimulationRunner();

    // Stops any run, then builds a World of `scene` on the runner thread and records
    // frame 0. Frames are computed up to the target (setTarget). Returns at once: the run
    // stopped hands over nothing more (a World it is building is dropped when built).
    void start(const sim::Scene& scene);
    // Stops any run, then runs the edited `scene` on from frame `editFrame` (> 0) of the
    // recorded run: from the last checkpoint at or before it, the run is stepped again to
    // editFrame with the scene it was recorded with, and the edited scene takes over that
    // state (World::adoptState). Frames 0..editFrame - 1 stay as recorded; the batches
    // that follow carry frames from editFrame on (Batch::resumedAt; frame editFrame again,
    // as the edited World has it: a stroke's agents show there at once) and, in their first batch,
    // the edited World's agents and what they were before (Batch::agents, previous): an
    // edit may add or remove agents. When the edit cannot be resumed (settings, lanes,
    // crosswalks or vehicles changed; see WorldState.h), the run starts again from frame
    // 0 instead, as start() does.
    void resume(const sim::Scene& scene, std::size_t editFrame);
    // Stops any run and ends the runner thread (waits for it).
    void stop();
    // Checkpoint every `intervalFrames` frames while their bytes stay within `budgetBytes`;
    // past it the interval doubles and every other checkpoint goes. Call before start().
    void setCheckpointBudget(std::size_t intervalFrames, std::size_t budgetBytes);
    // Frames that have a checkpoint, and the bytes they hold (for tests and the status).
    std::vector<std::size_t> checkpointFrames() const;
    std::size_t checkpointBytes() const;
    // Called on the runner thread just before it builds a World for a run from frame 0:
    // tests hold a build there to show that a run asked for meanwhile does not wait for
    // it. Set it while no World is being built (before start(), or once the run's first
    // frame has come): the runner reads it without a lock.
    void setBuildGate(std::function<void()> gate) { m_buildGate = std::move(gate); }
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
    // Stops any run and computes the recorded frames 1..recordedFrames-1 again from the
    // checkpoints, each span with the scene it was recorded with, recording the node
    // values of the agent with id `agentId` (wherever it is in each span's World): the
    // batches carry values only (Batch::frames empty) for those frames. Then the run goes
    // on from the last recorded frame as a live run (frames and values, pickBrainAgent).
    void replayBrainValues(sim::AgentId agentId, std::size_t recordedFrames);

    // The agents whose steering annotations (World::describeAgent) are recorded with each
    // frame computed from now on; empty = nobody. Any thread.
    void watchAgents(std::vector<sim::AgentId> ids) { m_watch.set(std::move(ids)); }
    std::vector<sim::AgentId> watchedAgents() const { return m_watch.ids(); }
    // Frame `frame`, recorded already, is computed again from the checkpoint at or before
    // it and the watched agents are described there; a later batch carries it. For frames
    // recorded before the agents were watched. Served between steps of the live run. Any thread.
    void describeFrame(std::size_t frame);

    // The watched agents' annotations on one frame.
    struct FrameSteering {
        std::size_t frame = 0;
        std::vector<sim::AgentDebug> agents;
    };

    struct Batch {
        // Set with frame 0, and with the first batch of a resumed run (the edited World's
        // agents from resumedAt on; previous[i]: agent i's index in the World that
        // recorded frame resumedAt before the edit, -1 = new).
        std::vector<sim::AgentInfo> agents;
        std::vector<std::int32_t> previous;
        float fps = 24.0f;
        std::vector<sim::AgentFrame> frames; // frame-major, agents.size() per frame
        std::size_t frameCount = 0;
        std::string error;                   // the World could not be built
        // Set with frame 0 of a run that starts (or starts over): the frames before are
        // gone, `agents` are the run's (none for a World without agents).
        bool started = false;
        // Per frame of `frames`: the picked agent's brain node values (see pickBrainAgent).
        std::vector<PickedBrainValues> brainValues;
        // The watched agents' annotations, by frame (frames of this batch and described ones).
        std::vector<FrameSteering> steering;
        // Set on the first batch of a resumed run: its frames start at resumedAt (that
        // frame recorded again from the edited World) and frames 0..resumedAt - 1 of the
        // recording stay. 0 otherwise.
        std::size_t resumedAt = 0;
    };
    // Moves out what was computed since the last call.
    Batch takeFrames();
    // Steps per second over the last run of steps; 0 when idle.
    double stepsPerSecond() const { return m_stepsPerSecond.load(); }
    bool isComputing() const { return m_computing.load(); }

private:
    struct Checkpoint {
        std::shared_ptr<const sim::Scene> scene;  // what the frames from here were simulated with
        std::shared_ptr<const sim::WorldState> state;
        bool pinned = false;                      // frame 0 and every resume point: never thinned
        // At a resume point: the state the edited scene took over and the scene it came
        // from, so that an edit at this very frame (an undo) resumes from it again.
        std::shared_ptr<const sim::Scene> beforeScene;
        std::shared_ptr<const sim::WorldState> beforeState;
    };
    struct Replay {
        bool on = false;
        sim::AgentId id = 0;
        std::size_t recordedFrames = 0;
    };
    // A run asked for and not taken up yet.
    struct Request {
        std::shared_ptr<const sim::Scene> scene;
        std::size_t resumeFrame = 0;
        Replay replay;
    };
    // Every run below is numbered (m_run when it was asked for): once another is asked
    // for, it stops at its next check and writes nothing more.
    using RunId = std::uint64_t;
    void launch(sim::Scene scene, std::size_t resumeFrame, Replay replay);
    // The runner thread: takes up the latest run asked for, one after the other.
    void work();
    // Whether run `runId` is to stop (m_mutex held).
    bool stopped(RunId runId) const { return m_quit || runId != m_run; }
    bool stoppedNow(RunId runId) const;  // the same, taking m_mutex
    void run(std::shared_ptr<const sim::Scene> scene, std::size_t resumeFrame, Replay replay, RunId runId);
    // On the runner thread: the replay's spans (values published as they are computed);
    // the World at the last recorded frame and its scene, or null when stopped.
    std::unique_ptr<sim::World> replayWorld(const Replay& replay, std::shared_ptr<const sim::Scene>& scene, RunId runId);
    // On the runner thread: the World to go on with from resumeFrame, or null to start over.
    std::unique_ptr<sim::World> resumeWorld(const std::shared_ptr<const sim::Scene>& scene, std::size_t resumeFrame,
                                            std::vector<std::int32_t>& previous, RunId runId);
    // On the runner thread: the watched agents on recorded frame `frame`, from a checkpoint.
    void describeRecorded(std::size_t frame, RunId runId);
    void keepCheckpoint(std::size_t frame, const std::shared_ptr<const sim::Scene>& scene, const sim::World& world,
                        bool pinned, Checkpoint before, RunId runId);

    std::function<void()> m_notify;
    std::function<void()> m_buildGate;  // setBuildGate
    std::thread m_thread;
    mutable std::mutex m_mutex;
    std::condition_variable m_wake;
    std::size_t m_target = 1;
    std::optional<Request> m_request;
    RunId m_run = 0;
    bool m_quit = false;  // the thread ends (stop)
    Batch m_pending;
    bool m_notified = false;
    std::atomic<double> m_stepsPerSecond{0.0};
    std::atomic<bool> m_computing{false};
    std::atomic<std::ptrdiff_t> m_brainAgent{-1};
    SteeringWatch m_watch;
    std::vector<std::size_t> m_describe;  // recorded frames to describe (describeFrame)
    // Written by the current run (under m_mutex); a run that resumes reads them.
    std::map<std::size_t, Checkpoint> m_checkpoints;
    std::size_t m_checkpointBytes = 0;
    std::size_t m_interval = 24;
    std::size_t m_budgetBytes = std::size_t(512) << 20;
};

}  // namespace throng::editor
