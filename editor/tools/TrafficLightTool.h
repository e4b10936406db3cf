#pragma once
// Places a traffic signal with a click: default phases (green 20 s, yellow 3 s, red
// 23 s); its stop lines are the lanes and crosswalks within reach of the click that no
// other signal controls yet.

#include "editor/tools/ViewportTool.h"

namespace throng::editor {

class TrafficLightTool : public ViewportTool {
    Q_OBJECT

public:
    using ViewportTool::ViewportTool;

    QString name() const override { return tr("Traffic Light"); }
    QString toolTip() const override
    {
        return tr("Traffic Light (L): click to place a signal; free nearby crosswalks and lanes get its stop lines");
    }
    QKeySequence shortcut() const override { return QKeySequence(Qt::Key_L); }
    QString objectKey() const override { return QStringLiteral("trafficLight"); }

    void mouseReleased(const ToolMouse& mouse) override;

    // Stop lines reach crosswalks and lane points this close to the signal, m.
    static constexpr float kReachM = 12.0f;
};

}  // namespace throng::editor
