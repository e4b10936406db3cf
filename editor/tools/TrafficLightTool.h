#pragma once
// Places a traffic signal with a click: default phases (green 20 s, yellow 3 s, red
// 23 s); its stop lines are the lanes and crosswalks within reach of the click that no
// other signal controls yet. A click on a signal selects it; Ctrl+click on a lane or
// crosswalk then attaches a stop line there to the selected signal, or detaches it.
// Phases are edited in the properties panel. Every change is one undo step.

#include "editor/tools/ViewportTool.h"

#include <glm/vec2.hpp>

namespace throng::editor {

class TrafficLightTool : public ViewportTool {
    Q_OBJECT

public:
    using ViewportTool::ViewportTool;

    QString name() const override { return tr("Traffic Light"); }
    QString toolTip() const override
    {
        return tr("Traffic Light (L): click to place a signal (nearby free crosswalks and lanes get stop lines); click a "
                  "signal to select it, then Ctrl+click a lane or crosswalk to attach or detach a stop line");
    }
    QKeySequence shortcut() const override { return QKeySequence(Qt::Key_L); }
    QString objectKey() const override { return QStringLiteral("trafficLight"); }

    void mouseReleased(const ToolMouse& mouse) override;
    QString statusText() const override { return m_status.isEmpty() ? toolTip() : m_status; }

    // Stop lines reach crosswalks and lane points this close to the signal, m.
    static constexpr float kReachM = 12.0f;
    // A click this close to a signal head picks it, in pixels.
    static constexpr double kPickPx = 12.0;

private:
    void placeLight(glm::vec2 at);
    void toggleStopLine(std::size_t light, glm::vec2 at);

    QString m_status;
};

}  // namespace throng::editor
