#include "editor/tools/ObstacleTool.h"

#include "editor/commands/AddSceneItemCommand.h"
#include "editor/tools/BrushOverlay.h"
#include "editor/tools/UniqueName.h"

#include <glm/geometric.hpp>


namespace throng::editor {

namespace {
constexpr float kDefaultRadiusM = 0.5f;
constexpr float kClickRadiusM = 0.1f;  // drags shorter than this are clicks
}  // namespace

float ObstacleTool::radiusTo(const ToolMouse& mouse) const
{
    if (!mouse.ground)
        return m_radiusM;
    const float r = glm::length(glm::vec2(mouse.ground->x - m_centre.x, mouse.ground->z - m_centre.z));
    return r < kClickRadiusM ? kDefaultRadiusM : r;
}

void ObstacleTool::mousePressed(const ToolMouse& mouse)
{
    if (!mouse.ground)
        return;
    m_centre = *mouse.ground;
    m_radiusM = kDefaultRadiusM;
    setState(State::Dragging);
    emit overlayChanged();
}

void ObstacleTool::mouseMoved(const ToolMouse& mouse)
{
    if (state() != State::Dragging)
        return;
    m_radiusM = radiusTo(mouse);
    emit overlayChanged();
}

void ObstacleTool::mouseReleased(const ToolMouse& mouse)
{
    if (state() != State::Dragging)
        return;
    m_radiusM = radiusTo(mouse);
    setState(State::Idle);
    sim::Obstacle obstacle;
    obstacle.name = uniqueName(document().scene().obstacles, "obstacle");
    obstacle.center = {m_centre.x, m_centre.z};
    obstacle.radiusM = m_radiusM;
    const QString text = tr("Add obstacle %1").arg(QString::fromStdString(obstacle.name));
    document().undoStack()->push(
        new AddSceneItemCommand<sim::Obstacle>(document(), &sim::Scene::obstacles, std::move(obstacle), text));
    emit overlayChanged();
}

void ObstacleTool::drawOverlay(QPainter& painter) const
{
    if (state() == State::Dragging)
        drawBrushCircle(painter, viewport(), m_centre, m_radiusM, QColor(200, 140, 255));
}

}  // namespace throng::editor
