#include "editor/simulation/SimulateToEndDialog.h"

#include "editor/simulation/SimulationController.h"

namespace throng::editor {

SimulateToEndDialog::SimulateToEndDialog(SimulationController& controller, QWidget* parent)
    : QProgressDialog(parent), m_controller(controller)
{
    setObjectName("simulateToEndDialog");
    setWindowTitle(tr("Simulate to End"));
    setWindowModality(Qt::WindowModal);
    setAttribute(Qt::WA_DeleteOnClose);
    setAutoClose(false);
    setAutoReset(false);
    setMinimumDuration(0);
    setCancelButtonText(tr("Cancel"));
    setRange(0, int(controller.totalFrames()));
    connect(&controller, &SimulationController::recordedChanged, this, &SimulateToEndDialog::progress);
    connect(this, &QProgressDialog::canceled, this, [this] {
        m_controller.stopRecording();
        close();
    });
    controller.simulateToEnd();
    progress(controller.recordedFrames());
    // At once, not when QProgressDialog's own timer or estimate decides to.
    if (isHidden() && controller.recordedFrames() < controller.totalFrames())
        show();
}

void SimulateToEndDialog::progress(std::size_t recordedFrames)
{
    setValue(int(recordedFrames));
    setLabelText(tr("Recorded frame %1 of %2 (%3 steps/s)")
                     .arg(recordedFrames)
                     .arg(m_controller.totalFrames())
                     .arg(m_controller.stepsPerSecond(), 0, 'f', 0));
    if (recordedFrames >= m_controller.totalFrames())
        close();
}

}  // namespace throng::editor
