#include "editor/tools/GoalTool.h"

#include "editor/SceneDocument.h"
#include "editor/commands/AddSceneItemCommand.h"
#include "editor/tools/UniqueName.h"

#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QLabel>

namespace throng::editor {

void GoalTool::place(glm::vec2 centre, float radiusM)
{
    sim::Goal goal;
    goal.name = uniqueName(document().scene().goals, "goal");
    goal.position = centre;
    goal.radiusM = radiusM;
    const QString text = tr("Add goal %1").arg(QString::fromStdString(goal.name));
    addAndSelect(document(), &sim::Scene::goals, std::move(goal), text);
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
