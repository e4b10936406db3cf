#include "editor/tools/OrientBrushTool.h"

#include <glm/trigonometric.hpp>

#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QLabel>

#include <cmath>

namespace throng::editor {

bool OrientBrushTool::editAgent(sim::Agent& agent, glm::vec2, glm::vec2 direction, int) const
{
    if (direction == glm::vec2(0.0f))
        return false;
    // Headings turn counter-clockwise seen from above, with +z pointing south.
    const float target = glm::degrees(std::atan2(-direction.y, direction.x));
    const float turn = std::remainder(target - agent.headingDeg, 360.0f);
    const float heading = m_strength >= 1.0f ? target : agent.headingDeg + m_strength * turn;
    if (heading == agent.headingDeg)
        return false;
    agent.headingDeg = heading;
    return true;
}

QWidget* OrientBrushTool::createOptionsWidget(QWidget* parent)
{
    auto* box = new QWidget(parent);
    auto* row = new QHBoxLayout(box);
    row->setContentsMargins(4, 0, 4, 0);
    addRadiusOption(box, row, objectKey() + "Radius");
    auto* spin = new QDoubleSpinBox(box);
    spin->setObjectName("orientStrength");
    spin->setRange(0.05, 1.0);
    spin->setSingleStep(0.05);
    spin->setValue(double(m_strength));
    spin->setToolTip(tr("How far each dab turns an agent toward the stroke: 1 = all the way"));
    connect(spin, &QDoubleSpinBox::valueChanged, this, [this](double v) { m_strength = float(v); });
    row->addWidget(new QLabel(tr("Strength"), box));
    row->addWidget(spin);
    return box;
}

}  // namespace throng::editor
