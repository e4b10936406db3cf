#include "editor/tools/LaneTool.h"

#include "editor/commands/AddSceneItemCommand.h"
#include "editor/tools/UniqueName.h"

#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QLabel>

namespace throng::editor {

void LaneTool::add(const std::vector<glm::vec2>& points)
{
    sim::Lane lane;
    lane.name = uniqueName(document().scene().lanes, "lane");
    lane.points = points;
    lane.widthM = m_widthM;
    lane.speedLimit = m_speedLimit;
    const QString text = tr("Add lane %1").arg(QString::fromStdString(lane.name));
    addAndSelect(document(), &sim::Scene::lanes, std::move(lane), text);
}

QWidget* LaneTool::createOptionsWidget(QWidget* parent)
{
    auto* box = new QWidget(parent);
    auto* row = new QHBoxLayout(box);
    row->setContentsMargins(4, 0, 4, 0);
    auto add = [&](const QString& label, const QString& key, double lo, double hi, float& field, const QString& tip) {
        auto* spin = new QDoubleSpinBox(box);
        spin->setObjectName(key);
        spin->setRange(lo, hi);
        spin->setValue(double(field));
        spin->setToolTip(tip);
        connect(spin, &QDoubleSpinBox::valueChanged, this, [&field](double v) { field = float(v); });
        row->addWidget(new QLabel(label, box));
        row->addWidget(spin);
    };
    add(tr("Width"), "laneWidth", 0.5, 50.0, m_widthM, tr("Lane width in metres"));
    add(tr("Speed limit"), "laneSpeedLimit", 0.1, 100.0, m_speedLimit, tr("Speed limit in m/s (13.9 = 50 km/h)"));
    return box;
}

}  // namespace throng::editor
