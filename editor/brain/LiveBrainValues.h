#pragma once
// The picked agent's brain node values at a recorded frame, for the live view. Runs its
// own World of the same scene on the GUI thread (same seed, so the same frames the
// playback shows), picked on that agent, stepping forward as playback advances and
// starting over when the user scrubs back. Never touches the playback's World.

#include "simcore/brain/BrainEvaluator.h"
#include "simcore/scene/Scene.h"

#include <cstddef>
#include <memory>
#include <vector>

namespace throng::sim {
class World;
}

namespace throng::editor {

class LiveBrainValues {
public:
    LiveBrainValues();
    ~LiveBrainValues();

    // The scene to follow (kept by reference: the document's, which outlives this; read
    // only when the World is rebuilt); the values computed so far are dropped.
    void setScene(const sim::Scene& scene);
    // The World agent (dense index, as the FrameCache orders agents); -1 = nobody.
    void pick(std::ptrdiff_t agent);
    std::ptrdiff_t picked() const { return m_agent; }
    // The picked agent's type index (Scene::agentTypes), -1 when nobody is picked.
    int pickedType() const { return m_type; }
    // The picked agent's node values after `frame` steps; empty at frame 0, when nobody
    // is picked or when its type has no running brain.
    const std::vector<sim::BrainNodeValue>& valuesAt(std::size_t frame);

private:
    void restart();

    const sim::Scene* m_scene = nullptr;
    std::unique_ptr<sim::World> m_world;
    std::size_t m_step = 0;
    std::ptrdiff_t m_agent = -1;
    int m_type = -1;
    std::vector<sim::BrainNodeValue> m_values;
};

}  // namespace throng::editor
