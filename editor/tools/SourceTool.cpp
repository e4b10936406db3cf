#include "editor/tools/SourceTool.h"

#include "editor/SceneDocument.h"
#include "editor/commands/AddSceneItemCommand.h"
#include "editor/tools/UniqueName.h"
#include "editor/viewport/Viewport.h"

#include <glm/geometric.hpp>

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPainter>

namespace throng::editor {

std::string SourceTool::sourceType() const
{
    const std::vector<sim::AgentType>& types = document().scene().agentTypes;
    for (const sim::AgentType& t : types)
        if (t.kind == sim::AgentKind::Pedestrian)
            return t.name;
    return types.empty() ? std::string() : types.front().name;
}

QString SourceTool::statusText() const
{
    if (document().scene().agentTypes.empty())
        return tr("Source: the scene has no agent type yet; click to create one");
    return toolTip();
}

void SourceTool::mousePressed(const ToolMouse& mouse)
{
    if (sourceType().empty()) {
        emit agentTypeNeeded();  // nothing to let in: the main window offers a type
        return;
    }
    if (!mouse.ground)
        return;
    m_from = m_to = {mouse.ground->x, mouse.ground->z};
    setState(State::Dragging);
    emit overlayChanged();
}

void SourceTool::mouseMoved(const ToolMouse& mouse)
{
    if (state() != State::Dragging || !mouse.ground)
        return;
    m_to = {mouse.ground->x, mouse.ground->z};
    emit overlayChanged();
}

void SourceTool::mouseReleased(const ToolMouse& mouse)
{
    if (state() != State::Dragging)
        return;
    if (mouse.ground)
        m_to = {mouse.ground->x, mouse.ground->z};
    setState(State::Idle);
    if (glm::length(m_to - m_from) < kClickM) {
        const glm::vec2 half(0.5f * kClickLineM, 0.0f);
        place(m_from - half, m_from + half);
    } else {
        place(m_from, m_to);
    }
    emit overlayChanged();
}

void SourceTool::place(glm::vec2 from, glm::vec2 to)
{
    const std::string type = sourceType();
    if (type.empty())
        return;
    sim::Source source;
    source.name = uniqueName(document().scene().sources, "source");
    source.types = {{type, 1.0f}};
    source.shape = sim::SourceShape::Line;
    source.from = from;
    source.to = to;
    source.rate = m_rate;
    source.arrivals = m_arrivals;
    const QString text = tr("Add source %1").arg(QString::fromStdString(source.name));
    addAndSelect(document(), &sim::Scene::sources, std::move(source), text);
}

void SourceTool::cancel()
{
    m_from = m_to = glm::vec2(0.0f);
    ViewportTool::cancel();
}

void SourceTool::drawOverlay(QPainter& painter) const
{
    if (state() != State::Dragging)
        return;
    const QPointF a = viewport().worldToPixel({m_from.x, 0.0f, m_from.y});
    const QPointF b = viewport().worldToPixel({m_to.x, 0.0f, m_to.y});
    const QColor colour(64, 209, 204);
    painter.setPen(QPen(colour, 2.0, Qt::DashLine));
    painter.drawLine(a, b);
    painter.setPen(QPen(colour, 2.0));
    painter.setBrush(Qt::NoBrush);
    painter.drawEllipse(a, 4.0, 4.0);
    painter.drawEllipse(b, 4.0, 4.0);
}

QWidget* SourceTool::createOptionsWidget(QWidget* parent)
{
    auto* box = new QWidget(parent);
    auto* row = new QHBoxLayout(box);
    row->setContentsMargins(4, 0, 4, 0);
    auto* rate = new QDoubleSpinBox(box);
    rate->setObjectName("sourceRate");
    rate->setRange(0.01, 1000.0);
    rate->setDecimals(2);
    rate->setValue(double(m_rate));
    rate->setSuffix(tr(" /s"));
    rate->setToolTip(tr("How many agents a new source lets in a second"));
    connect(rate, &QDoubleSpinBox::valueChanged, this, [this](double v) { m_rate = float(v); });
    auto* arrivals = new QComboBox(box);
    arrivals->setObjectName("sourceArrivals");
    arrivals->addItems({tr("Steady"), tr("Poisson")});
    arrivals->setCurrentIndex(int(m_arrivals));
    arrivals->setToolTip(tr("Steady: one every 1/rate seconds; Poisson: random gaps with that mean, as people come "
                            "to a door"));
    connect(arrivals, &QComboBox::currentIndexChanged, this, [this](int i) { m_arrivals = sim::Arrivals(i); });
    row->addWidget(new QLabel(tr("Rate"), box));
    row->addWidget(rate);
    row->addWidget(new QLabel(tr("Arrivals"), box));
    row->addWidget(arrivals);
    return box;
}

}  // namespace throng::editor
