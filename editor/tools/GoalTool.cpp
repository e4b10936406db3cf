#include "editor/tools/GoalTool.h"

#include "editor/SceneDocument.h"
#include "editor/commands/AddSceneItemCommand.h"
#include "editor/tools/BrushOverlay.h"
#include "editor/tools/UniqueName.h"

#include <glm/geometric.hpp>

#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QLabel>

namespace throng::editor {

namespace {
constexpr float kClickRadiusM = 0.3f;  // drags shorter than this are clicks
}

float GoalTool::radiusTo(const ToolMouse& mouse) const
{
    if (!mouse.ground)
        return m_dragRadiusM;
    const float r = glm::length(glm::vec2(mouse.ground->x - m_centre.x, mouse.ground->z - m_centre.z));
    return r < kClickRadiusM ? m_defaultRadiusM : r;
}

void GoalTool::mousePressed(const ToolMouse& mouse)
{
    if (!mouse.ground)
        return;
    m_centre = *mouse.ground;
    m_dragRadiusM = m_defaultRadiusM;
    setState(State::Dragging);
    emit overlayChanged();
}

void GoalTool::mouseMoved(const ToolMouse& mouse)
{
    if (state() != State::Dragging)
        return;
    m_dragRadiusM = radiusTo(mouse);
    emit overlayChanged();
}

void GoalTool::mouseReleased(const ToolMouse& mouse)
{
    if (state() != State::Dragging)
        return;
    m_dragRadiusM = radiusTo(mouse);
    setState(State::Idle);
    sim::Goal goal;
    goal.name = uniqueName(document().scene().goals, "goal");
    goal.position = {m_centre.x, m_centre.z};
    goal.radiusM = m_dragRadiusM;
    const QString text = tr("Add goal %1").arg(QString::fromStdString(goal.name));
    document().undoStack()->push(new AddSceneItemCommand<sim::Goal>(document(), &sim::Scene::goals, std::move(goal), text));
    emit overlayChanged();
}

void GoalTool::drawOverlay(QPainter& painter) const
{
    if (state() == State::Dragging)
        drawBrushCircle(painter, viewport(), m_centre, m_dragRadiusM, QColor(100, 230, 140));
}

QWidget* GoalTool::createOptionsWidget(QWidget* parent)
{
    auto* box = new QWidget(parent);
    auto* row = new QHBoxLayout(box);
    row->setContentsMargins(4, 0, 4, 0);
    auto* spin = new QDoubleSpinBox(box);
    spin->setObjectName("goalRadius");
    spin->setRange(0.1, 100.0);
    spin->setValue(double(m_defaultRadiusM));
    spin->setToolTip(tr("Arrival radius of a goal placed with a click, in metres"));
    connect(spin, &QDoubleSpinBox::valueChanged, this, [this](double v) { m_defaultRadiusM = float(v); });
    row->addWidget(new QLabel(tr("Radius"), box));
    row->addWidget(spin);
    return box;
}

}  // namespace throng::editor
