#pragma once
// Base of the brushes that edit the placed agents under a disk dragged over the ground
// (orient, variation, assign): each dab edits copies of the agents inside the disk and
// pushes one ChangeAgentsCommand; the dabs of one stroke merge into one undo step.
// Never edits the scene directly.

#include "editor/tools/ViewportTool.h"
#include "simcore/scene/Scene.h"

#include <glm/vec2.hpp>

#include <QColor>

#include <vector>

class QHBoxLayout;

namespace throng::editor {

class AgentBrushTool : public ViewportTool {
    Q_OBJECT

public:
    using ViewportTool::ViewportTool;

    void mousePressed(const ToolMouse& mouse) override;
    void mouseMoved(const ToolMouse& mouse) override;
    void mouseReleased(const ToolMouse& mouse) override;
    void cancel() override;
    void drawOverlay(QPainter& painter) const override;

    float radiusM() const { return m_radiusM; }
    void setRadiusM(float r) { m_radiusM = r; }

protected:
    // Edits `agent` for a dab at `centre`; `direction` is the stroke's unit direction over
    // the last radius of its length (zero for the first dab of a stroke). `strokeId` keys the brush's random draws. Returns
    // true when the agent changed.
    virtual bool editAgent(sim::Agent& agent, glm::vec2 centre, glm::vec2 direction, int strokeId) const = 0;
    // The history's verb ("Comb") and the colour of the disk.
    virtual QString verb() const = 0;
    virtual QColor brushColour() const = 0;
    // Adds the radius spin box (object name `<objectKey>Radius`) to an options row.
    void addRadiusOption(QWidget* box, QHBoxLayout* row);

private:
    void dab(glm::vec2 centre, glm::vec2 direction);

    float m_radiusM = 3.0f;
    std::optional<glm::vec3> m_cursor;
    glm::vec2 m_lastDab{0.0f};
    std::vector<glm::vec2> m_dabs;  // of the stroke in progress, for its direction
    int m_strokeId = 0;
};

}  // namespace throng::editor
