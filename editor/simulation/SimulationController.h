#pragma once
// Live simulation for the editor: runs the document's scene on a SimulationRunner
// thread into a FrameCache and plays, pauses, steps, loops and scrubs it. An edit the
// simulation reads (applyEdit) invalidates the recorded frames after the shown one: the
// edited scene runs on from the shown frame's state (simcore/world/WorldState.h has the
// rule). Never draws, never edits the scene, and never builds a World on the GUI thread
// nor waits for one being built.

#include "editor/SceneChange.h"
#include "editor/simulation/SimulationRunner.h"
#include "editor/simulation/SteeringRecord.h"
#include "simcore/scene/Scene.h"
#include "simcore/world/FrameCache.h"

#include <QElapsedTimer>
#include <QObject>
#include <QTimer>

#include <algorithm>
#include <cstddef>
#include <functional>
#include <optional>

namespace throng::editor {

class SimulationController : public QObject {
    Q_OBJECT

public:
    explicit SimulationController(QObject* parent = nullptr);
    ~SimulationController() override;

    // A new scene to simulate (opened, new, reverted): every recorded frame is dropped and
    // the runner starts over at frame 0 (its first batch brings frame 0). Playing goes on.
    void setScene(const sim::Scene& scene);
    // The document's scene after an edit, and what the edit changed (for a burst of edits
    // between two refreshes, the union of their changes). An edit the simulation does not
    // read (change.simulationReads false: a placed agent's look, a name nothing refers
    // to) keeps every recorded frame, the runner and the playback as they are. Otherwise,
    // at a later shown frame f, frames 0..f stay and the frames after it are recomputed
    // with the edited scene from frame f's state; playback goes on. An edit may add or
    // remove agents (the cache then keeps both sets: the frames before show the old
    // crowd). At frame 0 the run starts over as setScene's does. When the runner cannot
    // resume the edit (the settings changed: fps, duration, seed, bounds, navigation
    // cell) it starts over too: frames dropped, playback paused at frame 0.
    void applyEdit(const sim::Scene& scene, const SceneChange& change);

    // RealTime: the shown frame follows the wall clock at the scene's fps, skipping the
    // frames the display cannot keep up with. EveryFrame: each frame is shown in turn, at
    // most at the scene's fps, later when its computation lags.
    enum class PlaybackMode { RealTime, EveryFrame };
    void setPlaybackMode(PlaybackMode mode);
    PlaybackMode playbackMode() const { return m_mode; }

    void play();
    void pause();
    void togglePlay() { m_playing ? pause() : play(); }
    void stepForward();
    void stepBackward();
    void restart();
    // Pauses at the last recorded frame.
    void showLastRecorded();
    void setLoop(bool loop) { m_loop = loop; }
    // Shows frame `frame` of the shot (clamped to its last frame). A frame not recorded
    // yet is computed first, in the background: the shown frame follows the recording up
    // to it (seekTarget() until it is shown).
    void seek(std::size_t frame);
    std::optional<std::size_t> seekTarget() const { return m_seekTarget; }
    // Records every frame of the scene's duration in the background.
    void simulateToEnd();
    // Stops recording ahead: frames already recorded stay (Cancel of Simulate to End).
    void stopRecording() { m_runner.stopAhead(); }
    // Records frames in the background until `frameCount` exist (export asks for these).
    void requestFrames(std::size_t frameCount) { m_runner.setTarget(std::min(frameCount, m_totalFrames)); }

