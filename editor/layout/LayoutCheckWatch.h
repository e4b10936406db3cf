#pragma once
// Keeps the layout check (sim::checkLayout) of the shown recording current: after each
// edit of the layout layer, a new scene, or frames recorded, it checks the recording
// against the same frames through the layer, once the edits and frames stop coming for a
// moment, and says what it found. The GUI thread runs it: it reads only frames already
// recorded and costs what the edited agents' neighbourhoods cost.

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
    // Checks now (a pending check is dropped) and emits checked().
    void checkNow();
    const sim::LayoutCheck& last() const { return m_last; }
    // How long edits and frames must pause before the check runs, ms.
    static constexpr int kSettleMs = 250;

signals:
    void checked(const sim::LayoutCheck& check);

private:
    void schedule();

    SceneDocument& m_document;
    SimulationController& m_simulation;
    ShownRecording& m_shown;
    QTimer* m_timer = nullptr;
    sim::LayoutCheck m_last;
};

}  // namespace throng::editor
