#include "editor/layout/LayoutCheckWatch.h"

#include "editor/SceneDocument.h"
#include "editor/simulation/ShownRecording.h"
#include "editor/simulation/SimulationController.h"

#include <QTimer>

namespace throng::editor {

LayoutCheckWatch::LayoutCheckWatch(SceneDocument& document, SimulationController& simulation, ShownRecording& shown,
                                   QObject* parent)
    : QObject(parent), m_document(document), m_simulation(simulation), m_shown(shown)
{
    m_timer = new QTimer(this);
    m_timer->setSingleShot(true);
    m_timer->setInterval(kSettleMs);
    connect(m_timer, &QTimer::timeout, this, &LayoutCheckWatch::checkIfSmall);
    connect(&m_document, &SceneDocument::sceneReset, this, &LayoutCheckWatch::schedule);
    connect(&m_document, &SceneDocument::sceneChanged, this, [this](const SceneChange& change) {
        // The layer itself, or what the check reads of the scene: walls and the types' radii.
        if (change.touches(ItemKind::LayoutOp) || change.touches(ItemKind::Wall) || change.touches(ItemKind::AgentType))
            schedule();
    });
    connect(&m_simulation, &SimulationController::recordedChanged, this, &LayoutCheckWatch::schedule);
}

void LayoutCheckWatch::schedule()
{
    const bool layered = !m_document.scene().layout.ops.empty();
    // Nothing to check and nothing shown from before: stay idle while a run records.
    if (!layered && m_last.overlaps.empty() && m_last.wallCrossings.empty() && !m_timer->isActive())
        return;
    m_timer->start();
}

void LayoutCheckWatch::checkIfSmall()
{
    const sim::Scene& scene = m_document.scene();
    const sim::FrameCache& recorded = m_simulation.cache();
    if (!scene.layout.ops.empty()) {
        const std::size_t agentFrames = recorded.agentCount() * recorded.frameCount();
        if (agentFrames > m_automaticLimit) {
            m_last = {};
            emit skipped(agentFrames);
            return;
        }
    }
    checkNow();
}

void LayoutCheckWatch::checkNow()
{
    m_timer->stop();
    const sim::Scene& scene = m_document.scene();
    const sim::FrameCache& recorded = m_simulation.cache();
    if (scene.layout.ops.empty() || recorded.frameCount() == 0) {
        m_last = {};
    } else {
        const sim::FrameCache& laid = m_shown.frames(recorded, scene);
        m_last = sim::checkLayout(scene, recorded, laid);
    }
    emit checked(m_last);
}

}  // namespace throng::editor