    bool isPlaying() const { return m_playing; }
    bool loops() const { return m_loop; }
    std::size_t currentFrame() const { return m_current; }
    std::size_t recordedFrames() const { return m_cache.frameCount(); }
    // Frames of the whole duration, frame 0 included.
    std::size_t totalFrames() const { return m_totalFrames; }
    double fps() const { return m_fps; }
    const sim::FrameCache& cache() const { return m_cache; }
    // A reader of cache() on another thread (the Analysis dock's). While one is set, the
    // cache stays as it is: frames the runner records wait in the runner, and before an
    // edit or a new scene changes the recorded frames, `stop` is called, which returns once
    // the reader no longer reads (the reader is then cleared). The destructor stops it too.
    void setCacheReader(std::function<void()> stop);
    // The reader is done: the frames that waited are taken. Nothing when none is set.
    void clearCacheReader();
    bool hasCacheReader() const { return static_cast<bool>(m_cacheReader); }
    double stepsPerSecond() const { return m_runner.stepsPerSecond(); }
    // The brain editor's live view: the simulation records agent `agent`'s (dense index)
    // brain node values with every frame it computes; -1 = nobody. Frames recorded before
    // the pick are computed again in the background from the checkpoints, each span with
    // the scene it was recorded with (the same frames: the World is deterministic), to
    // record its values; brainValuesChanged() tells when they arrive.
    void pickBrainAgent(std::ptrdiff_t agent);
    // Agent `agent`'s node values recorded with frame `frame`; null when that frame was
    // computed with another agent picked (or not yet), or at frame 0 (no step yet).
    const std::vector<sim::BrainNodeValue>* brainValues(std::size_t frame, std::ptrdiff_t agent) const;
    // Steering annotations (World::describeAgent) of the agents `ids` (the selection): the
    // frames computed from now on carry them, and a shown frame recorded without them is
    // computed again in the background (steeringChanged() tells when it arrives).
    void watchAgents(std::vector<sim::AgentId> ids);
    // The watched agents' annotations on frame `frame`; empty when none were recorded, or
    // only for agents no longer watched.
    std::vector<sim::AgentDebug> steering(std::size_t frame) const { return m_steering.watchedAt(frame); }
    // The edit frame of the last resumed run the runner handed frames of (0: none yet), and
    // how many runs have started over from frame 0 (for tests and the status).
    std::size_t lastResumedAt() const { return m_lastResumedAt; }
    std::size_t restarts() const { return m_restarts; }
    const SimulationRunner& runner() const { return m_runner; }
    SimulationRunner& runner() { return m_runner; }

signals:
    // Frame `frame` of cache() is the one to show.
    void frameChanged(std::size_t frame);
    void recordedChanged(std::size_t recordedFrames);
    void playingChanged(bool playing);
    // Node values of frames already shown arrived (after pickBrainAgent).
    void brainValuesChanged();
    // Steering annotations of the shown frame arrived (after watchAgents).
    void steeringChanged();
    // The scene could not be simulated (a World could not be built from it).
    void problem(const QString& message);

private:
    void takeFrames();
    void tick();
    void tickRealTime();
    void startClock();
    void applyTimerInterval();
    void setCurrent(std::size_t frame);
    // Asks for the shown frame's annotations when it was recorded without them (paused).
    void describeShown();
    // Takes the scene's frame rate and duration.
    void takeTiming(const sim::Scene& scene);
    // Drops every frame and runs `scene` from frame 0; playing goes on from there.
    void startOver(const sim::Scene& scene);
    // Stops and clears the cache's reader, if one is set, before the cache changes.
    void stopCacheReader();

    SimulationRunner m_runner;
    bool m_hasScene = false;
    sim::FrameCache m_cache;
    std::function<void()> m_cacheReader;  // stops the reader of m_cache; empty = none
    std::vector<SimulationRunner::PickedBrainValues> m_brainValues;  // per recorded frame
    SteeringRecord m_steering;
    std::size_t m_runFrames = 0;  // frame index of the next frame the runner hands over
    bool m_replaying = false;     // the runner recomputes recorded frames for brain values
    std::ptrdiff_t m_replayAgent = -1;  // the cache agent a replay records values of
    std::size_t m_lastResumedAt = 0;
    std::size_t m_restarts = 0;
    QTimer m_timer;
    std::size_t m_current = 0;
    std::size_t m_totalFrames = 1;
    double m_fps = 24.0;
    PlaybackMode m_mode = PlaybackMode::RealTime;
    // Real time: the frame shown when m_clock started.
    QElapsedTimer m_clock;
    std::size_t m_clockFrame = 0;
    std::optional<std::size_t> m_seekTarget;
    bool m_playing = false;
    bool m_loop = false;
    bool m_stepPending = false;
};

}  // namespace throng::editor
