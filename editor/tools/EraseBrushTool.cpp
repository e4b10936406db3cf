#include "editor/tools/EraseBrushTool.h"

#include "editor/SceneDocument.h"
#include "editor/commands/EraseAgentsCommand.h"

#include <glm/geometric.hpp>

#include <QHBoxLayout>

namespace throng::editor {

namespace {
int g_nextEraseStrokeId = 1;
constexpr float kEraseBrushRadiusM = 2.0f;
}  // namespace

EraseBrushTool::EraseBrushTool(SceneDocument& document, Viewport& viewport, QObject* parent)
    : BrushTool(document, viewport, kEraseBrushRadiusM, parent)
{
}

void EraseBrushTool::strokeBegan(glm::vec2 point)
{
    m_strokeId = g_nextEraseStrokeId++;
    dab(point);
}

void EraseBrushTool::dab(glm::vec2 centre)
{
    std::vector<std::size_t> hit;
    const auto& agents = document().scene().agents;
    for (std::size_t i = 0; i < agents.size(); ++i)
        if (glm::length(glm::vec2(agents[i].position.x, agents[i].position.z) - centre) <= radiusM())
            hit.push_back(i);
    if (!hit.empty())
        document().undoStack()->push(new EraseAgentsCommand(document(), std::move(hit), m_strokeId));
}

QWidget* EraseBrushTool::createOptionsWidget(QWidget* parent)
{
    auto* box = new QWidget(parent);
    auto* row = new QHBoxLayout(box);
    row->setContentsMargins(4, 0, 4, 0);
    addRadiusOption(box, row, "eraseRadius");
    return box;
}

}  // namespace throng::editor
