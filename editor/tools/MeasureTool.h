#pragma once
// Draws a measurement for the analysis of a run: in Line mode, press where the line
// starts, drag and release where it ends (walkers crossing it are counted); in Area mode,
// drag a rectangle (the density and speed of the walkers inside are measured). The preview
// stays in the tool; the release pushes one AddMeasurement step, Escape drops it. A
// measurement changes nothing in the run, so drawing one keeps the recorded frames.

#include "editor/tools/ViewportTool.h"

#include "simcore/scene/Scene.h"

#include <glm/vec2.hpp>

namespace throng::editor {

class MeasureTool : public ViewportTool {
    Q_OBJECT

public:
    using ViewportTool::ViewportTool;

    QString name() const override { return tr("Measure"); }
    QString toolTip() const override
    {
        return tr("Measure (U): drag a line to count the walkers crossing it, or (Area) a rectangle to measure their "
                  "density and speed; see them in the Analysis panel");
    }
    QKeySequence shortcut() const override { return QKeySequence(Qt::Key_U); }
    QString objectKey() const override { return QStringLiteral("measure"); }

    void mousePressed(const ToolMouse& mouse) override;
    void mouseMoved(const ToolMouse& mouse) override;
    void mouseReleased(const ToolMouse& mouse) override;
    void cancel() override;
    void drawOverlay(QPainter& painter) const override;
    QWidget* createOptionsWidget(QWidget* parent) override;

    sim::MeasurementShape shape() const { return m_shape; }
    void setShape(sim::MeasurementShape shape) { m_shape = shape; }

    // A drag shorter than this (a line) or narrower than this (an area) draws nothing, m.
    static constexpr float kMinimumM = 0.2f;

private:
    void place();

    sim::MeasurementShape m_shape = sim::MeasurementShape::Line;
    glm::vec2 m_from{0.0f}, m_to{0.0f};
};

}  // namespace throng::editor
