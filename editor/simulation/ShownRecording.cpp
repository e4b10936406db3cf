#include "editor/simulation/ShownRecording.h"

#include "simcore/layout/LayoutApply.h"

#include <algorithm>

namespace throng::editor {

namespace {

bool retimes(const sim::LayoutLayer& layer)
{
    return std::any_of(layer.ops.begin(), layer.ops.end(), [](const sim::LayoutOp& op) {
        return op.enabled && op.kind == sim::LayoutKind::TimeOffset;
    });
}

}  // namespace

const sim::FrameCache& ShownRecording::frames(const sim::FrameCache& recorded, const sim::Scene& scene)
{
    if (scene.layout.ops.empty()) {
        m_valid = false;
        m_messages.clear();
        return recorded;
    }
    const bool same = m_valid && scene.layout == m_layer && recorded.revision() == m_revision &&
                      recorded.agentCount() == m_recordedAgents;
    if (same && recorded.frameCount() == m_laid.frameCount() && !m_stale)
        return m_laid;
    // Grown by frames appended to one agent set: lay out only the new ones. A time offset
    // may show on an early frame what a later one recorded (or hold a pose recorded later):
    // its frames laid out so far go stale as the recording grows, so it is laid out anew
    // only once the recording has grown by a tenth (and 24 frames) since, or when asked
    // again after it stopped growing; the newest frames are exact for what is recorded.
    const std::size_t frames = recorded.frameCount();
    const bool relayDue = frames >= m_fullAt + m_fullAt / 10 + kRelayFrames;
    if (same && frames > m_laid.frameCount() && m_laid.frameCount() > 0 && recorded.agentSetChanges().size() == 1 &&
        (!retimes(m_layer) || !relayDue)) {
        const sim::LayoutEvaluator evaluator(scene, recorded);
        std::vector<sim::AgentFrame> frame;
        for (std::size_t f = m_laid.frameCount(); f < recorded.frameCount(); ++f) {
            evaluator.frame(f, frame);
            m_laid.append(frame);
        }
        m_messages = evaluator.messages();
        m_stale = retimes(m_layer);
        return m_laid;
    }
    m_laid = sim::applyLayout(scene, recorded, &m_messages);
    ++m_fullLayouts;
    m_fullAt = frames;
    m_stale = false;
    m_recordedAgents = recorded.agentCount();
    m_layer = scene.layout;
    m_revision = recorded.revision();
    m_valid = true;
    return m_laid;
}

std::vector<std::string> ShownRecording::takeNewMessages()
{
    if (m_messages == m_told)
        return {};
    m_told = m_messages;
    return m_messages;
}

}  // namespace throng::editor
