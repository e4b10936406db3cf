#pragma once
// The recording as the editor shows it: the simulation's frames, or, when the scene has a
// layout layer, those frames through it (sim::LayoutEvaluator). Keeps the laid-out copy
// while the layer and the recording stay the same, and extends it frame by frame while the
// recording grows. A layer with a time offset, whose early frames may show later ones, is
// laid out anew only as the recording grows by a tenth, and once more when asked after it
// stopped growing: a live run costs a few whole layouts, not one per frame. Holds no Qt
// state.

#include "simcore/layout/LayoutLayer.h"
#include "simcore/scene/Scene.h"
#include "simcore/world/FrameCache.h"

#include <cstdint>
#include <string>
#include <vector>

namespace throng::editor {

class ShownRecording {
public:
    // The frames to show of `recorded`, a recording of `scene`: `recorded` itself when the
    // scene has no layout layer. Valid until the next call.
    const sim::FrameCache& frames(const sim::FrameCache& recorded, const sim::Scene& scene);
    // What the layer's selections say (operations that select nobody, ids the recording
    // lacks) since the last call, once each time they change; empty otherwise.
    std::vector<std::string> takeNewMessages();
    // How many times the whole recording was laid out (the rest: frame by frame).
    std::size_t fullLayouts() const { return m_fullLayouts; }
    // A retiming layer is laid out anew once the recording grew by this many frames and a tenth.
    static constexpr std::size_t kRelayFrames = 24;

private:
    sim::FrameCache m_laid;
    sim::LayoutLayer m_layer;
    std::uint64_t m_revision = 0;
    std::size_t m_recordedAgents = 0;  // the recording's width when laid out (copies widen m_laid)
    std::size_t m_fullAt = 0;          // the recording's frames at the last whole layout
    std::size_t m_fullLayouts = 0;
    bool m_stale = false;              // a retiming layer extended since its last whole layout
    bool m_valid = false;
    std::vector<std::string> m_messages, m_told;
};

}  // namespace throng::editor
