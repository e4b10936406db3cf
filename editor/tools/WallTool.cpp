#include "editor/tools/WallTool.h"

#include "editor/commands/AddSceneItemCommand.h"
#include "editor/tools/UniqueName.h"

namespace throng::editor {

void WallTool::add(const std::vector<glm::vec2>& points)
{
    sim::Wall wall{uniqueName(document().scene().walls, "wall"), points};
    const QString text = tr("Add wall %1").arg(QString::fromStdString(wall.name));
    addAndSelect(document(), &sim::Scene::walls, std::move(wall), text);
}

}  // namespace throng::editor
