#pragma once
// The timeline dock: Restart, Step, Play/Pause and Loop buttons, a scrub bar over the
// recorded frames and the frame read-out. Drives a SimulationController; holds no frames.

#include <QWidget>

class QLabel;
class QSlider;
class QToolButton;

namespace throng::editor {

class SimulationController;

class TimelinePanel : public QWidget {
    Q_OBJECT

public:
    TimelinePanel(SimulationController& controller, QWidget* parent = nullptr);

    QSlider* scrubBar() const { return m_scrub; }

private:
    void refresh();

    SimulationController& m_controller;
    QToolButton* m_play = nullptr;
    QSlider* m_scrub = nullptr;
    QLabel* m_frameLabel = nullptr;
};

}  // namespace throng::editor
