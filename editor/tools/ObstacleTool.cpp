#include "editor/tools/ObstacleTool.h"

#include "editor/SceneDocument.h"
#include "editor/commands/AddSceneItemCommand.h"
#include "editor/tools/UniqueName.h"

namespace throng::editor {

void ObstacleTool::place(glm::vec2 centre, float radiusM)
{
    sim::Obstacle obstacle;
    obstacle.name = uniqueName(document().scene().obstacles, "obstacle");
    obstacle.center = centre;
    obstacle.radiusM = radiusM;
    const QString text = tr("Add obstacle %1").arg(QString::fromStdString(obstacle.name));
    addAndSelect(document(), &sim::Scene::obstacles, std::move(obstacle), text);
}

}  // namespace throng::editor
