#pragma once
// "Simulate to End": a window-modal progress dialog while the controller records every
// frame of the scene's duration in the background; Cancel stops the recording and keeps
// the frames already made. Closes itself when the last frame is recorded. Never edits
// the scene.

#include <QProgressDialog>

namespace throng::editor {

class SimulationController;

class SimulateToEndDialog : public QProgressDialog {
    Q_OBJECT

public:
    // Starts the recording; the dialog deletes itself when closed.
    SimulateToEndDialog(SimulationController& controller, QWidget* parent);

private:
    void progress(std::size_t recordedFrames);

    SimulationController& m_controller;
};

}  // namespace throng::editor
