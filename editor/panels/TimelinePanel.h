#pragma once
// The timeline dock: a scrub bar over the shot with its computed frames (TimelineRuler),
// Restart, Step, Play/Pause and Loop, a frame field, the timecode and the playback mode
// (remembered in QSettings). Drives a SimulationController; holds no frames.

#include "editor/panels/TimelineRuler.h"

#include <QWidget>

#include <cstddef>

class QComboBox;
class QLabel;
class QSpinBox;
class QToolButton;

namespace throng::editor {

class SimulationController;

class TimelinePanel : public QWidget {
    Q_OBJECT

public:
    TimelinePanel(SimulationController& controller, QWidget* parent = nullptr);

    TimelineRuler* scrubBar() const { return m_scrub; }


private:
    QWidget* makeControls();
    void pickPlaybackMode(int index);
    void refresh();

    SimulationController& m_controller;
    TimelineRuler* m_scrub = nullptr;
    QToolButton* m_play = nullptr;
    QSpinBox* m_frameField = nullptr;
    QLabel* m_timecodeLabel = nullptr;
    QLabel* m_frameLabel = nullptr;
    QComboBox* m_modeBox = nullptr;
};

}  // namespace throng::editor
