#include "editor/tools/ActionPointTool.h"

#include "editor/ComboTypeAhead.h"
#include "editor/SceneDocument.h"
#include "editor/commands/AddSceneItemCommand.h"
#include "editor/tools/UniqueName.h"
#include "simcore/scene/Clip.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QLabel>

#include <cmath>

namespace throng::editor {

void ActionPointTool::place(glm::vec2 centre, float radiusM)
{
    sim::ActionPoint point;
    point.name = uniqueName(document().scene().actionPoints, "action_point");
    point.position = centre;
    point.radiusM = radiusM;
    point.action = m_action;
    point.durationS = m_durationS;
    if (const std::optional<float> heading = dragHeadingDeg()) {
        point.faces = true;
        point.facingDeg = std::round(*heading);  // whole degrees: what a user would type
    }
    const QString text = tr("Add action point %1").arg(QString::fromStdString(point.name));
    addAndSelect(document(), &sim::Scene::actionPoints, std::move(point), text);
}

QWidget* ActionPointTool::createOptionsWidget(QWidget* parent)
{
    auto* box = new QWidget(parent);
    auto* row = new QHBoxLayout(box);
    row->setContentsMargins(4, 0, 4, 0);
    auto* action = new QComboBox(box);
    action->setObjectName("actionPointClip");
    for (int c = int(sim::Clip::Wait); c < sim::kClipCount; ++c)
        action->addItem(QString::fromUtf8(sim::toString(sim::Clip(c))));
    action->setCurrentText(QString::fromStdString(m_action));
    action->setToolTip(tr("What walkers play at the point"));
    keepTypedLetters(action);
    connect(action, &QComboBox::currentTextChanged, this, [this](const QString& t) { m_action = t.toStdString(); });
    auto* duration = new QDoubleSpinBox(box);
    duration->setObjectName("actionPointDuration");
    duration->setRange(0.1, 3600.0);
    duration->setValue(double(m_durationS));
    duration->setSuffix(tr(" s"));
    duration->setToolTip(tr("How long walkers play the action there before they go on"));
    connect(duration, &QDoubleSpinBox::valueChanged, this, [this](double v) { m_durationS = float(v); });
    auto* radius = new QDoubleSpinBox(box);
    radius->setObjectName("actionPointRadius");
    radius->setRange(0.1, 100.0);
    radius->setValue(double(m_defaultRadiusM));
    radius->setSuffix(tr(" m"));
    radius->setToolTip(tr("Radius of an action point placed with a click"));
    connect(radius, &QDoubleSpinBox::valueChanged, this, [this](double v) { m_defaultRadiusM = float(v); });
    row->addWidget(new QLabel(tr("Action"), box));
    row->addWidget(action);
    row->addWidget(new QLabel(tr("Duration"), box));
    row->addWidget(duration);
    row->addWidget(new QLabel(tr("Radius"), box));
    row->addWidget(radius);
    return box;
}

}  // namespace throng::editor
