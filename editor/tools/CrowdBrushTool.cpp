#include "editor/tools/CrowdBrushTool.h"

#include "editor/SceneDocument.h"
#include "editor/commands/PaintAgentsCommand.h"
#include "editor/tools/BrushOverlay.h"
#include "editor/viewport/Viewport.h"

#include <glm/geometric.hpp>

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>

namespace throng::editor {

namespace {
// A new dab every quarter radius keeps the density even along fast strokes.
constexpr float kDabSpacingRadii = 0.25f;
int g_nextStrokeId = 1;

std::vector<TypeShare> parseMix(const QString& text)
{
    std::vector<TypeShare> mix;
    for (const QString& part : text.split(',', Qt::SkipEmptyParts)) {
        const QStringList kv = part.split(':');
        TypeShare share{kv.value(0).trimmed().toStdString(), 1.0f};
        bool ok = false;
        const float w = kv.value(1).toFloat(&ok);
        if (kv.size() > 1 && ok)
            share.weight = w;
        if (!share.type.empty())
            mix.push_back(share);
    }
    return mix;
}
}  // namespace

QString CrowdBrushTool::toolTip() const
{
    return tr("Crowd Brush (B): drag on the ground to paint agents at the chosen density, "
              "never inside walls or obstacles");
}

void CrowdBrushTool::mousePressed(const ToolMouse& mouse)
{
    if (document().scene().agentTypes.empty()) {
        emit agentTypeNeeded();  // nothing to paint with: the main window offers a type
        return;
    }
    m_cursor = mouse.ground;
    if (!mouse.ground)
        return;
    setState(State::Dragging);
    m_strokeId = g_nextStrokeId++;
    m_dabIndex = 0;
    m_strokeAgents = 0;
    const glm::vec2 p(mouse.ground->x, mouse.ground->z);
    m_lastDab = p;
    dab(p, glm::vec2(0.0f));
    emit overlayChanged();
}

void CrowdBrushTool::mouseMoved(const ToolMouse& mouse)
{
    m_cursor = mouse.ground;
    if (state() == State::Dragging && mouse.ground) {
        const glm::vec2 p(mouse.ground->x, mouse.ground->z);
        const float step = std::max(0.05f, m_settings.radiusM * kDabSpacingRadii);
        // Dabs at even spacing along the segment, so a fast move leaves no gaps.
        while (glm::length(p - m_lastDab) >= step) {
            const glm::vec2 dir = glm::normalize(p - m_lastDab);
            m_lastDab += dir * step;
            dab(m_lastDab, dir);
        }
    } else if (state() != State::Dragging) {
        setState(mouse.ground ? State::Hover : State::Idle);
    }
    emit overlayChanged();
}

void CrowdBrushTool::mouseReleased(const ToolMouse& mouse)
{
    mouseMoved(mouse);
    setState(State::Hover);
    emit overlayChanged();
}

void CrowdBrushTool::cancel()
{
    setState(State::Idle);
    m_cursor.reset();
    emit overlayChanged();
}

void CrowdBrushTool::dab(glm::vec2 centre, glm::vec2 direction)
{
    const std::uint64_t seed = (std::uint64_t(m_strokeId) << 32) ^ std::uint64_t(m_dabIndex++);
    std::vector<sim::Agent> agents = placeDab(document().scene(), {}, centre, direction, m_settings, seed);
    if (agents.empty())
        return;
    std::uint32_t id = document().nextAgentId();
    for (sim::Agent& a : agents)
        a.id = id++;
    m_strokeAgents += agents.size();
    document().undoStack()->push(new PaintAgentsCommand(document(), std::move(agents), m_strokeId));
}

void CrowdBrushTool::drawOverlay(QPainter& painter) const
{
    if (m_cursor)
        drawBrushCircle(painter, viewport(), *m_cursor, m_settings.radiusM, QColor(80, 200, 255));
}

QWidget* CrowdBrushTool::createOptionsWidget(QWidget* parent)
{
    auto* box = new QWidget(parent);
    auto* row = new QHBoxLayout(box);
    row->setContentsMargins(4, 0, 4, 0);
    auto addSpin = [&](const QString& label, const QString& key, double lo, double hi, double step, float& field,
                       const QString& tip) {
        auto* spin = new QDoubleSpinBox(box);
        spin->setObjectName(key);
        spin->setRange(lo, hi);
        spin->setSingleStep(step);
        spin->setDecimals(2);
        spin->setValue(double(field));
        spin->setToolTip(tip);
        connect(spin, &QDoubleSpinBox::valueChanged, this, [&field](double v) { field = float(v); });
        row->addWidget(new QLabel(label, box));
        row->addWidget(spin);
    };
    addSpin(tr("Radius"), "brushRadius", 0.1, 100.0, 0.5, m_settings.radiusM, tr("Brush radius in metres"));
    addSpin(tr("Density"), "brushDensity", 0.01, 10.0, 0.05, m_settings.densityPerM2,
            tr("Agents per square metre inside the brush"));
    addSpin(tr("Spacing"), "brushSpacing", 0.0, 20.0, 0.1, m_settings.minSpacingM,
            tr("Least distance between agents in metres (Poisson-disc)"));
    auto* heading = new QComboBox(box);
    heading->setObjectName("brushHeading");
    heading->addItems({tr("Random"), tr("Along stroke"), tr("Toward point")});
    heading->setToolTip(tr("Which way new agents face"));
    connect(heading, &QComboBox::currentIndexChanged, this,
            [this](int i) { m_settings.heading = HeadingMode(i); });
    row->addWidget(new QLabel(tr("Heading"), box));
    row->addWidget(heading);
    auto* mix = new QLineEdit(box);
    mix->setObjectName("brushMix");
    mix->setPlaceholderText(tr("type:weight, ..."));
    mix->setToolTip(tr("Agent type mix, e.g. \"pedestrian:3, child:1\"; empty = the first pedestrian type"));
    connect(mix, &QLineEdit::textChanged, this, [this](const QString& t) { m_settings.mix = parseMix(t); });
    row->addWidget(new QLabel(tr("Mix"), box));
    row->addWidget(mix);
    return box;
}

}  // namespace throng::editor
