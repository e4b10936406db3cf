#include "editor/tools/PathTool.h"

#include "editor/commands/AddSceneItemCommand.h"
#include "editor/tools/UniqueName.h"

#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QLabel>

namespace throng::editor {

void PathTool::add(const std::vector<glm::vec2>& points)
{
    sim::Path path{uniqueName(document().scene().paths, "path"), points, m_radiusM, false};
    const QString text = tr("Add path %1").arg(QString::fromStdString(path.name));
    addAndSelect(document(), &sim::Scene::paths, std::move(path), text);
}

QWidget* PathTool::createOptionsWidget(QWidget* parent)
{
    auto* box = new QWidget(parent);
    auto* row = new QHBoxLayout(box);
    row->setContentsMargins(4, 0, 4, 0);
    auto* spin = new QDoubleSpinBox(box);
    spin->setObjectName("pathRadius");
    spin->setRange(0.1, 50.0);
    spin->setValue(double(m_radiusM));
    spin->setToolTip(tr("How far from the centre line followers may stray, in metres"));
    connect(spin, &QDoubleSpinBox::valueChanged, this, [this](double v) { m_radiusM = float(v); });
    row->addWidget(new QLabel(tr("Radius"), box));
    row->addWidget(spin);
    return box;
}

}  // namespace throng::editor
