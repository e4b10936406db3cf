#pragma once
// Keeps the layout check (sim::checkLayout) of the shown recording current: after each
// edit of the layout layer, a new scene, or frames recorded, it checks the recording
// against the same frames through the layer, once the edits and frames stop coming for a
// moment, and says what it found. The GUI thread runs it: it reads only frames already
// recorded and costs what the edited agents' neighbourhoods cost, so on a shot too large
// to check in a moment it does not run by itself: it says so (skipped()), and checkNow()
// runs it when the user asks.

#include "editor/SceneChange.h"
#include "simcore/layout/LayoutCheck.h"

#include <QObject>

class QTimer;

namespace throng::editor {

class SceneDocument;
class ShownRecording;
class SimulationController;

class LayoutCheckWatch : public QObject {
    Q_OBJECT

public:
    LayoutCheckWatch(SceneDocument& document, SimulationController& simulation, ShownRecording& shown,
                     QObject* parent = nullptr);
    // Checks now, whatever the shot's size (a pending check is dropped), and emits checked().
    void checkNow();
    // Laid-out agent-frames above which the check waits to be asked (about a second's work).
    void setAutomaticLimit(std::size_t agentFrames) { m_automaticLimit = agentFrames; }
    static constexpr std::size_t kAutomaticLimit = 2'000'000;
    const sim::LayoutCheck& last() const { return m_last; }
    // How long edits and frames must pause before the check runs, ms.
    static constexpr int kSettleMs = 250;

signals:
    void checked(const sim::LayoutCheck& check);
    // The edits changed, but the shot has `agentFrames` laid-out agent-frames, more than the
    // check runs by itself: what it showed is out of date until checkNow().
    void skipped(std::size_t agentFrames);

private:
    void schedule();
    void checkIfSmall();

    SceneDocument& m_document;
    SimulationController& m_simulation;
    ShownRecording& m_shown;
    QTimer* m_timer = nullptr;
    sim::LayoutCheck m_last;
    std::size_t m_automaticLimit = kAutomaticLimit;
};

}  // namespace throng::editor
